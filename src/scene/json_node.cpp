#include "scene/json_node.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/input_error.h"
#include "common/read_file.h"

namespace relight {

namespace {

std::string escape_pointer_token(std::string_view key) {
  std::string out;
  for (char c : key) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

std::string child_pointer(const std::string& parent, std::string_view token) {
  return (parent == "/" ? std::string() : parent) + "/" + std::string(token);
}

}  // namespace

JsonNode::JsonNode(const nlohmann::json& value, std::string file, std::string pointer)
    : value_(&value), file_(std::move(file)), pointer_(std::move(pointer)) {}

std::string JsonNode::where() const {
  return file_ + ":" + pointer_;
}

void JsonNode::fail(const std::string& reason) const {
  fail_input(where(), reason);
}

bool JsonNode::has(std::string_view key) const {
  return value_->is_object() && value_->contains(key);
}

JsonNode JsonNode::at(std::string_view key) const {
  if (!value_->is_object()) fail("expected an object");
  const auto it = value_->find(key);
  if (it == value_->end()) fail("missing required key \"" + std::string(key) + "\"");
  return {*it, file_, child_pointer(pointer_, escape_pointer_token(key))};
}

std::optional<JsonNode> JsonNode::find(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return at(key);
}

std::vector<JsonNode> JsonNode::elements() const {
  if (!value_->is_array()) fail("expected an array");
  std::vector<JsonNode> out;
  out.reserve(value_->size());
  for (std::size_t i = 0; i < value_->size(); ++i) {
    out.emplace_back((*value_)[i], file_, child_pointer(pointer_, std::to_string(i)));
  }
  return out;
}

void JsonNode::expect_keys(std::initializer_list<std::string_view> allowed) const {
  if (!value_->is_object()) fail("expected an object");
  for (const auto& [key, unused] : value_->items()) {
    bool known = false;
    for (std::string_view a : allowed) known = known || a == key;
    if (!known) {
      std::string list;
      for (std::string_view a : allowed) {
        if (!list.empty()) list += ", ";
        list += a;
      }
      fail_input(file_ + ":" + child_pointer(pointer_, escape_pointer_token(key)),
                 "unknown key \"" + key + "\" (expected one of: " + list + ")");
    }
  }
}

double JsonNode::number() const {
  if (!value_->is_number()) fail("expected a number");
  const double v = value_->get<double>();
  if (!std::isfinite(v)) fail("expected a finite number");
  return v;
}

double JsonNode::number_at_least(double lo) const {
  const double v = number();
  if (v < lo) {
    std::ostringstream s;
    s << "must be at least " << lo << ", got " << v;
    fail(s.str());
  }
  return v;
}

double JsonNode::unit_interval() const {
  const double v = number();
  if (v < 0 || v > 1) {
    std::ostringstream s;
    s << "must be between 0 and 1, got " << v;
    fail(s.str());
  }
  return v;
}

double JsonNode::positive() const {
  const double v = number();
  if (!(v > 0)) {
    std::ostringstream s;
    s << "must be positive, got " << v;
    fail(s.str());
  }
  return v;
}

int JsonNode::integer_in(int lo, int hi) const {
  if (!value_->is_number_integer()) fail("expected an integer");
  const auto v = value_->get<long long>();
  if (v < lo || v > hi) {
    fail("must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
         std::to_string(v));
  }
  return static_cast<int>(v);
}

bool JsonNode::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false");
  return value_->get<bool>();
}

std::string JsonNode::string() const {
  if (!value_->is_string()) fail("expected a string");
  return value_->get<std::string>();
}

std::vector<double> JsonNode::numbers() const {
  std::vector<double> out;
  for (const JsonNode& e : elements()) out.push_back(e.number());
  return out;
}

Vec3 JsonNode::vec3() const {
  if (!value_->is_array() || value_->size() != 3) fail("expected an array of 3 numbers");
  const std::vector<double> v = numbers();
  return {v[0], v[1], v[2]};
}

Vec3 JsonNode::direction() const {
  const Vec3 v = vec3();
  if (length(v) < 1e-12) fail("direction must not be zero");
  return normalize(v);
}

Rgb JsonNode::rgb_non_negative() const {
  const Vec3 v = vec3();
  if (v.x < 0 || v.y < 0 || v.z < 0) fail("colour components must not be negative");
  return {v.x, v.y, v.z};
}

Rgb JsonNode::chromaticity() const {
  const Rgb color = rgb_non_negative();
  if (!(luminance(color) > 0)) fail("colour must have a positive luminance");
  return color / luminance(color);
}

Rgb JsonNode::rgb_in_unit_range() const {
  const Rgb c = rgb_non_negative();
  if (c.r > 1 || c.g > 1 || c.b > 1) fail("components must lie in 0..1");
  return c;
}

double JsonNode::number_or(std::string_view key, double fallback) const {
  const auto node = find(key);
  return node ? node->number() : fallback;
}

nlohmann::json parse_json_text(const std::string& text, const std::string& name) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    const std::size_t end = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    int line = 1;
    for (std::size_t i = 0; i < end; ++i) line += text[i] == '\n' ? 1 : 0;
    std::string reason = e.what();
    const auto colon = reason.find(": ", reason.find("parse error"));
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    fail_input(name + ":" + std::to_string(line), "malformed JSON: " + reason);
  } catch (const nlohmann::json::exception& e) {
    // Number overflow (e.g. 1e999) carries no position: find the literal it names.
    const std::string what = e.what();
    const auto open = what.find('\''), close = what.rfind('\'');
    std::string where = name;
    if (open != std::string::npos && close > open + 1) {
      const auto at = text.find(what.substr(open + 1, close - open - 1));
      if (at != std::string::npos) {
        where += ":" + std::to_string(1 + std::count(text.begin(), text.begin() + at, '\n'));
      }
    }
    fail_input(where, "malformed JSON: number out of range" +
                          (open != std::string::npos ? " " + what.substr(open) : std::string()));
  }
}

nlohmann::json read_json_file(const std::filesystem::path& file) {
  return parse_json_text(read_file(file), file.string());
}

}  // namespace relight

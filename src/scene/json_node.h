// A JSON value together with where it came from ("FILE:/json/pointer"), so that every validation
// failure in a scene or lighting-state file names the exact place. Unknown keys are errors:
// expect_keys() checks them.
#pragma once

#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

class JsonNode {
 public:
  JsonNode(const nlohmann::json& value, std::string file, std::string pointer);

  const nlohmann::json& value() const { return *value_; }
  const std::string& file() const { return file_; }
  const std::string& pointer() const { return pointer_; }
  // "FILE:/pointer" (the pointer of the root is "/").
  std::string where() const;
  [[noreturn]] void fail(const std::string& reason) const;

  bool is_object() const { return value_->is_object(); }
  bool is_array() const { return value_->is_array(); }
  bool has(std::string_view key) const;
  JsonNode at(std::string_view key) const;  // required member
  std::optional<JsonNode> find(std::string_view key) const;
  std::vector<JsonNode> elements() const;  // array elements (fails when not an array)
  // Fails naming the first member not in `allowed`.
  void expect_keys(std::initializer_list<std::string_view> allowed) const;

  double number() const;                    // finite number
  double number_at_least(double lo) const;  // finite, >= lo
  double positive() const;                  // finite, > 0
  double unit_interval() const;             // finite, 0..1
  int integer_in(int lo, int hi) const;
  bool boolean() const;
  std::string string() const;
  Vec3 vec3() const;              // [x, y, z], finite
  Vec3 direction() const;         // non-zero vec3, normalised
  Rgb rgb_in_unit_range() const;  // [r, g, b], each 0..1
  Rgb rgb_non_negative() const;   // [r, g, b], each >= 0
  // A light's colour: [r, g, b] ≥ 0 with positive luminance, scaled to luminance 1 (a chromaticity:
  // Y of linear Rec.709 is the photometric quantity).
  Rgb chromaticity() const;
  std::vector<double> numbers() const;  // array of finite numbers

  // Convenience: optional member with a default.
  double number_or(std::string_view key, double fallback) const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string pointer_;
};

// Parses a JSON file; a syntax error becomes "FILE:LINE: malformed JSON: ...".
nlohmann::json read_json_file(const std::filesystem::path& file);
nlohmann::json parse_json_text(const std::string& text, const std::string& name);

}  // namespace relight

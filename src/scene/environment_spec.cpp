// Parsing of the ENV objects of a scene or lighting state (see environment_spec.h for every
// convention). The CIE parameter table itself lives in light/sky_model.h; here only which types
// need a sun.
#include "scene/environment_spec.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "common/input_error.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

bool is_leap_year(int y) {
  return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

// Reads exactly `digits` decimal digits at text[pos] and advances pos.
std::optional<int> read_digits(std::string_view text, std::size_t& pos, int digits) {
  if (pos + digits > text.size()) return std::nullopt;
  int value = 0;
  for (int k = 0; k < digits; ++k) {
    const char c = text[pos + k];
    if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    value = value * 10 + (c - '0');
  }
  pos += digits;
  return value;
}

bool read_char(std::string_view text, std::size_t& pos, char expected) {
  if (pos >= text.size() || text[pos] != expected) return false;
  ++pos;
  return true;
}

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// A finite number in [lo, hi].
double number_in(const JsonNode& node, double lo, double hi) {
  const double v = node.number();
  if (v < lo || v > hi) {
    node.fail("must lie in " + format_number(lo) + ".." + format_number(hi) + ", got " +
              format_number(v));
  }
  return v;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

void parse_uniform(const JsonNode& node, EnvironmentSpec& spec) {
  node.expect_keys({"type", "luminance", "color"});
  spec.type = EnvironmentType::kUniform;
  spec.luminance = node.at("luminance").number_at_least(0);
  if (const auto c = node.find("color")) {
    spec.color = c->rgb_non_negative();
    if (!(luminance(spec.color) > 0)) c->fail("colour must have a positive luminance");
  }
}

void parse_map(const JsonNode& node, const fs::path& base_dir, bool require_file,
               EnvironmentSpec& spec) {
  node.expect_keys({"type", "file", "rotate_deg", "scale"});
  spec.type = EnvironmentType::kMap;
  const JsonNode f = node.at("file");
  const fs::path relative = f.string();
  if (relative.empty()) f.fail("file name is empty");
  const std::string ext = lower(relative.extension().string());
  if (ext != ".exr" && ext != ".hdr") {
    f.fail("expected an OpenEXR (.exr) or Radiance (.hdr) file, got \"" + relative.string() + "\"");
  }
  const fs::path path = relative.is_absolute() ? relative : base_dir / relative;
  if (require_file && !fs::is_regular_file(path)) f.fail("file not found: " + path.string());
  spec.file = path;
  if (const auto r = node.find("rotate_deg")) spec.rotate_deg = r->number();
  if (const auto s = node.find("scale")) spec.scale = s->number_at_least(0);
}

SunSpec parse_sun(const JsonNode& node, const Site* site) {
  if (!node.is_object()) node.fail("expected an object");
  node.expect_keys(
      {"latitude", "longitude", "utc_offset", "datetime", "azimuth_deg", "altitude_deg"});
  const bool place = node.has("latitude") || node.has("longitude") || node.has("utc_offset") ||
                     node.has("datetime");
  const bool angles = node.has("azimuth_deg") || node.has("altitude_deg");
  if (place == angles) {
    node.fail(
        "give either \"latitude\", \"longitude\", \"datetime\" (and \"utc_offset\"), "
        "\"datetime\" alone (at the site) or \"azimuth_deg\" and \"altitude_deg\"");
  }
  SunSpec sun;
  if (place) {
    sun.placement = SunPlacement::kPlaceAndTime;
    sun.place_from_site =
        !node.has("latitude") && !node.has("longitude") && !node.has("utc_offset");
    if (sun.place_from_site && site == nullptr) {
      node.fail(
          "a sun given by \"datetime\" alone stands at the project's site: give the scene a "
          "\"site\" (latitude, longitude, utc_offset) or the sun its \"latitude\" and "
          "\"longitude\"");
    }
    if (!sun.place_from_site) {
      sun.latitude_deg = number_in(node.at("latitude"), -90, 90);
      sun.longitude_deg = number_in(node.at("longitude"), -180, 180);
      if (const auto o = node.find("utc_offset")) sun.utc_offset_hours = number_in(*o, -14, 14);
    }
    const JsonNode d = node.at("datetime");
    const auto t = parse_civil_datetime(d.string());
    if (!t) {
      d.fail(
          "expected a local date and time \"YYYY-MM-DDTHH:MM[:SS]\" (years 1901..2099, no "
          "zone suffix: give \"utc_offset\"), got \"" +
          d.string() + "\"");
    }
    sun.local_time = *t;
  } else {
    sun.placement = SunPlacement::kAngles;
    sun.azimuth_deg = number_in(node.at("azimuth_deg"), -360, 360);
    sun.altitude_deg = number_in(node.at("altitude_deg"), -90, 90);
  }
  return sun;
}

void parse_cie_sky(const JsonNode& node, const Site* site, EnvironmentSpec& spec) {
  node.expect_keys({"type", "sky_type", "horizontal_illuminance", "zenith_luminance",
                    "linke_turbidity", "ground_albedo", "sun", "sun_illuminance"});
  spec.type = EnvironmentType::kCieSky;
  const JsonNode t = node.at("sky_type");
  if (t.value().is_string()) {
    if (t.string() != "overcast") {
      t.fail("expected an integer 1..15 or \"overcast\", got \"" + t.string() + "\"");
    }
    spec.sky_type = kTraditionalOvercastSky;
  } else if (t.value().is_number_integer()) {
    spec.sky_type = t.integer_in(1, 15);
  } else {
    t.fail("expected an integer 1..15 or \"overcast\"");
  }

  const bool horizontal = node.has("horizontal_illuminance");
  const bool zenith = node.has("zenith_luminance");
  if (horizontal && zenith) {
    node.fail(
        "give at most one of \"horizontal_illuminance\" (lx) or \"zenith_luminance\" "
        "(cd/m²); with neither the sky's brightness follows the sun's altitude");
  }
  if (horizontal) {
    spec.scaling = SkyScaling::kHorizontalIlluminance;
    spec.scaling_value = node.at("horizontal_illuminance").number_at_least(0);
  } else if (zenith) {
    spec.scaling = SkyScaling::kZenithLuminance;
    spec.scaling_value = node.at("zenith_luminance").number_at_least(0);
  } else {
    spec.scaling = SkyScaling::kSunAltitude;
    spec.sun_illuminance_from_model = !node.has("sun_illuminance");
    if (!node.has("sun")) {
      node.fail(
          "a sky without \"horizontal_illuminance\" or \"zenith_luminance\" takes its "
          "brightness from the sun's altitude: give \"sun\"");
    }
  }
  if (const auto l = node.find("linke_turbidity")) {
    if (spec.scaling != SkyScaling::kSunAltitude) {
      l->fail(
          "the Linke turbidity sets the brightness of a sky by the sun's altitude: leave out "
          "\"horizontal_illuminance\" and \"zenith_luminance\"");
    }
    spec.linke_turbidity = number_in(*l, 1, 10);
  }
  if (const auto g = node.find("ground_albedo")) spec.ground_albedo = number_in(*g, 0, 1);
  if (const auto s = node.find("sun")) spec.sun = parse_sun(*s, site);
  if (const auto e = node.find("sun_illuminance")) {
    spec.sun_illuminance = number_in(*e, 0, kMaxSunIlluminance);
    if (spec.sun_illuminance > 0 && spec.sun.placement == SunPlacement::kNone) {
      e->fail("a sun_illuminance needs a \"sun\" position");
    }
  }
  if (sky_type_needs_sun(spec.sky_type) && spec.sun.placement == SunPlacement::kNone) {
    t.fail("CIE sky type " + std::to_string(spec.sky_type) +
           " depends on the sun's position: give \"sun\"");
  }
}

void parse_perez(const JsonNode& node, const Site* site, EnvironmentSpec& spec) {
  node.expect_keys({"type", "direct_normal_irradiance", "diffuse_horizontal_irradiance",
                    "dew_point_c", "ground_albedo", "sun"});
  spec.type = EnvironmentType::kPerezSky;
  spec.direct_normal_irradiance = number_in(node.at("direct_normal_irradiance"), 0, kMaxIrradiance);
  spec.diffuse_horizontal_irradiance =
      number_in(node.at("diffuse_horizontal_irradiance"), 0, kMaxIrradiance);
  if (const auto d = node.find("dew_point_c")) spec.dew_point_c = number_in(*d, -90, 60);
  if (const auto g = node.find("ground_albedo")) spec.ground_albedo = number_in(*g, 0, 1);
  spec.sun = parse_sun(node.at("sun"), site);
}

}  // namespace

int days_in_month(int y, int m) {
  static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && is_leap_year(y) ? 29 : kDays[m - 1];
}

int day_of_year(const CivilDateTime& t) {
  int day = t.day;
  for (int m = 1; m < t.month; ++m) day += days_in_month(t.year, m);
  return day;
}

bool sky_type_needs_sun(int sky_type) {
  return sky_type == 2 || sky_type == 4 || (sky_type >= 6 && sky_type <= 15);
}

std::optional<CivilDateTime> parse_civil_datetime(std::string_view text) {
  std::size_t pos = 0;
  CivilDateTime t;
  const auto year = read_digits(text, pos, 4);
  if (!year || !read_char(text, pos, '-')) return std::nullopt;
  const auto month = read_digits(text, pos, 2);
  if (!month || !read_char(text, pos, '-')) return std::nullopt;
  const auto day = read_digits(text, pos, 2);
  if (!day) return std::nullopt;
  if (!read_char(text, pos, 'T') && !read_char(text, pos, ' ')) return std::nullopt;
  const auto hour = read_digits(text, pos, 2);
  if (!hour || !read_char(text, pos, ':')) return std::nullopt;
  const auto minute = read_digits(text, pos, 2);
  if (!minute) return std::nullopt;
  double second = 0;
  if (read_char(text, pos, ':')) {
    const auto whole = read_digits(text, pos, 2);
    if (!whole) return std::nullopt;
    second = *whole;
    if (read_char(text, pos, '.')) {
      double scale = 0.1;
      const std::size_t start = pos;
      while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) {
        second += (text[pos] - '0') * scale;
        scale *= 0.1;
        ++pos;
      }
      if (pos == start) return std::nullopt;
    }
  }
  if (pos != text.size()) return std::nullopt;
  if (*year < 1901 || *year > 2099 || *month < 1 || *month > 12) return std::nullopt;
  if (*day < 1 || *day > days_in_month(*year, *month)) return std::nullopt;
  if (*hour > 23 || *minute > 59 || !(second < 60)) return std::nullopt;
  t.year = *year;
  t.month = *month;
  t.day = *day;
  t.hour = *hour;
  t.minute = *minute;
  t.second = second;
  return t;
}

EnvironmentSpec parse_environment(const JsonNode& node, const fs::path& base_dir,
                                  bool require_files, const Site* site) {
  if (!node.is_object()) node.fail("expected an environment object");
  EnvironmentSpec spec;
  spec.where = node.where();
  const std::string type = node.at("type").string();
  if (type == "uniform") {
    parse_uniform(node, spec);
  } else if (type == "map") {
    parse_map(node, base_dir, require_files, spec);
  } else if (type == "cie_sky") {
    parse_cie_sky(node, site, spec);
  } else if (type == "perez") {
    parse_perez(node, site, spec);
  } else {
    node.at("type").fail("unknown environment type \"" + type +
                         "\" (expected uniform, map, cie_sky or perez)");
  }
  if (site != nullptr) apply_site(spec, *site);
  return spec;
}

Site parse_site(const JsonNode& node) {
  if (!node.is_object()) node.fail("expected an object");
  node.expect_keys({"latitude", "longitude", "utc_offset", "elevation_m", "north_deg"});
  Site site;
  site.latitude_deg = number_in(node.at("latitude"), -90, 90);
  site.longitude_deg = number_in(node.at("longitude"), -180, 180);
  if (const auto o = node.find("utc_offset")) site.utc_offset_hours = number_in(*o, -14, 14);
  if (const auto e = node.find("elevation_m")) site.elevation_m = number_in(*e, -500, 9000);
  if (const auto n = node.find("north_deg")) site.north_deg = number_in(*n, -360, 360);
  return site;
}

namespace {

nlohmann::json sun_json(const SunSpec& sun) {
  if (sun.placement == SunPlacement::kAngles) {
    return {{"azimuth_deg", sun.azimuth_deg}, {"altitude_deg", sun.altitude_deg}};
  }
  const CivilDateTime& t = sun.local_time;
  char text[40];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d", t.year, t.month, t.day, t.hour,
                t.minute);
  std::string datetime = text;
  if (t.second != 0) {
    std::snprintf(text, sizeof text, ":%06.3f", t.second);
    datetime += text;
  }
  nlohmann::json out = {{"datetime", datetime}};
  if (!sun.place_from_site) {
    out["latitude"] = sun.latitude_deg;
    out["longitude"] = sun.longitude_deg;
    out["utc_offset"] = sun.utc_offset_hours;
  }
  return out;
}

}  // namespace

nlohmann::json perez_sky_json(const EnvironmentSpec& sky) {
  if (sky.type != EnvironmentType::kPerezSky || sky.sun.placement == SunPlacement::kNone) {
    throw std::logic_error("perez_sky_json: not a Perez sky with a sun");
  }
  nlohmann::json out = {{"type", "perez"},
                        {"direct_normal_irradiance", sky.direct_normal_irradiance},
                        {"diffuse_horizontal_irradiance", sky.diffuse_horizontal_irradiance},
                        {"ground_albedo", sky.ground_albedo},
                        {"sun", sun_json(sky.sun)}};
  if (sky.dew_point_c) out["dew_point_c"] = *sky.dew_point_c;
  return out;
}

void apply_site(EnvironmentSpec& spec, const Site& site) {
  if (spec.sun.place_from_site) {
    spec.sun.latitude_deg = site.latitude_deg;
    spec.sun.longitude_deg = site.longitude_deg;
    spec.sun.utc_offset_hours = site.utc_offset_hours;
  }
  spec.elevation_m = site.elevation_m;
  spec.north_deg = site.north_deg;
}

}  // namespace relight

namespace relight {

Rgb parse_tint(const JsonNode& node) {
  const Rgb tint = node.rgb_non_negative();
  if (tint.r > 1 || tint.g > 1 || tint.b > 1) {
    node.fail("a window's tint is a transmittance: each channel must lie in 0..1");
  }
  return tint;
}

Glazing parse_glazing(const JsonNode& node) {
  if (!node.is_object()) node.fail("expected an object");
  node.expect_keys({"visible_transmittance", "panes", "diffusing"});
  const int panes = node.has("panes") ? node.at("panes").integer_in(1, kMaxPanes) : 1;
  const bool diffusing = node.has("diffusing") && node.at("diffusing").boolean();
  const JsonNode t = node.at("visible_transmittance");
  const double value = t.number();
  try {
    return make_glazing(value, panes, diffusing);
  } catch (const std::invalid_argument&) {  // more than the clear panes can transmit, or 0
    t.fail("uncoated glass of " + std::to_string(panes) + " pane" + (panes > 1 ? "s" : "") +
           " transmits more than 0 and at most " + format_number(max_glazing_transmittance(panes)) +
           " at normal incidence, got " + format_number(value));
  }
}

double parse_frost_deg(const JsonNode& node) {
  const double frost = node.number_at_least(0);
  if (frost > 90) node.fail("frost_deg must lie in 0..90");
  return frost;
}

}  // namespace relight

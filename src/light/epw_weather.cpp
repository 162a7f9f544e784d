// EnergyPlus weather files; the format and the choices are in epw_weather.h.
#include "light/epw_weather.h"

#include <string>

#include "common/input_error.h"
#include "common/read_file.h"
#include "light/number_text.h"
#include "scene/environment_spec.h"

namespace relight {

namespace {

constexpr int kHeaderLines = 8;
constexpr std::size_t kRecordFields = 35;
constexpr double kMissingRadiation = 9999;
constexpr double kMissingDewPoint = 99.9;
constexpr double kMissingAlbedo = 999;               // and above: the data dictionary's "missing"
constexpr std::uintmax_t kMaxFileBytes = 64u << 20;  // a year of hours is ~1.5 MB

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

// One line's fields with what messages need to name them.
struct Fields {
  const std::string& file;
  int line;
  std::vector<std::string_view> values;

  [[noreturn]] void fail(std::size_t field, const char* name, const std::string& reason) const {
    fail_input(at_line(file, line),
               "field " + std::to_string(field) + " (" + name + "): " + reason);
  }
  double number(std::size_t field, const char* name) const {
    const std::string_view token = trim(values[field - 1]);
    const auto v = parse_finite_number(token);
    if (!v) fail(field, name, "expected a number, got \"" + printable_token(token) + "\"");
    return *v;
  }
  int integer(std::size_t field, const char* name, int lo, int hi) const {
    const std::string_view token = trim(values[field - 1]);
    const auto v = parse_integer(token);
    if (!v) fail(field, name, "expected an integer, got \"" + printable_token(token) + "\"");
    if (*v < lo || *v > hi) {
      fail(field, name,
           std::to_string(*v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    }
    return static_cast<int>(*v);
  }
  double number_in(std::size_t field, const char* name, double lo, double hi) const {
    const double v = number(field, name);
    if (v < lo || v > hi) {
      fail(field, name,
           printable_token(trim(values[field - 1])) + " is outside " +
               printable_token(std::to_string(lo)) + ".." + printable_token(std::to_string(hi)));
    }
    return v;
  }
  double radiation(std::size_t field, const char* name) const {
    const double v = number(field, name);
    if (v == kMissingRadiation) fail(field, name, "missing (9999): the record cannot be lit");
    if (v < 0 || v > kMaxIrradiance) {
      fail(field, name, printable_token(trim(values[field - 1])) + " Wh/m² is outside 0..1500");
    }
    return v;
  }
};

WeatherLocation parse_location(const Fields& f) {
  if (f.values.size() < 10 || trim(f.values[0]) != "LOCATION") {
    fail_input(at_line(f.file, f.line),
               "expected the LOCATION line: LOCATION,city,state,country,source,WMO,latitude,"
               "longitude,time zone,elevation");
  }
  WeatherLocation loc;
  loc.city = std::string(trim(f.values[1]));
  loc.latitude_deg = f.number_in(7, "latitude", -90, 90);
  loc.longitude_deg = f.number_in(8, "longitude", -180, 180);
  loc.time_zone_hours = f.number_in(9, "time zone", -12, 14);
  loc.elevation_m = f.number(10, "elevation");
  return loc;
}

WeatherRecord parse_record(const Fields& f) {
  if (f.values.size() < kRecordFields) {
    fail_input(at_line(f.file, f.line), "truncated record: " + std::to_string(f.values.size()) +
                                            " of " + std::to_string(kRecordFields) + " fields");
  }
  WeatherRecord r;
  r.line = f.line;
  r.year = f.integer(1, "year", 1901, 2099);
  r.month = f.integer(2, "month", 1, 12);
  r.day = f.integer(3, "day", 1, days_in_month(r.year, r.month));
  r.hour = f.integer(4, "hour", 1, 24);
  const double dew = f.number(8, "dew point");
  if (dew != kMissingDewPoint) r.dew_point_c = f.number_in(8, "dew point", -90, 60);
  r.direct_normal_irradiance = f.radiation(15, "direct normal radiation");
  r.diffuse_horizontal_irradiance = f.radiation(16, "diffuse horizontal radiation");
  if (f.number(33, "albedo") < kMissingAlbedo) r.ground_albedo = f.number_in(33, "albedo", 0, 1);
  return r;
}

}  // namespace

WeatherFile parse_epw(std::string_view text, const std::string& name) {
  WeatherFile out;
  int line = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view content = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line;
    const Fields f{name, line, split_fields(content)};
    if (line == 1) {
      out.location = parse_location(f);
    } else if (line == kHeaderLines) {
      if (!content.starts_with("DATA PERIODS")) {
        fail_input(at_line(name, line), "expected the DATA PERIODS line (the eighth header line)");
      }
    } else if (line > kHeaderLines && !content.empty()) {
      out.records.push_back(parse_record(f));
    }
  }
  if (line < kHeaderLines) {
    fail_input(at_line(name, line == 0 ? 1 : line),
               "truncated file: an EPW file has 8 header lines, then its records");
  }
  if (out.records.empty()) fail_input(name, "no weather records after the header");
  return out;
}

WeatherFile read_epw(const std::filesystem::path& file) {
  return parse_epw(read_file(file, kMaxFileBytes), file.string());
}

}  // namespace relight

// EnergyPlus weather files (light/epw_weather.h): a synthetic year read back field by field,
// and clear errors — file, line, field — for truncated, non-numeric and out-of-range records.
#include <gtest/gtest.h>

#include <string>

#include "common/input_error.h"
#include "light/epw_weather.h"
#include "support/synthetic_epw.h"

namespace relight {
namespace {

TEST(EpwWeather, ASyntheticYearReadsBackFieldByField) {
  const WeatherFile w = parse_epw(testing::synthetic_epw(), "year.epw");
  EXPECT_EQ(w.location.city, "Testville");
  EXPECT_DOUBLE_EQ(w.location.latitude_deg, 48.14);
  EXPECT_DOUBLE_EQ(w.location.longitude_deg, 11.58);
  EXPECT_DOUBLE_EQ(w.location.time_zone_hours, 1);
  EXPECT_DOUBLE_EQ(w.location.elevation_m, 520);
  ASSERT_EQ(w.records.size(), 8760u);
  const WeatherRecord& noon = w.records[172 * 24 + 12];  // 22 June, the hour ending 13:00
  EXPECT_EQ(noon.month, 6);
  EXPECT_EQ(noon.day, 22);
  EXPECT_EQ(noon.hour, 13);
  EXPECT_EQ(noon.line, 9 + 172 * 24 + 12);
  // Day 173: 173 % 3 = 2, an intermediate day.
  EXPECT_GT(noon.direct_normal_irradiance, 300);
  EXPECT_GT(noon.diffuse_horizontal_irradiance, 200);
  ASSERT_TRUE(noon.dew_point_c.has_value());
  EXPECT_EQ(w.records.front().hour, 1);
  EXPECT_EQ(w.records.back().hour, 24);
  EXPECT_EQ(w.records.back().day, 31);
  EXPECT_DOUBLE_EQ(w.records.front().direct_normal_irradiance, 0);  // night
  EXPECT_EQ(noon.ground_albedo, 0.2);                               // field 33
}

// The synthetic file with line `line` (1-based) replaced by `replacement`.
std::string with_line(int line, const std::string& replacement) {
  const std::string text = testing::synthetic_epw();
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = text.find('\n', start) + 1;
  const std::size_t end = text.find('\n', start);
  return text.substr(0, start) + replacement + text.substr(end);
}

// Line `line` of the synthetic file with field `field` (1-based) set to `value`.
std::string with_field(int line, int field, const std::string& value) {
  const std::string text = testing::synthetic_epw();
  std::size_t start = 0;
  for (int i = 1; i < line; ++i) start = text.find('\n', start) + 1;
  std::string record = text.substr(start, text.find('\n', start) - start);
  std::size_t f = 0;
  for (int i = 1; i < field; ++i) f = record.find(',', f) + 1;
  const std::size_t e = record.find(',', f);
  record.replace(f, e == std::string::npos ? std::string::npos : e - f, value);
  return with_line(line, record);
}

std::string error_of(const std::string& text) {
  try {
    parse_epw(text, "w.epw");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(EpwWeather, BadRecordsNameTheirLineAndField) {
  struct Case {
    std::string text;
    const char* expected;
  };
  const Case cases[] = {
      {with_line(20, "2023,1,1,12,60,x,1,2,3"), "w.epw:20: truncated record: 9 of 35 fields"},
      {with_field(30, 15, "lots"),
       "w.epw:30: field 15 (direct normal radiation): expected a number, got \"lots\""},
      {with_field(31, 16, "9999"),
       "w.epw:31: field 16 (diffuse horizontal radiation): missing (9999)"},
      {with_field(32, 15, "-4"), "w.epw:32: field 15 (direct normal radiation): -4 Wh/m²"},
      {with_field(33, 2, "13"), "w.epw:33: field 2 (month): 13 is outside 1..12"},
      {with_field(34, 3, "30"), ""},  // 30 January is a day
      {with_field(9 + 31 * 24 + 5, 3, "29"), "field 3 (day): 29 is outside 1..28"},
      {with_field(35, 4, "0"), "w.epw:35: field 4 (hour): 0 is outside 1..24"},
      {with_field(36, 4, "7.5"), "w.epw:36: field 4 (hour): expected an integer"},
      {with_field(37, 8, "120"), "w.epw:37: field 8 (dew point): 120 is outside"},
      {with_field(38, 8, "99.9"), ""},  // missing dew point: allowed
      {with_field(39, 33, "1.4"), "w.epw:39: field 33 (albedo): 1.4 is outside 0"},
      {with_field(40, 33, "snow"), "w.epw:40: field 33 (albedo): expected a number"},
      {with_field(1, 7, "north"), "w.epw:1: field 7 (latitude): expected a number"},
      {with_field(1, 9, "20"), "w.epw:1: field 9 (time zone): 20 is outside"},
      {with_line(1, "CITY,x"), "w.epw:1: expected the LOCATION line"},
      {with_line(8, "COMMENTS 3"), "w.epw:8: expected the DATA PERIODS line"},
      {"LOCATION,a,b,c,d,e,1,2,3,4\nDESIGN CONDITIONS,0\n", "w.epw:2: truncated file"},
      {testing::synthetic_epw().substr(0, testing::synthetic_epw().find("DATA PERIODS") + 40),
       "w.epw: no weather records"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    if (std::string(c.expected).empty()) {
      EXPECT_EQ(message, "");
    } else {
      EXPECT_NE(message.find(c.expected), std::string::npos)
          << "expected \"" << c.expected << "\" in \"" << message << "\"";
    }
  }
  // The last record cut short by a truncated download.
  const std::string text = testing::synthetic_epw();
  EXPECT_NE(error_of(text.substr(0, text.size() - 60)).find("w.epw:8768: truncated record"),
            std::string::npos);
}

TEST(EpwWeather, TheGroundAlbedoIsReadAndMayBeMissing) {
  EXPECT_EQ(parse_epw(with_field(9, 33, "0.35"), "w.epw").records[0].ground_albedo, 0.35);
  EXPECT_FALSE(parse_epw(with_field(9, 33, "999"), "w.epw").records[0].ground_albedo);
  EXPECT_FALSE(parse_epw(with_field(9, 33, "999.000"), "w.epw").records[0].ground_albedo);
}

}  // namespace
}  // namespace relight

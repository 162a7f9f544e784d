// What a scene or a run-time lighting state says about the exterior seen through a portal: the ENV
// objects, as plain data parsed from JSON. light/environment.h turns a spec into an evaluable
// Environment (it computes the sun position and reads no files); light/environment_map_io.h reads
// the map files.
//
//   { "type": "uniform", "luminance": cd/m², "color": [r, g, b] }
//   { "type": "map", "file": "x.exr" | "x.hdr", "rotate_deg": deg, "scale": factor }
//   { "type": "cie_sky", "sky_type": 1..15 | "overcast",
//     "horizontal_illuminance": lx | "zenith_luminance": cd/m² | neither (by the sun's altitude),
//     "linke_turbidity": T_L, "ground_albedo": 0..1,
//     "sun": { "latitude", "longitude", "utc_offset", "datetime" } | { "datetime" } (the site's)
//          | { "azimuth_deg", "altitude_deg" },
//     "sun_illuminance": lx }
//   { "type": "perez", "direct_normal_irradiance": W/m², "diffuse_horizontal_irradiance": W/m²,
//     "dew_point_c": °C, "ground_albedo": 0..1, "sun": { as cie_sky } }
//
// Conventions (world frame: metres, right-handed, y up; NORTH IS −z, EAST IS +x):
//  * uniform: the same luminance in every direction of the sphere. "color" is a tint that is
//    normalised to unit luminance (Y = 0.2126 r + 0.7152 g + 0.0722 b of linear Rec.709), so
//    the photometric luminance is always "luminance"; default [1, 1, 1].
//  * map: an equirectangular image in the math/equirect.h orientation (image centre column =
//    south +z, left edge = north −z, a quarter of the width = east +x; top row = zenith).
//    Texel values are taken as cd/m² per channel and multiplied by "scale" (default 1, >= 0).
//    A Radiance .hdr stores W·sr⁻¹·m⁻²: scale 179 lm/W turns it into cd/m².
//    "rotate_deg" (default 0) turns the map about +y CLOCKWISE SEEN FROM ABOVE, the sense of
//    the compass azimuth: what the file shows at azimuth A appears at azimuth A + rotate_deg
//    (rotate_deg = 90 moves the file's north to the east). "file" is resolved against the
//    folder of the JSON file and must exist, with extension .exr or .hdr.
//  * cie_sky: the CIE standard general sky (ISO 15469:2004 / CIE S 011/E:2003), types 1..15,
//    or the traditional CIE overcast sky (Moon & Spencer 1942; CIE 1955), "overcast", stored
//    as sky_type 0. At most one of
//      "horizontal_illuminance": the diffuse horizontal illuminance of the sky dome alone
//                                (without the sun disc), lx, >= 0;
//      "zenith_luminance":       the luminance of the zenith, cd/m², >= 0;
//    with neither, the sky's brightness (and the sun disc's, unless "sun_illuminance" is given)
//    follows the sun's altitude by light/daylight_availability.h, with the site's elevation and
//    "linke_turbidity" (default 3, 1..10): a "sun" is then required.
//    "ground_albedo" (default 0.2, 0..1): the ground below the horizon is a uniform Lambertian
//    luminance ground_albedo·(E_h,sky + E_h,sun)/π.
//    "sun": where the sun is. Required by the types whose luminance depends on it (2, 4, 6..15)
//    and whenever sun_illuminance > 0; optional otherwise. Either
//      { "latitude": deg north (−90..90), "longitude": deg east (−180..180),
//        "utc_offset": hours added to UTC to get the local time (−14..14, default 0),
//        "datetime": "YYYY-MM-DDTHH:MM" or "YYYY-MM-DDTHH:MM:SS[.fff]" local civil time,
//                    years 1901..2099, no zone suffix (use utc_offset) }
//      — the position follows from the PSA algorithm (light/sun_position.h) —, or
//      { "datetime" } alone, whose place (latitude, longitude, utc_offset) is the site's, or
//      { "azimuth_deg": from north clockwise toward east (−360..360),
//        "altitude_deg": above the horizon (−90..90) }.
//    "sun_illuminance" (0..140000 lx): the illuminance on a plane normal to the sun from the
//    0.53° sun disc (direct normal illuminance; the extraterrestrial value is about 133 800 lx).
//    Default: the daylight model's when the brightness follows the sun, else 0 (no sun disc). A
//    sun below the horizon contributes nothing.
//  * perez: the Perez all-weather sky (Perez, Seals & Michalsky 1993) of one weather record,
//    as light/perez_sky.h computes it: "direct_normal_irradiance" and
//    "diffuse_horizontal_irradiance" (W/m², 0..1500, both required) give the sky's clearness
//    and brightness; the Perez et al. 1990 luminous efficacies turn them into the sun disc's
//    normal illuminance and the dome's diffuse horizontal illuminance. "dew_point_c" (°C,
//    −90..60, optional) sets the atmosphere's precipitable water (2 cm without it).
//    "ground_albedo" as cie_sky. "sun" is required; with a date (place and time) the
//    extraterrestrial irradiance follows the earth's orbit, with angles its mean (1367 W/m²).
//
// The site ("site" of a scene or lighting state, parse_site): latitude, longitude, utc_offset as
// a sun's, "elevation_m" (−500..9000, default 0) and "north_deg" (−360..360, default 0), the
// angle from the scene's −z clockwise (seen from above) to true north. Every azimuth of an
// environment is a compass azimuth from true north: a sun's (by place and time or by angles)
// and a map's north, so north_deg turns them all about +y.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "math/glazing.h"
#include "math/rgb.h"
#include "scene/json_node.h"

namespace relight {

enum class EnvironmentType { kUniform, kMap, kCieSky, kPerezSky };

// sky_type value of the traditional CIE overcast sky ("overcast").
inline constexpr int kTraditionalOvercastSky = 0;
// Upper bound accepted for sun_illuminance (lx).
inline constexpr double kMaxSunIlluminance = 140000.0;
// Upper bound accepted for a Perez sky's irradiances (W/m²; the solar constant is 1361–1367).
inline constexpr double kMaxIrradiance = 1500.0;

// kSunAltitude: neither given; light/daylight_availability.h sets the brightness.
enum class SkyScaling { kHorizontalIlluminance, kZenithLuminance, kSunAltitude };

// T_L of a cie_sky whose brightness follows the sun and gives no "linke_turbidity": a typical
// rural mid-latitude atmosphere.
inline constexpr double kDefaultLinkeTurbidity = 3.0;

// A local civil date and time as written in "datetime".
struct CivilDateTime {
  int year = 2000, month = 1, day = 1;
  int hour = 0, minute = 0;
  double second = 0;
  bool operator==(const CivilDateTime&) const = default;
};

enum class SunPlacement {
  kNone,          // no "sun"
  kPlaceAndTime,  // latitude, longitude, utc_offset, datetime
  kAngles,        // azimuth_deg, altitude_deg
};

struct SunSpec {
  SunPlacement placement = SunPlacement::kNone;
  bool place_from_site = false;  // kPlaceAndTime by "datetime" alone: the site's place
  double latitude_deg = 0;       // north positive
  double longitude_deg = 0;      // east positive
  double utc_offset_hours = 0;   // local time = UTC + utc_offset_hours
  CivilDateTime local_time;
  double azimuth_deg = 0;   // from north (−z) clockwise toward east (+x)
  double altitude_deg = 0;  // above the horizon
  bool operator==(const SunSpec&) const = default;
};

struct EnvironmentSpec {
  EnvironmentType type = EnvironmentType::kUniform;
  // uniform
  double luminance = 0;  // cd/m²
  Rgb color{1, 1, 1};    // tint; the radiance is luminance · color / Y(color)
  // map
  std::filesystem::path file;  // resolved, exists
  double rotate_deg = 0;
  double scale = 1;
  // cie_sky
  int sky_type = kTraditionalOvercastSky;  // 0 = traditional overcast, 1..15 = ISO 15469 types
  SkyScaling scaling = SkyScaling::kHorizontalIlluminance;
  double scaling_value = 0;  // lx or cd/m², as `scaling` says
  double ground_albedo = 0.2;
  SunSpec sun;
  double sun_illuminance = 0;               // lx on a plane normal to the sun; 0 = no sun disc
  bool sun_illuminance_from_model = false;  // kSunAltitude without "sun_illuminance"
  double linke_turbidity = kDefaultLinkeTurbidity;
  // from the site: the ground's elevation (m) for the daylight model, and true north (the
  // clockwise angle from −z), which turns every sun and map
  double elevation_m = 0;
  double north_deg = 0;
  // perez (with sun and ground_albedo above)
  double direct_normal_irradiance = 0;       // W/m²
  double diffuse_horizontal_irradiance = 0;  // W/m²
  std::optional<double> dew_point_c;         // °C
  std::string where;                         // "FILE:JSON-PATH" of the object, for messages
  bool operator==(const EnvironmentSpec&) const = default;
};

// The project's site (see above).
struct Site {
  double latitude_deg = 0;      // north positive
  double longitude_deg = 0;     // east positive
  double utc_offset_hours = 0;  // local time = UTC + utc_offset_hours
  double elevation_m = 0;
  double north_deg = 0;  // clockwise from the scene's −z to true north
  bool operator==(const Site&) const = default;
};

// Parses a "site" object. Throws InputError "FILE:/json/pointer: reason".
Site parse_site(const JsonNode& node);
// Puts a spec at the site: a sun by "datetime" alone takes the site's place; the spec takes the
// site's elevation and north.
void apply_site(EnvironmentSpec& spec, const Site& site);

// The JSON object of a Perez sky spec, in the form parse_environment reads back into the same
// sky (its site-given elevation and north come from the document it is put in): how the studio
// receives each hour of a day from weather data as a lighting state's environment. Pinned by
// EnvironmentSpec.PerezSkyJsonReadsBackAsTheSameSky.
nlohmann::json perez_sky_json(const EnvironmentSpec& sky);

// True for the CIE standard sky types whose luminance distribution depends on the sun's
// position (an indicatrix with c != 0 or e != 0): 2, 4, 6..15.
bool sky_type_needs_sun(int sky_type);

// The days of a month (1..12) of the Gregorian calendar, and the day of the year of a civil
// date, 1..366.
int days_in_month(int year, int month);
int day_of_year(const CivilDateTime& t);

// Parses "YYYY-MM-DDTHH:MM[:SS[.fff]]" (a 'T' or one space between date and time); checks the
// calendar (leap years) and the clock (hour 0..23, minute 0..59, second < 60). Years
// 1901..2099. Returns nullopt when the text is not such a date and time.
std::optional<CivilDateTime> parse_civil_datetime(std::string_view text);

// Parses an ENV object; relative map paths resolve against base_dir. Throws InputError
// "FILE:/json/pointer: reason" for unknown keys, missing or out-of-range values.
// With require_files false a map's file need not exist yet (a .rlt keeps only the path; the
// file is read when the environment is first used). With a site the spec is put there
// (apply_site); without one a sun by "datetime" alone is refused.
EnvironmentSpec parse_environment(const JsonNode& node, const std::filesystem::path& base_dir,
                                  bool require_files = true, const Site* site = nullptr);

// Window glass, in a scene's portal or a lighting state's: "tint" [r, g, b], a transmittance
// per channel in 0..1; "frost_deg" in 0..90, the angular width of frosted glass's blur.
Rgb parse_tint(const JsonNode& node);
double parse_frost_deg(const JsonNode& node);
// A portal material's or state's "glazing": { "visible_transmittance": T (required),
// "panes": 1|2|3 (default 1), "diffusing": bool (default false) } (math/glazing.h); a
// transmittance uncoated panes cannot have is refused with their maximum.
Glazing parse_glazing(const JsonNode& node);

}  // namespace relight

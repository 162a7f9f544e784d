// A year of daylight through the precomputed transfer (`relight annual`): every occupied hour of an
// EnergyPlus weather file (light/epw_weather.h) with the sun up becomes a Perez all-weather sky
// (light/perez_sky.h) in every portal, and the scene is relit with it — the same state `relight
// probe --state` would apply for that hour, so the two agree.
//
// Time: a record's hour h (1..24) is the hour ending at h, local standard time; it is
// evaluated at h − 30 min of the record's own year and date, at the weather file's latitude,
// longitude and time zone (the sun by the PSA algorithm, light/sun_position.h). An hour is
// occupied when that time lies in the occupied period [start, end) (default 08:00–18:00: ten
// hours a day), and lit when the sun's centre is then above the horizon. Lighting: the state
// document, if any, on the scene's own state; luminaires and near-field emitters the document
// does not name are off (daylight alone unless the state says otherwise); each portal's
// environment is the hour's sky (its tint, frost and exterior objects stay as the state has
// them).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "light/epw_weather.h"
#include "runtime/daylight_metrics.h"
#include "runtime/lighting_state.h"
#include "runtime/relit_scene.h"
#include "scene/environment_spec.h"

namespace relight {

// [start, end) in minutes of local standard time, 0 <= start < end <= 24·60.
struct OccupiedPeriod {
  int start_minutes = 8 * 60, end_minutes = 18 * 60;
};

// "HH:MM-HH:MM" (end up to 24:00, after start); nullopt otherwise.
std::optional<OccupiedPeriod> parse_occupied_period(std::string_view text);

// The Perez sky of a record at its evaluation time (h − 30 min) at the weather file's place,
// the ground reflecting the record's albedo (0.2 when it gives none), its sun turned by the
// scene's true north (`north_deg`, the site's); messages name the record's line.
EnvironmentSpec record_sky(const WeatherLocation& location, const WeatherRecord& record,
                           double north_deg);

struct AnnualHour {
  WeatherRecord record;
  EnvironmentSpec sky;
};

// The occupied records with the sun up, in file order, and how many were occupied.
struct AnnualHours {
  std::vector<AnnualHour> hours;
  std::size_t occupied = 0;
};
AnnualHours annual_hours(const WeatherFile& weather, const OccupiedPeriod& period,
                         double north_deg);

// `rlt` opened for a year of hours: every sun's bounce solved from nothing
// (RelighterSettings::warm_sun_bounce), so that each hour equals `relight probe` with its sky.
std::unique_ptr<RelitScene> open_for_annual(const std::filesystem::path& rlt);

// The state the year starts from (see above); `document` is the state file's, if any.
LightingState annual_base_state(const Scene& scene,
                                const std::optional<std::filesystem::path>& file);

// What the sweep measured: per hour (rows) and chosen sensor (columns), the illuminance
// (lx) and the direct sunlight alone (lx, the exact sun through the windows with no
// interreflection: what ASE counts); and the time spent.
struct AnnualValues {
  std::size_t sensors = 0;
  std::vector<float> lux;             // hours × sensors
  std::vector<float> direct_sun_lux;  // hours × sensors
  std::size_t streams = 1;            // hours relit at once (kAnnualStreams)
  double total_seconds = 0;           // wall time
  // Summed over the streams (thread time): every hour, and its rebuilding of the portals'
  // shells.
  double hour_seconds = 0, shell_seconds = 0;
};

// At most this many streams of hours are relit at once (as many as TBB may run threads, up
// to this), each by its own relighter: a further copy of the runtime scene and the gather
// operator per stream.
inline constexpr std::size_t kAnnualStreams = 2;

// Relights `relit` (and its twins, RelitScene::twin) for every hour from `base`; `sensors` are
// indices into the scene's sensor points (scene order, sets back to back). `on_hour` is called
// after each hour, from any of the streams' threads, one call at a time.
AnnualValues annual_sensor_values(RelitScene& relit, const LightingState& base,
                                  std::span<const AnnualHour> hours,
                                  std::span<const std::size_t> sensors,
                                  const std::function<void()>& on_hour = {});

// `state` with every luminaire and emitter off: daylight alone (the studio's annual panel).
LightingState daylight_alone(LightingState state);

// Every sensor set of the scene, by index (what the report and the studio's panel compute).
std::vector<std::size_t> every_sensor_set(const Scene& scene);

// A year of the chosen sensor sets (indices into scene.sensors): every hour's values (sets back
// to back, in the order given) and the climate-based metrics per sensor and per set — what
// `relight annual`, `relight report --weather` and the studio's annual panel show.
struct AnnualDaylight {
  AnnualValues values;
  std::vector<SensorDaylight> per_sensor;
  std::vector<SetDaylight> per_set;
};
AnnualDaylight annual_daylight(RelitScene& relit, const LightingState& base,
                               std::span<const AnnualHour> hours, std::span<const std::size_t> sets,
                               const std::function<void()>& on_hour = {});

}  // namespace relight

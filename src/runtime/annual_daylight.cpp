// A year of daylight through the precomputed transfer; see annual_daylight.h.
#include "runtime/annual_daylight.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>

#include "engine/light_term.h"
#include "light/environment.h"
#include "math/rgb.h"
#include "scene/json_node.h"

namespace relight {

namespace {

std::optional<int> parse_clock(std::string_view text) {
  if (text.size() != 5 || text[2] != ':') return std::nullopt;
  for (const int i : {0, 1, 3, 4}) {
    if (text[i] < '0' || text[i] > '9') return std::nullopt;
  }
  const int h = (text[0] - '0') * 10 + (text[1] - '0');
  const int m = (text[3] - '0') * 10 + (text[4] - '0');
  if (m > 59 || h > 24 || (h == 24 && m != 0)) return std::nullopt;
  return h * 60 + m;
}

// The record's evaluation time, h − 30 min local standard time.
CivilDateTime evaluation_time(const WeatherRecord& r) {
  return {r.year, r.month, r.day, r.hour - 1, 30, 0};
}

bool occupied(const OccupiedPeriod& period, const WeatherRecord& r) {
  const int minutes = (r.hour - 1) * 60 + 30;
  return minutes >= period.start_minutes && minutes < period.end_minutes;
}

}  // namespace

std::optional<OccupiedPeriod> parse_occupied_period(std::string_view text) {
  const std::size_t dash = text.find('-');
  if (dash == std::string_view::npos) return std::nullopt;
  const auto start = parse_clock(text.substr(0, dash));
  const auto end = parse_clock(text.substr(dash + 1));
  if (!start || !end || *start >= *end) return std::nullopt;
  return OccupiedPeriod{*start, *end};
}

EnvironmentSpec record_sky(const WeatherLocation& location, const WeatherRecord& record,
                           double north_deg) {
  EnvironmentSpec sky;
  sky.type = EnvironmentType::kPerezSky;
  sky.direct_normal_irradiance = record.direct_normal_irradiance;
  sky.diffuse_horizontal_irradiance = record.diffuse_horizontal_irradiance;
  sky.dew_point_c = record.dew_point_c;
  sky.ground_albedo = record.ground_albedo.value_or(0.2);
  sky.sun.placement = SunPlacement::kPlaceAndTime;
  sky.sun.latitude_deg = location.latitude_deg;
  sky.sun.longitude_deg = location.longitude_deg;
  sky.sun.utc_offset_hours = location.time_zone_hours;
  sky.sun.local_time = evaluation_time(record);
  sky.north_deg = north_deg;
  sky.where = "weather record at line " + std::to_string(record.line);
  return sky;
}

AnnualHours annual_hours(const WeatherFile& weather, const OccupiedPeriod& period,
                         double north_deg) {
  AnnualHours out;
  for (const WeatherRecord& r : weather.records) {
    if (!occupied(period, r)) continue;
    ++out.occupied;
    EnvironmentSpec sky = record_sky(weather.location, r, north_deg);
    if (sun_direction(sky.sun).y <= 0) continue;
    out.hours.push_back({r, std::move(sky)});
  }
  return out;
}

std::unique_ptr<RelitScene> open_for_annual(const std::filesystem::path& rlt) {
  RelighterSettings settings;
  settings.warm_sun_bounce = false;
  settings.sensors_only = true;
  return std::make_unique<RelitScene>(rlt, std::nullopt, settings);
}

LightingState annual_base_state(const Scene& scene,
                                const std::optional<std::filesystem::path>& file) {
  LightingState state = default_lighting_state(scene);
  nlohmann::json document = nlohmann::json::object();
  if (file) {
    document = read_json_file(*file);
    apply_lighting_state(state, scene, document, file->string(),
                         file->has_parent_path() ? file->parent_path() : ".");
  }
  const auto named = [&](const char* kind, const std::string& name) {
    const auto k = document.is_object() ? document.find(kind) : document.end();
    return k != document.end() && k->is_object() && k->contains(name);
  };
  for (std::size_t j = 0; j < scene.luminaires.size(); ++j) {
    if (!named("luminaires", scene.luminaires[j].name)) state.luminaires[j].on = false;
  }
  for (std::size_t e = 0; e < scene.emitters.size(); ++e) {
    if (!named("emitters", scene.emitters[e].name)) state.emitters[e].on = false;
  }
  return state;
}

LightingState daylight_alone(LightingState state) {
  for (LuminaireState& l : state.luminaires) l.on = false;
  for (EmitterState& e : state.emitters) e.on = false;
  return state;
}

namespace {

// A stream's thread time: all its hours, and their shells.
struct StreamSeconds {
  double hours = 0, shells = 0;
};

// Relights `relit` for hours [first, last) from `state` and writes their sensor values into
// the rows first..last of `out` (lux and direct_sun_lux already sized).
StreamSeconds sweep_hours(RelitScene& relit, LightingState state, std::span<const AnnualHour> hours,
                          std::size_t first, std::size_t last, std::span<const std::size_t> sensors,
                          std::span<const Vec3> points, std::span<const Vec3> normals,
                          AnnualValues& out, const std::function<void()>& on_hour) {
  const auto start = std::chrono::steady_clock::now();
  double shell_seconds = 0;
  for (std::size_t h = first; h < last; ++h) {
    for (PortalState& p : state.portals) p.environment = hours[h].sky;
    relit.apply(state);
    const Relighter& relighter = relit.relighter();
    for (std::size_t p = 0; p < state.portals.size(); ++p) {
      shell_seconds += relighter.shell_seconds(p);
    }
    const std::vector<Rgb> e = relit.sensor_irradiance();
    // ASE's direct sunlight: the suns traced past the room and the movable objects as placed —
    // as the relight traced them at the sensors when there are no objects, else again here,
    // through the portals' exact direct light (engine/light_term.h).
    const ObjectLighting* objects = relighter.objects();
    const std::vector<Rgb> traced =
        objects == nullptr ? relit.sensor_sun_irradiance() : std::vector<Rgb>{};
    std::unique_ptr<const DirectLights> suns;
    if (objects != nullptr) {
      suns = relighter.portals().direct_lights(objects->occluders(), kOpeningSamples);
    }
    float* const lux = out.lux.data() + h * sensors.size();
    float* const sun_lux = out.direct_sun_lux.data() + h * sensors.size();
    for (std::size_t c = 0; c < sensors.size(); ++c) {
      lux[c] = static_cast<float>(luminance(e[sensors[c]]));
      Rgb sun;
      if (!traced.empty()) {
        sun = traced[sensors[c]];
      } else if (suns) {
        sun = suns->irradiance_at(points[c], normals[c]);
      }
      sun_lux[c] = static_cast<float>(luminance(sun));
    }
    on_hour();
  }
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
          shell_seconds};
}

}  // namespace

AnnualValues annual_sensor_values(RelitScene& relit, const LightingState& base,
                                  std::span<const AnnualHour> hours,
                                  std::span<const std::size_t> sensors,
                                  const std::function<void()>& on_hour) {
  const auto start = std::chrono::steady_clock::now();
  const Scene& scene = relit.scene();
  // Every sensor point's position and normal, scene order; the chosen ones are read by index.
  std::vector<Vec3> all_points, all_normals;
  for (const SensorSet& set : scene.sensors) {
    all_points.insert(all_points.end(), set.points.begin(), set.points.end());
    all_normals.insert(all_normals.end(), set.points.size(), set.normal);
  }
  std::vector<Vec3> points, normals;
  for (const std::size_t k : sensors) {
    points.push_back(all_points.at(k));
    normals.push_back(all_normals.at(k));
  }
  AnnualValues out;
  out.sensors = sensors.size();
  out.lux.assign(hours.size() * sensors.size(), 0.0f);
  out.direct_sun_lux.assign(hours.size() * sensors.size(), 0.0f);
  // Streams of consecutive hours, each relit by its own twin of `relit` (a relighter is not
  // thread-safe): within an hour the shell's sky, the sums and the sun use every core, but
  // parts of it run on one (the sky's normalisation, the SH and Haar transforms of the shell,
  // the gaps between parallel loops); a second stream fills those. Every hour is relit from
  // `base` alone (open_for_annual: no warm start), so the values do not depend on the split.
  const std::size_t streams =
      std::min({kAnnualStreams,
                tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism),
                std::max<std::size_t>(hours.size(), 1)});
  std::vector<std::unique_ptr<RelitScene>> twins;
  for (std::size_t k = 1; k < streams; ++k) twins.push_back(relit.twin());
  std::mutex progress;
  const auto hour_done = [&] {
    if (!on_hour) return;
    const std::scoped_lock lock(progress);
    on_hour();
  };
  std::vector<StreamSeconds> seconds(streams);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, streams, 1),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
          // Isolated: a thread waiting inside one stream's parallel loops must not take up
          // the other stream (it would then finish that whole stream first).
          tbb::this_task_arena::isolate([&] {
            seconds[k] = sweep_hours(k == 0 ? relit : *twins[k - 1], base, hours,
                                     hours.size() * k / streams, hours.size() * (k + 1) / streams,
                                     sensors, points, normals, out, hour_done);
          });
        }
      },
      tbb::simple_partitioner{});
  out.streams = streams;
  for (const StreamSeconds& s : seconds) {
    out.hour_seconds += s.hours;
    out.shell_seconds += s.shells;
  }
  out.total_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<std::size_t> every_sensor_set(const Scene& scene) {
  std::vector<std::size_t> sets(scene.sensors.size());
  std::iota(sets.begin(), sets.end(), std::size_t{0});
  return sets;
}

AnnualDaylight annual_daylight(RelitScene& relit, const LightingState& base,
                               std::span<const AnnualHour> hours, std::span<const std::size_t> sets,
                               const std::function<void()>& on_hour) {
  const Scene& scene = relit.scene();
  std::vector<std::size_t> first(scene.sensors.size() + 1, 0);  // each set's first point
  for (std::size_t k = 0; k < scene.sensors.size(); ++k) {
    first[k + 1] = first[k] + scene.sensors[k].points.size();
  }
  std::vector<std::size_t> columns, counts;
  counts.reserve(sets.size());
  for (const std::size_t k : sets) {
    for (std::size_t i = first.at(k); i < first.at(k + 1); ++i) columns.push_back(i);
    counts.push_back(scene.sensors.at(k).points.size());
  }
  AnnualDaylight out;
  out.values = annual_sensor_values(relit, base, hours, columns, on_hour);
  out.per_sensor = sensor_daylight(out.values.lux, out.values.direct_sun_lux, out.values.sensors);
  out.per_set = sets_daylight(out.values.lux, out.values.sensors, out.per_sensor, counts);
  return out;
}

}  // namespace relight

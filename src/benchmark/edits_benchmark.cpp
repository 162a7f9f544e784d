#include "benchmark/edits_benchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "benchmark/bench_timing.h"
#include "benchmark/edit_paths.h"
#include "common/input_error.h"
#include "light/color_temperature.h"
#include "material/material_reflectance.h"
#include "math/mat3.h"
#include "runtime/progressive_frames.h"
#include "runtime/relit_scene.h"

namespace relight {

namespace {

// An edit: whether the scene allows it, and frame i's state made from the last one.
struct Edit {
  const char* name;
  std::function<bool(const LightingState&)> allowed;
  std::function<void(LightingState&, int)> step;
};

// A sky with a sun, by place and time (moved a minute a frame) or by angles (a quarter degree).
bool has_sun(const EnvironmentSpec& e) {
  return (e.type == EnvironmentType::kCieSky || e.type == EnvironmentType::kPerezSky) &&
         e.sun.placement != SunPlacement::kNone;
}

// Every environment of the state: the portals' and the top-level one.
template <class F>
void for_each_environment(LightingState& s, F&& f) {
  for (PortalState& p : s.portals) f(p.environment);
  if (s.environment) f(*s.environment);
}
template <class P>
bool any_environment(const LightingState& s, P&& p) {
  return std::any_of(s.portals.begin(), s.portals.end(),
                     [&](const PortalState& q) { return p(q.environment); }) ||
         (s.environment && p(*s.environment));
}

// The next CIE sky type after `type` that the sky can show (a type whose luminance follows the
// sun needs one).
int next_sky_type(const EnvironmentSpec& e) {
  for (int k = 1; k <= 16; ++k) {
    const int t = (e.sky_type + k) % 16;
    if (!sky_type_needs_sun(t) || e.sun.placement != SunPlacement::kNone) return t;
  }
  return e.sky_type;
}

// A step of 2 cm along the room's longer horizontal axis, toward its middle from `p`.
Vec3 step_toward_middle(const Bounds& b, Vec3 p) {
  const Vec3 extent = b.max - b.min, middle = (b.min + b.max) * 0.5;
  if (extent.x >= extent.z) return {middle.x >= p.x ? 0.02 : -0.02, 0, 0};
  return {0, 0, middle.z >= p.z ? 0.02 : -0.02};
}

// A drag of `step` a frame, ten frames one way and ten back, so a long run stays where it began.
double back_and_forth(int frame, double step) {
  return (frame / 10) % 2 == 0 ? step : -step;
}

bool same_distribution(const DistributionSpec& a, const DistributionSpec& b) {
  return a.type == b.type && a.candela == b.candela && a.exponent == b.exponent &&
         a.cutoff_deg == b.cutoff_deg && a.gamma_deg == b.gamma_deg &&
         a.curve_candela == b.curve_candela && a.file == b.file;
}

// A luminaire's distribution other than the first luminaire's, to swap it for.
std::optional<DistributionSpec> other_distribution(const LightingState& s) {
  for (const LuminaireState& l : s.luminaires) {
    if (!same_distribution(l.distribution, s.luminaires.front().distribution)) {
      return l.distribution;
    }
  }
  return std::nullopt;
}

std::vector<Edit> edits_of(const RelitScene& relit, const LightingState& home) {
  const Bounds bounds = relit.scene().bounds();
  const std::optional<DistributionSpec> other = other_distribution(home);
  const std::size_t material = most_used_material(relit.transfer());
  const auto luminaires = [](const LightingState& s) { return !s.luminaires.empty(); };
  return {
      {"dimmer", luminaires,
       [](LightingState& s, int i) {
         s.luminaires.front().dimmer = std::max(0.05, 1.0 - 0.02 * (i + 1));
       }},
      {"aim", luminaires,
       [](LightingState& s, int) {
         LuminaireState& l = s.luminaires.front();
         l.aim = normalize(mat3_rotation(normalize(l.c0), radians(1.0)) * l.aim);
       }},
      {"colour_temperature", luminaires,
       [](LightingState& s, int i) {
         s.luminaires.front().color = cct_to_rgb(std::min(kMaxCctKelvin, 3000.0 + 50.0 * (i + 1)));
       }},
      {"distribution_swap", [other](const LightingState&) { return other.has_value(); },
       [other, own = home.luminaires.empty()
                         ? DistributionSpec{}
                         : home.luminaires.front().distribution](LightingState& s, int i) {
         s.luminaires.front().distribution = i % 2 == 0 ? *other : own;
       }},
      {"luminaire_move", luminaires,
       [bounds](LightingState& s, int) {
         LuminaireState& l = s.luminaires.front();
         l.position = l.position + step_toward_middle(bounds, l.position);
       }},
      {"sky_time", [](const LightingState& s) { return any_environment(s, has_sun); },
       [](LightingState& s, int i) {
         for_each_environment(s, [&](EnvironmentSpec& e) {
           if (has_sun(e)) advance_sky(e, i);
         });
       }},
      {"sky_type",
       [](const LightingState& s) {
         return any_environment(
             s, [](const EnvironmentSpec& e) { return e.type == EnvironmentType::kCieSky; });
       },
       [](LightingState& s, int) {
         for_each_environment(s, [](EnvironmentSpec& e) {
           if (e.type == EnvironmentType::kCieSky) e.sky_type = next_sky_type(e);
         });
       }},
      {"environment_rotation",
       [](const LightingState& s) {
         return any_environment(
             s, [](const EnvironmentSpec& e) { return e.type == EnvironmentType::kMap; });
       },
       [](LightingState& s, int) {
         for_each_environment(s, [](EnvironmentSpec& e) {
           if (e.type == EnvironmentType::kMap) e.rotate_deg += 1;
         });
       }},
      {"object_dragged", [](const LightingState& s) { return !s.objects.empty(); },
       [](LightingState& s, int i) { s.objects.front().translate.x += back_and_forth(i, 0.02); }},
      {"objects_moving", [](const LightingState& s) { return s.objects.size() > 1; },
       [start = home.objects](LightingState& s, int i) {
         // Each along a circle of 0.3 m radius from where the scene put it: a 2 cm step and a
         // 2° turn a frame.
         const double a = (i + 1) * (0.02 / 0.3);
         for (std::size_t k = 0; k < s.objects.size(); ++k) {
           s.objects[k].translate =
               start[k].translate + Vec3{0.3 * (std::cos(a) - 1), 0, 0.3 * std::sin(a)};
           s.objects[k].rotate_deg = start[k].rotate_deg + 2.0 * (i + 1);
         }
       }},
      {"emitter_moved", [](const LightingState& s) { return !s.emitters.empty(); },
       [](LightingState& s, int i) { s.emitters.front().translate.x += back_and_forth(i, 0.01); }},
      {"material_albedo",
       [material](const LightingState& s) { return material < s.materials.size(); },
       [material](LightingState& s, int i) {
         Material& m = s.materials[material];
         m.albedo = m.albedo * (i % 2 == 0 ? 0.98 : 1 / 0.98);
       }},
      {"material_roughness",
       [material](const LightingState& s) { return material < s.materials.size(); },
       [material](LightingState& s, int i) {
         Material& m = s.materials[material];
         m.glossy = true;
         m.roughness = 0.3 + 0.01 * (i % 5);
       }},
  };
}

double sensor_lux_difference(const std::vector<Rgb>& first, const std::vector<Rgb>& converged) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < converged.size(); ++k) {
    const double c = luminance(converged[k]);
    if (!(c > 0)) continue;
    sum += std::abs(luminance(first[k]) - c) / c;
    ++n;
  }
  return n > 0 ? sum / static_cast<double>(n) : 0;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

std::vector<nlohmann::ordered_json> run_edits_bench(const BenchOptions& args) {
  if (args.sky || args.environment || args.emitters || args.objects || args.materials || args.aim ||
      args.layout || !args.optimize.empty() || !args.object.empty() || !args.material.empty() ||
      args.roughness) {
    fail_input(args.rlt, "--edits times every kind of edit itself: give no other mode with it");
  }
  // As the studio does at start: the glossy BRDF's table is built before an edit needs it.
  prepare_metallic_roughness_tables();
  RelitScene relit(args.rlt, std::nullopt);
  const LightingState home = default_lighting_state(relit.scene());
  const bool sensors = relit.scene().sensor_count() > 0;
  std::vector<nlohmann::ordered_json> lines;
  double worst_first = 0, worst_converged = 0;
  for (Edit& edit : edits_of(relit, home)) {
    if (!edit.allowed(home)) continue;
    relit.apply(home);
    LightingState state = home;
    std::vector<double> first_ms, converged_ms, first_error;
    for (int i = 0; i < args.frames; ++i) {
      edit.step(state, i);
      std::vector<Rgb> first_sensors;
      bool first = true;
      const auto start = std::chrono::steady_clock::now();
      show_progressively(relit, state, [&](bool) {
        const double ms = ms_since(start);
        if (first) {
          first_ms.push_back(ms);
          if (sensors) first_sensors = relit.sensor_irradiance();
          first = false;
        }
        converged_ms.resize(first_ms.size());
        converged_ms.back() = ms;
      });
      if (sensors)
        first_error.push_back(sensor_lux_difference(first_sensors, relit.sensor_irradiance()));
    }
    const double first_median = median(first_ms), converged_median = median(converged_ms);
    worst_first = std::max(worst_first, first_median);
    worst_converged = std::max(worst_converged, converged_median);
    lines.push_back({{"edit", edit.name},
                     {"first_ms", first_median},
                     {"converged_ms", converged_median},
                     {"first_error", sensors ? nlohmann::ordered_json(median(first_error))
                                             : nlohmann::ordered_json()},
                     {"frames", args.frames},
                     {"receivers", relit.relighter().receivers()}});
  }
  lines.push_back({{"edits", lines.size()},
                   {"worst_first_ms", worst_first},
                   {"worst_converged_ms", worst_converged}});
  return lines;
}

}  // namespace relight

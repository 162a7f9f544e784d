#include "benchmark/frame_benchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "benchmark/bench_timing.h"
#include "benchmark/edit_paths.h"
#include "benchmark/layout_benchmark.h"
#include "common/input_error.h"
#include "design/optimize.h"
#include "material/material_reflectance.h"
#include "math/mat3.h"
#include "render/relit_scene_image.h"
#include "runtime/relit_scene.h"

namespace relight {

namespace {

// --optimize: `relight optimize` with the targets, from the scene's own state (design/
// optimize.h), against a relight of the whole scene after every dimmer changed, both medians
// of `frames` runs in the same process.
nlohmann::json bench_optimize(const BenchOptions& args) {
  RelitScene relit(args.rlt, std::nullopt);
  if (relit.scene().sensor_count() == 0) fail_input(args.rlt, "--optimize needs sensors");
  const DesignTargets targets = load_design_targets(args.optimize, relit.scene());
  LightingState state = relit.state();
  const double relight_ms = median(time_ms(args.frames, [&](int i) {
    for (LuminaireState& l : state.luminaires) l.dimmer = 0.5 + 0.5 * ((i % 2) == 0);
    relit.apply(state);
  }));
  OptimizeResult result;
  const double optimize_ms = median(time_ms(
      args.frames, [&](int) { result = optimize_lighting(relit, StartState{}, targets, {}); }));
  return {{"mode", "optimize"},
          {"receivers", relit.relighter().receivers()},
          {"luminaires", relit.scene().luminaires.size()},
          {"sensors", relit.scene().sensor_count()},
          {"frames", args.frames},
          {"median_ms", optimize_ms},
          {"relight_ms", relight_ms},
          {"ratio_to_relight", optimize_ms / relight_ms},
          {"feasible", result.feasible},
          {"objective", result.objective_value},
          {"iterations", result.iterations},
          {"aim_trials", result.aim_trials}};
}

}  // namespace

nlohmann::json run_bench(const BenchOptions& args) {
  if (!args.optimize.empty()) {
    if (args.sky || args.environment || args.emitters || args.objects || args.materials ||
        args.aim) {
      fail_input(args.rlt,
                 "--optimize times inverse design alone: no --sky, --environment, --emitters, "
                 "--objects, --materials or --aim with it");
    }
    return bench_optimize(args);
  }
  if (args.layout) {
    if (args.sky || args.environment || args.emitters || args.objects || args.materials ||
        args.aim) {
      fail_input(args.rlt,
                 "--layout moves and adds luminaires alone: no --sky, --environment, --emitters, "
                 "--objects, --materials or --aim with it");
    }
    return bench_layout(args);
  }
  RelitScene relit(args.rlt, std::nullopt);
  Relighter& relighter = relit.relighter();
  std::vector<float> irradiance(3 * relighter.receivers());
  LightingState state = relighter.state();

  if (args.sky && state.portals.empty()) {
    fail_input(args.rlt, "--sky needs a scene with portals (windows)");
  }
  if (args.environment && !state.environment) {
    fail_input(args.rlt, "--environment needs a scene with a top-level environment");
  }
  if (args.emitters && state.emitters.empty()) {
    fail_input(args.rlt, "--emitters needs a scene with near-field emitters");
  }
  if (args.objects && state.objects.empty()) {
    fail_input(args.rlt, "--objects needs a scene with movable objects");
  }
  if (int(args.sky) + int(args.environment) + int(args.emitters) + int(args.objects) +
          int(args.materials) + int(args.aim) >
      1) {
    fail_input(args.rlt,
               "--sky, --environment, --emitters, --objects, --materials and --aim: one at a "
               "time");
  }
  if (args.materials && relit.transfer().view.scene.vertex_material.empty()) {
    fail_input(args.rlt,
               "--materials needs a file with the vertices' materials (precompute again)");
  }
  if ((!args.material.empty() || args.roughness) && !args.materials) {
    fail_input(args.rlt, "--material and --roughness need --materials");
  }
  std::size_t edited = args.materials ? most_used_material(relit.transfer()) : 0;
  if (!args.material.empty()) {
    const std::vector<Material>& materials = relit.scene().materials;
    const auto named = std::find_if(materials.begin(), materials.end(),
                                    [&](const Material& m) { return m.name == args.material; });
    if (named == materials.end() || named->portal) {
      fail_input(args.rlt, "no material named \"" + args.material + "\" to edit");
    }
    edited = static_cast<std::size_t>(named - materials.begin());
  }
  std::vector<bool> moving(state.objects.size(), args.object.empty());
  if (!args.object.empty()) {
    if (!args.objects) fail_input(args.rlt, "--object needs --objects");
    bool found = false;
    for (std::size_t k = 0; k < relit.scene().objects.size(); ++k) {
      if (relit.scene().objects[k].name == args.object) moving[k] = found = true;
    }
    if (!found) fail_input(args.rlt, "no movable object named \"" + args.object + "\"");
  }
  const std::vector<MovablePlacement> start = state.objects;
  // A frame: a lighting change (new weights, new shells) and the full weighted sum.
  relighter.relight(irradiance);  // warm
  std::vector<double> shell_ms, sun_ms, sun_bounce_ms, sampling_ms, bounce_ms;
  std::vector<double> object_direct_ms, object_transfer_ms, object_bounce_ms, object_bounces;
  std::vector<double> approximate_ms, final_ms, edit_view_ms;
  std::vector<double> environment_ms, environment_bounce_ms, environment_objects_ms;
  // A material edit's two frames: its light reflected once, then converged.
  const auto edit_material = [&](int i) {
    Material& m = state.materials.at(edited);
    if (args.roughness) {
      m.glossy = true;
      m.roughness = i % 2 == 0 ? 0.3 : 0.35;
    } else {
      m.albedo = m.albedo * (i % 2 == 0 ? 0.95 : 1 / 0.95);
    }
    const auto start_edit = std::chrono::steady_clock::now();
    relighter.set_material_bounces(0);
    relighter.set_state(state);
    relighter.relight(irradiance);
    const auto approximate = std::chrono::steady_clock::now();
    relighter.set_material_bounces(-1);
    relighter.relight(irradiance);
    const auto done = std::chrono::steady_clock::now();
    approximate_ms.push_back(
        std::chrono::duration<double, std::milli>(approximate - start_edit).count());
    final_ms.push_back(std::chrono::duration<double, std::milli>(done - start_edit).count());
    // The edited BRDF seen from the first camera (the studio's glossy view, 16 BRDF samples of
    // the room a vertex): after a roughness edit its kept diffuse-layer sums are made again.
    const std::vector<Camera>& cameras = relit.scene().cameras;
    if (!cameras.empty() && !glossy_materials(state.materials).empty()) {
      const auto view_start = std::chrono::steady_clock::now();
      (void)glossy_vertex_luminance(relit, cameras.front().eye, 16);
      edit_view_ms.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - view_start)
              .count());
    }
  };
  double first_approximate_ms = 0, first_final_ms = 0;
  if (args.materials) {
    // As the studio does at start (serve/studio_server.cpp): the BRDF's albedo table is built
    // before the first edit can need it.
    prepare_metallic_roughness_tables();
    edit_material(0);  // the first edit: its light solved from nothing
    first_approximate_ms = approximate_ms.front();
    first_final_ms = final_ms.front();
    approximate_ms.clear();
    final_ms.clear();
    edit_view_ms.clear();
  }
  const std::vector<double> frame_times = time_ms(args.frames, [&](int i) {
    if (args.materials) {
      edit_material(i + 1);
      return;
    }
    if (args.sky) {
      for (PortalState& p : state.portals) advance_sky(p.environment, i);
    } else if (args.environment) {
      advance_sky(*state.environment, i);
    } else if (args.emitters) {
      // A designer dragging the emitters: 1 cm a frame, back and forth.
      for (EmitterState& e : state.emitters) e.translate.x += (i % 2 == 0) ? 0.01 : -0.01;
    } else if (args.objects) {
      // Along a circle of 0.3 m radius from where the scene (or nothing) put each object: a
      // 2 cm step and a 2° turn a frame.
      const double a = (i + 1) * (0.02 / 0.3);
      for (std::size_t k = 0; k < state.objects.size(); ++k) {
        if (!moving[k]) continue;
        state.objects[k].translate =
            start[k].translate + Vec3{0.3 * (std::cos(a) - 1), 0, 0.3 * std::sin(a)};
        state.objects[k].rotate_deg = start[k].rotate_deg + 2.0 * (i + 1);
      }
    } else if (args.aim) {
      // A designer turning every luminaire: 1° about its C0 axis a frame, back and forth
      // (c0 stays perpendicular to the aim).
      const double a = radians(i % 2 == 0 ? 1.0 : -1.0);
      for (LuminaireState& l : state.luminaires) {
        l.aim = normalize(mat3_rotation(normalize(l.c0), a) * l.aim);
      }
    } else {
      for (LuminaireState& l : state.luminaires) l.dimmer = 0.5 + 0.5 * ((i % 2) == 0);
    }
    relighter.set_state(state);
    relighter.relight(irradiance);
    double shells = 0;
    for (std::size_t p = 0; p < state.portals.size(); ++p) shells += relighter.shell_seconds(p);
    shell_ms.push_back(shells * 1e3);
    sun_ms.push_back(relighter.portals().sun_seconds() * 1e3);
    sun_bounce_ms.push_back(relighter.portals().sun_bounce_seconds() * 1e3);
    if (const ObjectLighting* o = relighter.objects()) {
      const ObjectTimings& t = o->timings();
      object_direct_ms.push_back(t.direct_seconds * 1e3);
      object_transfer_ms.push_back(t.transfer_seconds * 1e3);
      object_bounce_ms.push_back(t.bounce_seconds * 1e3);
      object_bounces.push_back(t.bounces);
    }
    if (const EnvironmentLighting* e = relighter.environment()) {
      environment_ms.push_back(e->seconds() * 1e3);
      environment_bounce_ms.push_back(e->bounce_seconds() * 1e3);
      environment_objects_ms.push_back(e->objects_seconds() * 1e3);
    }
    if (const EmitterLighting* e = relighter.emitters()) {
      const NearfieldResult& s = e->last_sampling();
      sampling_ms.push_back((s.sampling_seconds + s.reconstruction_seconds) * 1e3);
      bounce_ms.push_back(e->last_bounce_seconds() * 1e3);
    }
  });
  const double frame_ms = median(frame_times);

  // What a frame of this kind reads and writes: the transfer of the sources that changed
  // (the other kind's partial sum is kept, runtime/relighter.h) and the sums and output.
  const std::size_t bytes = relighter.last_frame_bytes();

  // The same number of bytes read by a plain parallel reduction: the machine's streaming
  // rate. Integer addition is associative, so the compiler vectorises it and the loop is
  // bound by memory, not by a floating-point add chain.
  std::vector<std::uint64_t> buffer(std::max<std::size_t>(bytes / sizeof(std::uint64_t), 1), 1);
  auto stream = [&] {
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, buffer.size(), 1 << 14), std::uint64_t{0},
        [&](const auto& r, std::uint64_t sum) {
          return std::accumulate(buffer.begin() + r.begin(), buffer.begin() + r.end(), sum);
        },
        std::plus<std::uint64_t>());
  };
  volatile std::uint64_t sink = stream();  // warm
  const double stream_ms = median(time_ms(args.frames, [&](int) { sink = stream(); }));
  (void)sink;

  const double effective = bytes / (frame_ms * 1e-3) / 1e9;
  const double streaming = buffer.size() * sizeof(std::uint64_t) / (stream_ms * 1e-3) / 1e9;
  const char* mode =
      args.sky ? "sky"
      : args.environment
          ? "environment"
          : (args.emitters ? "emitters"
                           : (args.objects ? "objects"
                                           : (args.materials ? "materials"
                                                             : (args.aim ? "aim" : "luminaires"))));
  nlohmann::json line = {{"mode", mode},
                         {"receivers", relighter.receivers()},
                         {"luminaires", relit.scene().luminaires.size()},
                         {"portals", state.portals.size()},
                         {"transfer_bytes", bytes},
                         {"stored_transfer_bytes", relighter.transfer_bytes()},
                         {"frames", args.frames},
                         {"median_ms", frame_ms},
                         {"effective_gbps", effective},
                         {"stream_gbps", streaming},
                         {"ratio", effective / streaming},
                         {"fps", 1e3 / frame_ms}};
  if (args.sky) {
    // The weighted sum alone (to compare the window sum with the streaming rate): each frame less
    // its shells and suns, its bytes against the same streaming read.
    std::vector<double> sum_ms;
    for (std::size_t i = 0; i < frame_times.size(); ++i) {
      sum_ms.push_back(frame_times[i] - shell_ms[i] - sun_ms[i]);
    }
    line["sum_ms"] = median(sum_ms);
    line["sum_ratio"] = bytes / (median(sum_ms) * 1e-3) / 1e9 / streaming;
    line["shell_ms"] = median(shell_ms);
    // The suns traced exactly behind clear glass (sources/portals/portal_sun.h): the direct
    // sun at every receiver and its bounce, of which the bounce.
    line["suns"] = relighter.suns().size();
    line["sun_ms"] = median(sun_ms);
    line["sun_bounce_ms"] = median(sun_bounce_ms);
  }
  if (args.environment) {
    // Clustering and the cuts' sums, the bounce, and the objects' part (their shadows and
    // light through the cuts, sources/environment/environment_objects.h).
    line["environment_ms"] = median(environment_ms);
    line["bounce_ms"] = median(environment_bounce_ms);
    line["objects_ms"] = median(environment_objects_ms);
    line["cut_directions"] = relighter.environment()->tree().leaf_count();
    // The viewpoint: glossy vertices shaded toward an eye moved a centimetre a frame, with the
    // studio's BRDF samples of the room's reflection (serve/studio_server.cpp, RLGV).
    constexpr int kViewSamples = 16;
    const std::vector<Camera>& cameras = relit.scene().cameras;
    if (!glossy_materials(state.materials).empty() && !cameras.empty()) {
      const Vec3 eye = cameras.front().eye;
      line["view_ms"] = median(time_ms(args.frames, [&](int i) {
        (void)glossy_vertex_luminance(relit, eye + Vec3{0.01 * (i % 2), 0, 0}, kViewSamples);
      }));
      // An image of the first camera so moved (640 × 480, as `relight render` makes it: 2 × 2
      // rays a pixel, 64 BRDF samples a glossy vertex), which shades only the vertices its
      // rays meet (the capture paper's §V.B).
      line["view_image_ms"] = median(time_ms(args.frames, [&](int i) {
        Camera moved = cameras.front();
        moved.eye = eye + Vec3{0.01 * (i % 2), 0, 0};
        (void)render_relit_scene(relit, moved, 640, 480);
      }));
    }
  }
  if (args.emitters) {
    line["emitters"] = state.emitters.size();
    line["sampling_ms"] = median(sampling_ms);
    line["bounce_ms"] = median(bounce_ms);
  }
  if (args.objects) {
    // The objects' term (sources/objects/object_lighting.h): their direct light and shadows,
    // their transfer traced again (the paper's basis irradiance), and the bounce.
    const ObjectLighting& o = *relighter.objects();
    line["objects"] = state.objects.size();
    line["moving"] = std::count(moving.begin(), moving.end(), true);
    line["object_vertices"] = o.placed().vertex_count();
    line["direct_ms"] = median(object_direct_ms);
    line["transfer_ms"] = median(object_transfer_ms);
    line["bounce_ms"] = median(object_bounce_ms);
    line["bounces"] = median(object_bounces);
    line["transfer_rays"] = o.timings().rays;
  }
  if (args.materials) {
    line["material"] = relit.scene().materials[edited].name;
    line["edit"] = args.roughness ? "roughness" : "albedo";
    line["approximate_ms"] = median(approximate_ms);
    line["final_ms"] = median(final_ms);
    line["first_approximate_ms"] = first_approximate_ms;
    line["first_final_ms"] = first_final_ms;
    if (!edit_view_ms.empty()) line["edit_view_ms"] = median(edit_view_ms);
  }
  return line;
}

}  // namespace relight

// `relight reference SCENE.json [--spp N] [--seed S] [--sensors-out FILE.csv]
//   [--camera NAME] [--width W --height H] [-o IMAGE.exr|IMAGE.png]
//   [--exposure EV] [--false-color lux|luminance [--range MIN:MAX]]`
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/oriented_scene.h"
#include "cli/reference_run.h"
#include "cli/view_args.h"
#include "common/input_error.h"
#include "light/emitter_placement.h"
#include "light/environment_map_io.h"
#include "light/luminaire_frame.h"
#include "reference/reference_tracer.h"
#include "render/sensor_report.h"
#include "runtime/lighting_state.h"
#include "scene/scene_loader.h"
#include "sources/portals/portal_lighting.h"
#include "trace/traced_scene.h"

namespace relight {

namespace {

struct ReferenceArgs {
  std::string scene;
  ReferenceRequest request;
  std::string sensors_out;
  ViewArgs view;
  std::uint64_t seed = 1;
  std::string state;
};

void print_rate(const char* what, const ReferenceStats& s) {
  std::printf("reference %s: %.3g Mrays in %.2f s (%.2f Mrays/s)\n", what, s.rays * 1e-6, s.seconds,
              s.seconds > 0 ? s.rays * 1e-6 / s.seconds : 0.0);
  std::fflush(stdout);
}

}  // namespace

void run_reference(const Scene& scene_file, const ReferenceRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  const LightingState state = request.state ? load_lighting_state(scene_file, *request.state)
                                            : default_lighting_state(scene_file);
  const Scene scene = scene_with_state(scene_file, state);
  const std::vector<PlacedLuminaire> luminaires = place_luminaires(scene);
  // The reference traces the surfaces as they are: no subdivision for receivers.
  PreparationSettings preparation;
  preparation.max_edge = 0;
  preparation.crease_deg = scene.precompute.crease_deg;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, preparation);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  // The exterior objects in front of each window, as the state places them for it.
  std::vector<std::vector<ExteriorObject>> exterior;
  for (const PortalState& p : state.portals) exterior.push_back(placed_exterior(scene, p.exterior));
  // The exterior of each portal; map files are read here, not in the tracer.
  std::vector<Environment> environments;
  for (const Portal& portal : scene.portals) {
    environments.push_back(load_environment(portal.environment));
  }
  ReferenceScene ref =
      make_reference_scene(scene, mesh, traced, luminaires, std::move(environments),
                           place_emitters(scene.emitters, state.emitters), exterior);
  if (scene.environment) light_with_environment(ref, load_environment(*scene.environment));
  ReferenceSettings settings;
  settings.spp = request.spp;
  settings.seed = request.seed;
  settings.progress = request.progress;
  settings.max_bounces = request.max_bounces;

  // Validate the camera before spending time on sensors.
  std::optional<Camera> camera;
  if (!request.images.empty()) camera = choose_camera(scene, request.camera, scene.bounds());

  if (request.sensors && scene.sensor_count() > 0) {
    ReferenceStats stats;
    const std::vector<Rgb> e = reference_sensor_illuminance(scene, ref, settings, &stats);
    print_rate("sensors", stats);
    print_sensor_statistics(std::cout, sensor_statistics(scene, e));
    if (request.sensors_out) {
      write_sensor_csv(*request.sensors_out, scene, e);
      std::cout << "wrote " << request.sensors_out->string() << "\n";
    }
  } else if (request.sensors_out) {
    fail_input(scene.file.string(), "--sensors-out given but the scene has no sensors");
  }

  if (camera) {
    const PinholeCamera pinhole = make_pinhole_camera(*camera, request.width, request.height);
    ReferenceStats stats;
    const ReferenceImages images = reference_render(pinhole, ref, settings, &stats);
    warn_back_sides(*camera, images.back_side_pixels, images.luminance.pixels.size());
    print_rate("image", stats);
    for (const ImageOutput& out : request.images) {
      const bool lux =
          out.display.false_color && out.display.false_color->quantity == Quantity::kIlluminance;
      const DisplayReport report =
          write_image(out.file, lux ? images.illuminance : images.luminance, out.display);
      std::cout << "wrote " << out.file.string() << " (" << request.width << "x" << request.height
                << ", " << request.spp << " spp, camera " << camera->name;
      if (report.exposure_ev) std::cout << ", EV " << *report.exposure_ev;
      std::cout << ")\n";
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "reference finished in " << seconds << " s\n";
}

void add_reference_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ReferenceArgs>();
  CLI::App* cmd = app.add_subcommand(
      "reference", "Monte Carlo path tracing of a scene: sensor illuminance and/or an image");
  cmd->add_option("scene", args->scene, "scene JSON file")->required();
  cmd->add_option("--spp", args->request.spp, "samples per sensor and per pixel")
      ->check(CLI::Range(1, 1 << 24));
  cmd->add_option("--seed", args->seed, "random seed (results are deterministic per seed)");
  cmd->add_option("--state", args->state,
                  "lighting state JSON (luminaires, windows, emitters) to trace the scene under");
  cmd->add_option("--sensors-out", args->sensors_out, "write sensor illuminance CSV here");
  cmd->add_option("--max-bounces", args->request.max_bounces,
                  "longest path counted: 1 = direct light only, 2 = one more reflection, ...; "
                  "0 (default) = no limit")
      ->check(CLI::Range(0, 1000));
  add_view_options(*cmd, args->view);
  cmd->add_flag("!--no-progress", args->request.progress, "no progress bar");
  cmd->callback([args, &action] {
    action = [args] {
      ReferenceRequest request = args->request;
      request.seed = args->seed;
      if (!args->state.empty()) request.state = args->state;
      if (!args->sensors_out.empty()) request.sensors_out = args->sensors_out;
      request.width = args->view.width;
      request.height = args->view.height;
      if (!args->view.camera.empty()) request.camera = args->view.camera;
      if (!args->view.output.empty()) {
        request.images.push_back({args->view.output, display_options(args->view)});
      }
      request.sensors = request.sensors_out.has_value() || request.images.empty();
      run_reference(oriented_scene(load_scene(args->scene)), request);
      return 0;
    };
  });
}

}  // namespace relight

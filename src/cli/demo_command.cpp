// `relight demo [-o DIR]`: the built-in furnished room on the precomputed path. Writes
// the scene, precomputes it once (cached beside the images, reused while the scene is
// unchanged), relights it under two lighting states written as state files and under a
// clear day through its south window at three times (images side by side), renders and
// probes each, and says where the files are. `--reference` also renders the same
// room with the independent path tracer for comparison. Then it serves the studio on the room
// (relight serve, docs/studio.md) and prints the URL; `--no-serve` ends after the files.
#include <filesystem>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/demo_room.h"
#include "cli/precompute_run.h"
#include "cli/oriented_scene.h"
#include "cli/reference_run.h"
#include "cli/serve_run.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "render/relit_scene_image.h"
#include "render/sensor_report.h"
#include "runtime/relit_scene.h"
#include "scene/scene_loader.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

struct DemoArgs {
  std::string out = "relight-demo";
  int width = 640, height = 400;
  bool reference = false;
  int spp = 32;
  bool progress = true;
  bool serve = true;
  StudioOptions studio;
};

// Two light scenes a designer might set up: a dim warm evening and a bright work light
// with the wall washer re-aimed at the accent wall.
const char* kEvening = R"({
  "luminaires": {
    "downlight left":  { "dimmer": 0.3, "cct_kelvin": 2700 },
    "downlight right": { "dimmer": 0.3, "cct_kelvin": 2700 },
    "wall washer":     { "on": false },
    "pendant":         { "dimmer": 1.0, "cct_kelvin": 2200 }
  },
  "portals": {
    "south window": { "environment": { "type": "cie_sky", "sky_type": "overcast",
                                       "horizontal_illuminance": 30 } }
  }
})";
const char* kWork = R"({
  "luminaires": {
    "downlight left":  { "cct_kelvin": 4000 },
    "downlight right": { "cct_kelvin": 4000 },
    "wall washer":     { "target": [4.9, 1.0, 0.4], "cct_kelvin": 4000 },
    "pendant":         { "on": false }
  }
})";

// A clear equinox day at the scene's site (Munich) through the south window, the luminaires as
// the scene sets them: the sun moves from the south-east to the south-west, and the sky and sun
// are as bright as its altitude makes them (light/daylight_availability.h).
std::string clear_day_state(const char* local_time) {
  return std::string(R"({
  "portals": {
    "south window": { "environment": {
      "type": "cie_sky", "sky_type": 12, "ground_albedo": 0.2,
      "sun": { "datetime": "2026-03-21T)") +
         local_time + R"(" } } }
  }
})";
}

// Images of equal size, left to right, in one image (one exposure for all).
Image side_by_side(const std::vector<Image>& images) {
  Image strip =
      make_image(images.front().width * static_cast<int>(images.size()), images.front().height);
  for (std::size_t k = 0; k < images.size(); ++k) {
    const Image& image = images[k];
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        strip.at(static_cast<int>(k) * image.width + x, y) = image.at(x, y);
      }
    }
  }
  return strip;
}

bool cached_precompute_matches(const fs::path& rlt, const nlohmann::json& document) {
  if (!fs::exists(rlt)) return false;
  try {
    const TransferFile t = open_transfer_file(rlt);
    return t.metadata.value("scene_digest", "") == scene_digest(document);
  } catch (const InputError&) {
    return false;  // stale or damaged cache: precompute again
  }
}

int run_demo(const DemoArgs& args) {
  const fs::path dir = args.out;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) fail_input(dir.string(), "cannot create output folder: " + ec.message());
  const fs::path scene_file = dir / "demo-room.json";
  const nlohmann::json document = demo_room_scene();
  write_text_atomically(scene_file, document.dump(2) + "\n");

  const fs::path rlt = dir / "demo-room.rlt";
  if (cached_precompute_matches(rlt, document)) {
    std::cout << "using the cached precompute " << rlt.string() << "\n";
  } else {
    PrecomputeOptions options;
    options.progress = args.progress;
    run_precompute(document, scene_file, rlt, options);
  }

  RelitScene relit(rlt, std::nullopt);
  const Scene& scene = relit.scene();
  const Camera& camera = scene.cameras.front();
  for (const auto& [name, text] : {std::pair{"evening", kEvening}, std::pair{"work", kWork}}) {
    const fs::path state_file = dir / (std::string(name) + ".json");
    write_text_atomically(state_file, text);
    relit.apply(load_lighting_state(scene, state_file));
    const ShadedImages images = render_relit_scene(relit, camera, args.width, args.height, true);
    const fs::path png = dir / ("room-" + std::string(name) + ".png");
    const fs::path lux = dir / ("room-" + std::string(name) + "-lux.png");
    const fs::path csv = dir / ("work-plane-" + std::string(name) + ".csv");
    write_image(png, images.luminance, {});
    DisplayOptions false_color;
    false_color.false_color = FalseColor{};
    false_color.false_color->quantity = Quantity::kIlluminance;
    write_image(lux, images.illuminance, false_color);
    const std::vector<Rgb> e = relit.sensor_irradiance();
    write_sensor_csv(csv, scene, e);
    std::cout << name << ": ";
    print_sensor_statistics(std::cout, sensor_statistics(scene, e));
  }

  // Daylight: one clear day at three times, side by side with one exposure.
  std::vector<Image> day;
  for (const char* time : {"10:00", "13:00", "16:00"}) {
    const std::string name = std::string("day-") + time[0] + time[1] + time[3] + time[4];
    const fs::path state_file = dir / (name + ".json");
    write_text_atomically(state_file, clear_day_state(time));
    relit.apply(load_lighting_state(scene, state_file));
    const ShadedImages images = render_relit_scene(relit, camera, args.width, args.height, true);
    write_image(dir / ("room-" + name + ".png"), images.luminance, {});
    write_sensor_csv(dir / ("work-plane-" + name + ".csv"), scene, relit.sensor_irradiance());
    std::cout << name << ": ";
    print_sensor_statistics(std::cout, sensor_statistics(scene, relit.sensor_irradiance()));
    day.push_back(images.luminance);
  }
  write_image(dir / "room-day-side-by-side.png", side_by_side(day), {});

  if (args.reference) {
    ReferenceRequest request;
    request.spp = args.spp;
    request.width = args.width;
    request.height = args.height;
    request.progress = args.progress;
    request.sensors_out = dir / "work-plane-reference.csv";
    request.images = {{dir / "reference.png", {}}, {dir / "reference.exr", {}}};
    run_reference(oriented_scene(scene_from_json(document, scene_file)), request);
  }

  std::cout << "\ndemo files in " << fs::absolute(dir).lexically_normal().string() << ":\n"
            << "  demo-room.json           the scene\n"
            << "  demo-room.rlt            its precomputed transfer (reused while the scene is "
               "unchanged)\n"
            << "  evening.json, work.json  two lighting states\n"
            << "  room-evening.png         the room under each state, tone-mapped\n"
            << "  room-work.png\n"
            << "  room-*-lux.png           illuminance in lux, false colour with legend\n"
            << "  day-1000.json, ...       a clear day through the south window at 10, 13, 16 h\n"
            << "  room-day-*.png           the room at each time; room-day-side-by-side.png all\n"
            << "                           three with one exposure\n"
            << "  work-plane-*.csv         work-plane illuminance per sensor\n";
  if (args.reference) {
    std::cout << "  reference.png/.exr       the same room by the reference path tracer\n";
  }
  std::cout << "try: relight render " << rlt.string() << " --state " << (dir / "work.json").string()
            << " --false-color lux -o my-view.png\n";
  if (!args.serve) return 0;
  std::cout << "\nthe studio: design the light of this room in a browser (docs/studio.md)\n";
  return serve_studio(rlt, args.studio);
}

}  // namespace

void add_demo_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand("demo", "Precompute, relight and render the built-in room");
  cmd->add_option("-o,--output", args->out, "output folder")->capture_default_str();
  cmd->add_option("--width", args->width, "image width")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  cmd->add_option("--height", args->height, "image height")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  cmd->add_flag("--reference", args->reference, "also render with the reference path tracer");
  cmd->add_option("--spp", args->spp, "reference samples per pixel")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_flag("!--no-progress", args->progress, "no progress bars");
  cmd->add_flag("!--no-serve", args->serve, "end after writing the files (batch use)");
  add_studio_address_options(*cmd, args->studio);
  cmd->callback([args, &action] { action = [args] { return run_demo(*args); }; });
}

}  // namespace relight

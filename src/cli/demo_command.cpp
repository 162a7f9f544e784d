// `relight demo [-o DIR]`: writes the built-in furnished room as a scene file, renders
// it with the reference path tracer (luminance PNG + EXR, false-colour illuminance PNG,
// work-plane sensor CSV) and says where the files are.
#include <filesystem>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/demo_room.h"
#include "cli/reference_run.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "scene/scene_loader.h"

namespace relight {

namespace fs = std::filesystem;

namespace {

struct DemoArgs {
  std::string out = "relight-demo";
  int spp = 32;
  int width = 640, height = 400;
  bool progress = true;
};

int run_demo(const DemoArgs& args) {
  const fs::path dir = args.out;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) fail_input(dir.string(), "cannot create output folder: " + ec.message());
  const fs::path scene_file = dir / "demo-room.json";
  const nlohmann::json document = demo_room_scene();
  write_text_atomically(scene_file, document.dump(2) + "\n");
  const Scene scene = scene_from_json(document, scene_file);
  std::cout << "relight demo: furnished room, " << scene.geometry.triangles.size() << " triangles, "
            << scene.luminaires.size() << " luminaires\n";

  ReferenceRequest request;
  request.spp = args.spp;
  request.width = args.width;
  request.height = args.height;
  request.progress = args.progress;
  request.sensors_out = dir / "work-plane.csv";
  request.images = {{dir / "room.png", {}}, {dir / "room.exr", {}}, {dir / "room-lux.png", {}}};
  FalseColor lux;
  lux.quantity = Quantity::kIlluminance;
  request.images.back().display.false_color = lux;
  run_reference(scene, request);

  std::cout << "\ndemo files in " << fs::absolute(dir).lexically_normal().string() << ":\n"
            << "  demo-room.json  the scene (edit it and run: relight reference "
            << scene_file.string() << " -o room.png)\n"
            << "  room.png        luminance, tone-mapped\n"
            << "  room.exr        luminance in cd/m2 (HDR)\n"
            << "  room-lux.png    illuminance in lux, false colour with legend\n"
            << "  work-plane.csv  work-plane illuminance per sensor\n";
  return 0;
}

}  // namespace

void add_demo_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand("demo", "Render the built-in furnished room");
  cmd->add_option("-o,--output", args->out, "output folder")->capture_default_str();
  cmd->add_option("--spp", args->spp, "samples per pixel")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--width", args->width, "image width")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  cmd->add_option("--height", args->height, "image height")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  cmd->add_flag("!--no-progress", args->progress, "no progress bar");
  cmd->callback([args, &action] { action = [args] { return run_demo(*args); }; });
}

}  // namespace relight

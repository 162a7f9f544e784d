// `relight render SCENE.rlt [--state STATE.json] [--max-bounces 1] [--camera NAME] [--width W
// --height H]
//   [--exposure EV] [--false-color lux|luminance [--range MIN:MAX]] -o IMAGE.png|IMAGE.exr`
// Relights the precomputed scene and renders per-vertex radiance (Gouraud-equivalent).
#include <chrono>
#include <cstdio>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/max_bounces.h"
#include "cli/view_args.h"
#include "render/relit_scene_image.h"
#include "render/vertex_shading.h"
#include "runtime/relit_scene.h"

namespace relight {

namespace {

struct RenderArgs {
  std::string rlt, state, direct = "vertex";
  int max_bounces = 0;
  ViewArgs view;
};

int run_render(const RenderArgs& args) {
  const auto start = std::chrono::steady_clock::now();
  const DisplayOptions display = display_options(args.view);
  RelitScene relit(
      args.rlt,
      args.state.empty() ? std::nullopt : std::optional<std::filesystem::path>(args.state),
      max_bounces_settings(args.max_bounces));
  check_max_bounces(relit.scene(), args.max_bounces, args.rlt);
  const TransferFile& t = relit.transfer();
  const Camera camera = choose_camera(
      t.scene,
      args.view.camera.empty() ? std::nullopt : std::optional<std::string>(args.view.camera),
      t.bounds());
  const ShadedImages images =
      render_relit_scene(relit, camera, args.view.width, args.view.height, args.direct == "pixel");
  warn_back_sides(camera, images.back_side_pixels, images.luminance.pixels.size());
  const bool lux = display.false_color && display.false_color->quantity == Quantity::kIlluminance;
  const DisplayReport report =
      write_image(args.view.output, lux ? images.illuminance : images.luminance, display);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("wrote %s (%dx%d, camera %s", args.view.output.c_str(), args.view.width,
              args.view.height, camera.name.c_str());
  if (report.exposure_ev) std::printf(", EV %.2f", *report.exposure_ev);
  std::printf(", %.2f s)\n", seconds);
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a precomputed scene under a lighting state");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_option("--state", args->state, "lighting state JSON (default: the scene's own)");
  add_max_bounces_option(*cmd, args->max_bounces);
  add_view_options(*cmd, args->view);
  cmd->add_option("--direct", args->direct,
                  "vertex: per-vertex radiance interpolated (Gouraud, default); pixel: direct "
                  "light exact at every pixel, interreflection interpolated")
      ->check(CLI::IsMember({"vertex", "pixel"}));
  cmd->get_option("-o")->required();
  cmd->callback([args, &action] { action = [args] { return run_render(*args); }; });
}

}  // namespace relight

// `relight nearfield SCENE.rlt [--state STATE.json] --epsilon E [--max-samples N]
//   [--method adaptive|icp|truth] [--face-size K] [--scene-occlusion] [-o IMAGE] [view options]`
// Lights a precomputed scene's receivers by its near-field emitters as the lighting state places
// them (Sun 2005; sources/emitters/nearfield_lighting.h), with the chosen sampling method, and
// compares with the truth (a sample at every receiver), on the direct light the sampling decides
// (interreflection, when on, is the same for both). Prints one JSON line: method, epsilon,
// max_samples, receivers, samples, evaluations, placement_s, sampling_s, reconstruction_s, truth_s,
// rmse (cd/m², vertex radiance ρE/π, RGB) and rmse_relative (rmse over the truth's RMS radiance).
// With -o, renders the receivers' radiance.
#include <chrono>
#include <cstdio>
#include <memory>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/view_args.h"
#include "common/input_error.h"
#include "math/sh.h"
#include "render/vertex_shading.h"
#include "runtime/relit_scene.h"
#include "scene/camera.h"
#include "sources/emitters/nearfield_lighting.h"
#include "sources/transfer_file.h"

namespace relight {

namespace {

struct NearfieldArgs {
  std::string rlt, state, method = "adaptive";
  double epsilon = 0.01;
  std::size_t max_samples = 4096;
  int face_size = 16;
  bool scene_occlusion = false;
  ViewArgs view;
};

int run_nearfield(const NearfieldArgs& args) {
  RelitScene relit(args.rlt, args.state.empty() ? std::nullopt
                                                : std::optional<std::filesystem::path>(args.state));
  const TransferFile& t = relit.transfer();
  if (t.scene.emitters.empty()) {
    fail_input(args.rlt, "the scene has no emitters (\"emitters\" in the scene file)");
  }
  const LightingState& state = relit.state();
  NearfieldSettings settings;
  settings.method = parse_nearfield_method(args.method);
  settings.epsilon = args.epsilon;
  settings.max_samples = args.max_samples;
  settings.face_size = args.face_size;
  settings.scene_occlusion = args.scene_occlusion;

  const NearfieldTransferView& nf = t.view.nearfield;
  const NearfieldScene scene(t.view.scene.receiver_positions, nf.sh_order, t.positions,
                             t.view.scene.opaque_triangles);
  const PlacedEmitters emitters = place_emitters(t.scene.emitters, state.emitters);
  const std::size_t k = static_cast<std::size_t>(sh_count(nf.sh_order));

  const auto shade = [&](const NearfieldResult& r) {
    std::vector<float> e(3 * scene.receiver_count());
    nearfield_irradiance(nf.transfer, r.sh, k, e);
    return e;
  };
  const NearfieldResult result = scene.light(emitters, settings);
  const std::vector<float> irradiance = shade(result);
  NearfieldSettings truth_settings = settings;
  truth_settings.method = NearfieldMethod::kTruth;
  const NearfieldResult truth = settings.method == NearfieldMethod::kTruth
                                    ? NearfieldResult{}
                                    : scene.light(emitters, truth_settings);
  const std::vector<float> reference =
      settings.method == NearfieldMethod::kTruth ? irradiance : shade(truth);
  const std::vector<float> l = relit.vertex_radiance(irradiance),
                           l_truth = relit.vertex_radiance(reference);
  const std::vector<float> zero(l.size(), 0.0f);
  const double rmse = rms_difference(l, l_truth, t.vertex_count);
  const double truth_rms = rms_difference(l_truth, zero, t.vertex_count);

  if (!args.view.output.empty()) {
    const Camera camera = choose_camera(
        t.scene,
        args.view.camera.empty() ? std::nullopt : std::optional<std::string>(args.view.camera),
        t.bounds());
    const PinholeCamera pinhole = make_pinhole_camera(camera, args.view.width, args.view.height);
    const ShadedImages images = shade_vertices(pinhole, {relit.opaque_tracer(),
                                                         t.positions,
                                                         t.triangles,
                                                         t.vertex_albedo,
                                                         irradiance,
                                                         {},
                                                         {},
                                                         {},
                                                         {}});
    const DisplayOptions display = display_options(args.view);
    const bool lux = display.false_color && display.false_color->quantity == Quantity::kIlluminance;
    write_image(args.view.output, lux ? images.illuminance : images.luminance, display);
  }
  const nlohmann::json line = {
      {"method", nearfield_method_name(settings.method)},
      {"epsilon", settings.epsilon},
      {"max_samples", settings.max_samples},
      {"receivers", scene.receiver_count()},
      {"samples", result.samples.size()},
      {"evaluations", result.evaluations},
      {"placement_s", result.placement_seconds},
      {"sampling_s", result.sampling_seconds},
      {"reconstruction_s", result.reconstruction_seconds},
      {"truth_s", settings.method == NearfieldMethod::kTruth ? result.sampling_seconds
                                                             : truth.sampling_seconds},
      {"rmse", rmse},
      {"rmse_relative", truth_rms > 0 ? rmse / truth_rms : 0.0}};
  std::printf("%s\n", line.dump().c_str());
  return 0;
}

}  // namespace

void add_nearfield_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<NearfieldArgs>();
  CLI::App* cmd = app.add_subcommand(
      "nearfield", "Light a precomputed scene by its near-field emitters (adaptive sampling)");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file of a scene with emitters")->required();
  cmd->add_option("--state", args->state, "lighting state JSON (default: the scene's own)");
  cmd->add_option("--epsilon", args->epsilon, "the oracle's error bound (adaptive)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--max-samples", args->max_samples,
                  "cap on samples (adaptive) or their number (icp)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 24))
      ->capture_default_str();
  cmd->add_option("--method", args->method, "adaptive (the thesis), icp (the baseline) or truth")
      ->check(CLI::IsMember({"adaptive", "icp", "truth"}))
      ->capture_default_str();
  cmd->add_option("--face-size", args->face_size, "cubemap texels per face side at each sample")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  cmd->add_flag("--scene-occlusion", args->scene_occlusion,
                "the static scene occludes the emitters at each sample too (default: only the "
                "emitters; static shadows are in the transfer)");
  add_view_options(*cmd, args->view);
  cmd->callback([args, &action] { action = [args] { return run_nearfield(*args); }; });
}

}  // namespace relight

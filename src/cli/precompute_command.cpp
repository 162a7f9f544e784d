// `relight precompute SCENE.json -o SCENE.rlt`: the expensive step, once per static
// scene; prints a summary of rays, rates, time per phase and bytes stored.
#include <cstdio>
#include <filesystem>
#include <memory>

#include <unistd.h>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/precompute_run.h"
#include "common/input_error.h"
#include "scene/scene_loader.h"
#include "sources/object/object_sections.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"

namespace relight {

namespace {

struct PrecomputeArgs {
  std::string scene, output;
  std::uint64_t seed = 1;
  bool progress = true;
};

}  // namespace

void run_precompute(const nlohmann::json& document, const std::filesystem::path& scene_file,
                    const std::filesystem::path& output, const PrecomputeOptions& options) {
  // Refuse an unwritable destination before the long computation, not after it.
  const std::filesystem::path folder =
      output.has_parent_path() ? output.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(folder) || ::access(folder.c_str(), W_OK) != 0) {
    fail_input(output.string(),
               "cannot write: folder " + folder.string() + " does not exist or is not writable");
  }
  const Scene scene = scene_from_json(document, scene_file);
  const Precomputed p = precompute_transfer(scene, options);
  for (const std::string& w : p.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  write_transfer_file(output, p, scene, document, scene_file);

  std::uint64_t rays = 0;
  double seconds = 0;
  std::printf("precompute %s: %zu vertices, %zu sensors, %zu luminaires, sh_order %d, direct %s\n",
              scene_file.string().c_str(), p.receivers.vertex_count, p.receivers.sensor_count,
              p.luminaires.size(), p.sh_order, p.direct_mode.c_str());
  for (const PhaseTiming& t : p.phases) {
    rays += t.rays;
    seconds += t.seconds;
    if (t.rays > 0) {
      std::printf("  %-18s %8.2f s  %10.3g rays  %6.2f Mrays/s\n", t.name.c_str(), t.seconds,
                  double(t.rays), t.rays * 1e-6 / std::max(t.seconds, 1e-9));
    } else {
      std::printf("  %-18s %8.2f s\n", t.name.c_str(), t.seconds);
    }
  }
  std::printf("  bounces: %d (tolerance %g)\n", p.bounces, scene.precompute.tolerance);
  for (const PortalTransfer& t : p.portals) {
    const CubemapEncodingStats& s = t.direct.stats;
    const double n = std::max<double>(1, static_cast<double>(s.receivers));
    std::printf(
        "  portal \"%s\": %.2f m², %.2f m across; direct %d² a face: %.1f B/receiver "
        "(%zu empty, %zu pulse %.1f B avg, %zu Haar %.1f B avg; all pulse %.1f, all Haar %.1f "
        "B/receiver), %.0f samples/receiver; indirect l < %d RGB: %.0f B/receiver\n",
        t.geometry.name.c_str(), t.geometry.area, t.geometry.diameter, t.direct.face_size,
        bytes_per_receiver(s), s.empty, s.pulse,
        s.pulse ? double(s.pulse_bytes) / double(s.pulse) : 0.0, s.haar,
        s.haar ? double(s.haar_bytes) / double(s.haar) : 0.0, double(s.all_pulse_bytes) / n,
        double(s.all_haar_bytes) / n, double(t.direct.samples) / n, p.portal_sh_order,
        double(t.indirect_blocks.size() * sizeof(float)) / n);
  }
  for (std::size_t i = 0; i < p.objects.size(); ++i) {
    const ObjectMesh& o = p.objects[i];
    std::printf("  object \"%s\": %zu vertices, %zu triangles, %.1f kB stored, %.3f s\n",
                o.name.c_str(), o.positions.size(), o.triangles.size(),
                object_section_bytes(o) / 1e3, p.object_seconds[i]);
    seconds += p.object_seconds[i];
  }
  std::printf("  total %.2f s, %.3g rays, %.2f Mrays/s\n", seconds, double(rays),
              rays * 1e-6 / std::max(seconds, 1e-9));
  std::printf("wrote %s (%.2f MB)\n", output.string().c_str(),
              std::filesystem::file_size(output) / 1e6);
}

void add_precompute_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<PrecomputeArgs>();
  CLI::App* cmd = app.add_subcommand("precompute", "Precompute radiance transfer into a .rlt file");
  cmd->add_option("scene", args->scene, "scene JSON file")->required();
  cmd->add_option("-o,--output", args->output, ".rlt file to write")->required();
  cmd->add_option("--seed", args->seed, "random seed of the gather rays");
  cmd->add_flag("!--no-progress", args->progress, "no progress bars");
  cmd->callback([args, &action] {
    action = [args] {
      PrecomputeOptions options;
      options.seed = args->seed;
      options.progress = args->progress;
      run_precompute(read_json_file(args->scene), args->scene, args->output, options);
      return 0;
    };
  });
}

}  // namespace relight

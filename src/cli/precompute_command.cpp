// `relight precompute SCENE.json -o SCENE.rlt`: the expensive step, once per static
// scene; prints a summary of rays, rates, time per phase and bytes stored. Under an MPI launcher
// (`mpirun -n N relight precompute …`) the ranks share the work and rank 0 writes the same file one
// process would (engine/ranks.h).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <sched.h>
#include <unistd.h>

#include <tbb/global_control.h>
#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/oriented_scene.h"
#include "cli/precompute_run.h"
#include "common/input_error.h"
#include "common/memory.h"
#include "engine/mpi_ranks.h"
#include "engine/transfer_blocks.h"
#include "math/sh.h"
#include "scene/scene_loader.h"
#include "sources/objects/object_sections.h"
#include "sources/precompute.h"
#include "sources/transfer_file.h"

namespace relight {

namespace {

struct PrecomputeArgs {
  std::string scene, output;
  std::uint64_t seed = 1;
  bool progress = true;
  std::optional<double> memory_limit_mb;
};

// `text` as a positive, finite number of megabytes; nullopt when it is not one.
std::optional<double> megabytes_in(const std::string& text) {
  char* end = nullptr;
  const double mb = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(mb > 0) || !std::isfinite(mb)) {
    return std::nullopt;
  }
  return mb;
}

std::string megabytes_expected(const std::string& text) {
  return "expected a positive number of megabytes, got '" + text + "'";
}

// RELIGHT_MEMORY_LIMIT, when set: megabytes a precompute process (each rank) may use; anything
// but a positive number is an input error (exit 2).
std::optional<double> memory_limit_from_environment() {
  const char* text = std::getenv("RELIGHT_MEMORY_LIMIT");
  if (text == nullptr) return std::nullopt;
  const std::optional<double> mb = megabytes_in(text);
  if (!mb) throw InputError("RELIGHT_MEMORY_LIMIT: " + megabytes_expected(text));
  return mb;
}

// The memory this process may use, and where the figure comes from: the machine's available
// memory, a rank's share of it when `ranks_here` ranks share the machine, or less where
// --memory-limit or RELIGHT_MEMORY_LIMIT (megabytes a process) says so.
void set_memory_limit(std::optional<double> limit_mb, int ranks_here, PrecomputeOptions& options) {
  if (const std::optional<std::uint64_t> available = available_memory_bytes()) {
    options.memory_bytes = *available / static_cast<unsigned>(std::max(ranks_here, 1));
    options.memory_source =
        "this machine's MemAvailable + SwapFree, or its cgroup's limit" +
        (ranks_here > 1 ? ", shared by its " + std::to_string(ranks_here) + " ranks"
                        : std::string());
  }
  const auto lower = [&](std::optional<double> mb, const std::string& source) {
    if (!mb) return;
    const auto bytes = static_cast<std::uint64_t>(*mb * 1e6);
    if (!options.memory_bytes || bytes < *options.memory_bytes) {
      options.memory_bytes = bytes;
      options.memory_source = source;
    }
  };
  lower(memory_limit_from_environment(), "RELIGHT_MEMORY_LIMIT");
  lower(limit_mb, "--memory-limit");
}

// Refuses an unwritable destination before the long computation, not after it.
void check_output_folder(const std::filesystem::path& output) {
  const std::filesystem::path folder =
      output.has_parent_path() ? output.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(folder) || ::access(folder.c_str(), W_OK) != 0) {
    fail_input(output.string(),
               "cannot write: folder " + folder.string() + " does not exist or is not writable");
  }
}

// A phase as the summary prints it: its wall time (the slowest rank's), its rays over all
// ranks, and over the ranks the least and most time in its own work and in exchanges (waiting
// for the others included).
struct PhaseLine {
  std::string name;
  double seconds = 0;
  std::uint64_t rays = 0;
  double work_min = 0, work_max = 0, exchange_min = 0, exchange_max = 0;
  std::uint64_t bytes_max = 0;  // received by a rank
};

// Collective: every rank's phases (the same names in the same order on every rank).
std::vector<PhaseLine> phase_lines(const std::vector<PhaseTiming>& phases, RankExchange* ranks) {
  std::vector<PhaseLine> out;
  for (const PhaseTiming& t : phases) {
    const std::array<double, 3> mine{t.seconds, t.exchange_seconds,
                                     static_cast<double>(t.exchange_bytes)};
    const std::vector<std::array<double, 3>> all =
        ranks != nullptr ? all_gather_values(*ranks, mine) : std::vector{mine};
    PhaseLine line{t.name, 0, t.rays, 1e300, 0, 1e300, 0, 0};
    for (const auto& [seconds, exchange, bytes] : all) {
      line.bytes_max = std::max(line.bytes_max, static_cast<std::uint64_t>(bytes));
      line.seconds = std::max(line.seconds, seconds);
      line.work_min = std::min(line.work_min, seconds - exchange);
      line.work_max = std::max(line.work_max, seconds - exchange);
      line.exchange_min = std::min(line.exchange_min, exchange);
      line.exchange_max = std::max(line.exchange_max, exchange);
    }
    out.push_back(line);
  }
  return out;
}

// Collective: over the ranks, the least and most share of their time spent in exchanges, and
// the most bytes a rank received.
struct ExchangeSummary {
  double least_share = 1, most_share = 0;
  std::uint64_t most_bytes = 0;
};

ExchangeSummary exchange_summary(const std::vector<PhaseTiming>& phases, RankExchange& ranks) {
  double seconds = 0, exchange = 0;
  for (const PhaseTiming& t : phases) {
    seconds += t.seconds;
    exchange += t.exchange_seconds;
  }
  const std::array<double, 2> mine{exchange / std::max(seconds, 1e-9),
                                   static_cast<double>(ranks.exchange_bytes())};
  ExchangeSummary out;
  for (const auto& [share, bytes] : all_gather_values(ranks, mine)) {
    out.least_share = std::min(out.least_share, share);
    out.most_share = std::max(out.most_share, share);
    out.most_bytes = std::max(out.most_bytes, static_cast<std::uint64_t>(bytes));
  }
  return out;
}

// Precomputes, writes `output` (rank 0 of several) and prints the summary (rank 0).
void precompute_and_write(const Scene& scene, const nlohmann::json& document,
                          const std::filesystem::path& scene_file,
                          const std::filesystem::path& output, const PrecomputeOptions& options) {
  const Precomputed p = precompute_transfer(scene, options);
  const std::vector<PhaseLine> phases = phase_lines(p.phases, options.ranks);
  const int rank = options.ranks != nullptr ? options.ranks->rank() : 0;
  const int ranks = options.ranks != nullptr ? options.ranks->size() : 1;
  const ExchangeSummary exchange =
      ranks > 1 ? exchange_summary(p.phases, *options.ranks) : ExchangeSummary{};
  if (rank != 0) {
    send_transfer_file_sections(p, scene, *options.ranks);
    all_gather_values(*options.ranks, peak_resident_bytes());
    return;
  }
  for (const std::string& w : p.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  const auto write_start = std::chrono::steady_clock::now();
  const std::uint64_t bytes_before = ranks > 1 ? options.ranks->exchange_bytes() : 0;
  write_transfer_file(output, p, scene, document, scene_file, options.ranks);
  const double write_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
  const std::uint64_t write_bytes = ranks > 1 ? options.ranks->exchange_bytes() - bytes_before : 0;
  // Each rank's peak, the file written (rank 0 held a round of every rank's blocks there).
  std::uint64_t least_peak = peak_resident_bytes(), most_peak = least_peak;
  if (ranks > 1) {
    for (const std::uint64_t peak : all_gather_values(*options.ranks, least_peak)) {
      least_peak = std::min(least_peak, peak);
      most_peak = std::max(most_peak, peak);
    }
  }

  std::uint64_t rays = 0;
  double seconds = 0;
  std::printf(
      "precompute %s: %zu vertices, %zu sensors, %zu luminaires, sh_order %d, direct %s, "
      "storage %s\n",
      scene_file.string().c_str(), p.receivers.vertex_count, p.receivers.sensor_count,
      p.luminaires.size(), p.sh_order, p.direct_mode.c_str(), scene.precompute.storage.c_str());
  if (ranks > 1) {
    std::printf(
        "  %d ranks: each phase's time is its slowest rank's; [work: the ranks' least and "
        "most time in the phase's own work, exchange: in exchanges, waiting included, and the most "
        "bytes a rank received]\n",
        ranks);
  }
  for (const PhaseLine& t : phases) {
    rays += t.rays;
    seconds += t.seconds;
    std::printf("  %-18s %8.2f s", t.name.c_str(), t.seconds);
    if (t.rays > 0) {
      std::printf("  %10.3g rays  %6.2f Mrays/s", double(t.rays),
                  t.rays * 1e-6 / std::max(t.seconds, 1e-9));
    }
    if (ranks > 1) {
      std::printf("  [work %.2f–%.2f s, exchange %.2f–%.2f s, %.1f MB]", t.work_min, t.work_max,
                  t.exchange_min, t.exchange_max, t.bytes_max * 1e-6);
    }
    std::printf("\n");
  }
  if (ranks > 1) {
    std::printf(
        "  exchanges between ranks: %.1f–%.1f %% of a rank's time, at most %.1f MB "
        "received by a rank\n",
        100 * exchange.least_share, 100 * exchange.most_share, exchange.most_bytes * 1e-6);
  }
  if (ranks > 1) {
    std::printf(
        "  file: written by rank 0 in %.2f s, receiving %.1f MB of the other ranks' rows as it "
        "wrote\n",
        write_seconds, write_bytes * 1e-6);
    std::printf("  peak resident memory: %.1f–%.1f MB a rank\n", least_peak * 1e-6,
                most_peak * 1e-6);
  } else {
    std::printf("  peak resident memory: %.1f MB\n", most_peak * 1e-6);
  }
  std::printf("  memory estimate: %s%s\n", memory_summary(p.memory).c_str(),
              ranks > 1 ? " a rank" : "");
  std::printf("  bounces: %d (tolerance %g)\n", p.bounces, scene.precompute.tolerance);
  for (const PortalTransfer& t : p.portals) {
    const CubemapEncodingStats& s = t.direct.stats;
    const double n = std::max<double>(1, static_cast<double>(s.receivers));
    std::printf(
        "  portal \"%s\": %.2f m², %.2f m across; direct %d² a face: %.1f B/receiver "
        "(%zu empty, %zu pulse %.1f B avg, %zu runs %.1f B avg, %zu rectangles %.1f B avg, %zu "
        "Haar %.1f B avg; all pulse %.1f, all runs %.1f, all rectangles %.1f, all Haar %.1f "
        "B/receiver), %.0f samples/receiver; indirect l < %d "
        "RGB: %.0f B/receiver\n",
        t.geometry.name.c_str(), t.geometry.area, t.geometry.diameter, t.direct.face_size,
        bytes_per_receiver(s), s.empty, s.pulse,
        s.pulse ? double(s.pulse_bytes) / double(s.pulse) : 0.0, s.runs,
        s.runs ? double(s.runs_bytes) / double(s.runs) : 0.0, s.rectangles,
        s.rectangles ? double(s.rectangles_bytes) / double(s.rectangles) : 0.0, s.haar,
        s.haar ? double(s.haar_bytes) / double(s.haar) : 0.0, double(s.all_pulse_bytes) / n,
        double(s.all_runs_bytes) / n, double(s.all_rectangles_bytes) / n,
        double(s.all_haar_bytes) / n, double(t.direct.samples) / n, p.portal_sh_order,
        // The whole section's bytes: on several ranks, rank 0 holds its own blocks only.
        double(block_count(p.receivers.size()) *
               static_cast<std::size_t>(sh_count(p.portal_sh_order)) * 3 * kBlock *
               (t.indirect.f16.empty() ? 4 : 2)) /
            double(std::max<std::size_t>(1, p.receivers.size())));
  }
  if (!p.cuts.empty()) {
    // The cuts' sizes: height encoded as stored, and with 2-byte node indices.
    const HeightCutsView svc = p.cuts.self_visibility.view();
    const double receivers = static_cast<double>(std::max<std::size_t>(1, p.receivers.size()));
    std::printf(
        "  self-visibility cuts: %zu directions, %.3g nodes (%.0f a receiver), %.1f kB (%.1f "
        "bytes a receiver); index encoded %.1f kB (%.1f %%)\n",
        p.cuts.directions.size(), double(svc.node_count()), double(svc.node_count()) / receivers,
        double(svc.bytes()) / 1e3, double(svc.bytes()) / receivers,
        double(index_encoded_bytes(svc)) / 1e3,
        100.0 * double(svc.bytes()) / double(index_encoded_bytes(svc)));
    // Each object's visibility cut field and its vertices' cuts of itself.
    const HeightCutsView fields = p.cuts.field_cuts.view();
    const HeightCutsView own = p.cuts.object_self_visibility.view();
    std::uint64_t height = svc.bytes(), index = index_encoded_bytes(svc), vertex = 0;
    for (std::size_t o = 0; o < p.cuts.fields.size(); ++o) {
      const std::uint64_t first = p.cuts.field_first[o], last = p.cuts.field_first[o + 1];
      const std::uint64_t nodes = fields.first[last] - fields.first[first];
      const std::uint64_t bytes = (nodes + 1) / 2 + (nodes + 7) / 8 + 8 * (last - first);
      const std::uint64_t indexed = (nodes * 17 + 7) / 8 + 8 * (last - first);
      const std::uint64_t v0 = vertex, v1 = vertex + p.objects[o].positions.size();
      const std::uint64_t own_nodes = own.first[v1] - own.first[v0];
      const std::uint64_t own_bytes = (own_nodes + 1) / 2 + (own_nodes + 7) / 8 + 8 * (v1 - v0);
      const std::uint64_t own_indexed = (own_nodes * 17 + 7) / 8 + 8 * (v1 - v0);
      vertex = v1;
      height += bytes + own_bytes;
      index += indexed + own_indexed;
      std::printf(
          "  cuts of \"%s\": field %llu samples, %.3g nodes, %.1f kB (index encoded %.1f kB); "
          "its %llu vertices' own cuts %.1f kB (%.1f bytes a vertex)\n",
          p.objects[o].name.c_str(), static_cast<unsigned long long>(last - first), double(nodes),
          double(bytes) / 1e3, double(indexed) / 1e3, static_cast<unsigned long long>(v1 - v0),
          double(own_bytes) / 1e3, double(own_bytes) / double(std::max<std::uint64_t>(1, v1 - v0)));
    }
    std::printf("  all cuts: %.1f MB height encoded, %.1f MB index encoded (%.1f %%)\n",
                double(height) / 1e6, double(index) / 1e6, 100.0 * double(height) / double(index));
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

}  // namespace

void run_precompute(const nlohmann::json& document, const std::filesystem::path& scene_file,
                    const std::filesystem::path& output, const PrecomputeOptions& options) {
  check_output_folder(output);
  PrecomputeOptions checked = options;
  if (!checked.memory_bytes) set_memory_limit(std::nullopt, 1, checked);
  precompute_and_write(oriented_scene(scene_from_json(document, scene_file)), document, scene_file,
                       output, checked);
}

namespace {

// `mpirun -n N relight precompute`. What can fail on some ranks and not others before the ranks
// exchange anything (the scene read, the output folder checked on rank 0, which writes, each rank's
// share of memory) is agreed (engine/ranks.h agree_on_failure): on a failure rank 0 reports the
// first failing rank's error once and every rank exits 2. A failure after that (out of memory, a
// rank's internal error) ends every rank through MPI_Abort, since the others may be waiting in an
// exchange; only rank 0 writes, so no partial file is left at the output path.
int run_precompute_on_ranks(const PrecomputeArgs& args, PrecomputeOptions options) {
  MpiRanks mpi;
  // The ranks on one machine share its cores (RELIGHT_THREADS, when set, caps it further).
  const tbb::global_control threads(
      tbb::global_control::max_allowed_parallelism,
      std::max<std::size_t>(
          1, std::thread::hardware_concurrency() / static_cast<unsigned>(mpi.ranks_here())));
  options.ranks = &mpi;
  options.progress = options.progress && mpi.rank() == 0;
  // Open MPI binds each of one or two ranks to a core by default: one rank a machine would then
  // leave the machine's other cores idle.
  cpu_set_t cpus;
  const unsigned share =
      std::max(1u, std::thread::hardware_concurrency() / static_cast<unsigned>(mpi.ranks_here()));
  if (mpi.rank() == 0 && ::sched_getaffinity(0, sizeof cpus, &cpus) == 0 &&
      static_cast<unsigned>(CPU_COUNT(&cpus)) < share) {
    std::fprintf(stderr,
                 "warning: rank 0 may run on %d of the %u cores its machine has for each of its "
                 "%d ranks (the launcher bound it); mpirun --bind-to none lets the ranks use "
                 "them all\n",
                 CPU_COUNT(&cpus), share, mpi.ranks_here());
  }
  std::string failure;
  nlohmann::json document;
  std::optional<Scene> scene;
  try {
    if (mpi.rank() == 0) check_output_folder(args.output);
    document = read_json_file(args.scene);
    scene.emplace(oriented_scene(scene_from_json(document, args.scene), mpi.rank() == 0));
  } catch (const InputError& e) {
    failure = e.what();
  }
  try {
    set_memory_limit(args.memory_limit_mb, mpi.ranks_here(), options);
  } catch (const InputError& e) {
    if (failure.empty()) failure = e.what();
  }
  try {
    agree_on_failure(mpi, failure);
    precompute_and_write(*scene, document, args.scene, args.output, options);
  } catch (const AgreedInputError& e) {
    // Every rank knows it and none waits for another: rank 0 reports it, all end with 2.
    if (mpi.rank() == 0) std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    const bool input = dynamic_cast<const InputError*>(&e) != nullptr;
    std::fprintf(stderr, "error: rank %d of %d: %s%s\n", mpi.rank(), mpi.size(),
                 input ? "" : "internal: ", e.what());
    std::fflush(stderr);
    mpi.abort(input ? 2 : 1);
  }
  return 0;
}

}  // namespace

void add_precompute_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<PrecomputeArgs>();
  CLI::App* cmd = app.add_subcommand("precompute", "Precompute radiance transfer into a .rlt file");
  cmd->add_option("scene", args->scene, "scene JSON file")->required();
  cmd->add_option("-o,--output", args->output, ".rlt file to write")->required();
  cmd->add_option("--seed", args->seed, "random seed of the gather rays");
  cmd->add_flag("!--no-progress", args->progress, "no progress bars");
  cmd->add_option("--memory-limit", args->memory_limit_mb,
                  "megabytes this process (each rank) may use; less than the available memory "
                  "refuses a scene predicted to need more (also RELIGHT_MEMORY_LIMIT)")
      ->check(CLI::Validator(
          [](const std::string& text) {
            return megabytes_in(text) ? std::string() : megabytes_expected(text);
          },
          "MB"));
  cmd->callback([args, &action] {
    action = [args] {
      PrecomputeOptions options;
      options.seed = args->seed;
      options.progress = args->progress;
      if (launched_by_mpi()) return run_precompute_on_ranks(*args, options);
      set_memory_limit(args->memory_limit_mb, 1, options);
      run_precompute(read_json_file(args->scene), args->scene, args->output, options);
      return 0;
    };
  });
}

}  // namespace relight

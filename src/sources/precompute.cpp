#include "sources/precompute.h"

#include <array>
#include <chrono>

#include "common/input_error.h"
#include "common/memory.h"
#include "engine/gather_operator.h"
#include "engine/transfer_blocks.h"
#include "sources/objects/object_mesh.h"
#include "sources/precompute_memory.h"
#include "trace/traced_scene.h"

namespace relight {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::uint32_t> triangle_portals(const Scene& scene, const PreparedMesh& mesh) {
  const std::vector<int> portal_of_material = scene.portal_of_material();
  std::vector<std::uint32_t> out;
  out.reserve(mesh.triangle_material.size());
  for (std::uint32_t m : mesh.triangle_material) {
    const int p = portal_of_material.at(m);
    std::uint32_t code = 0;  // opaque
    if (p >= 0) {
      code = static_cast<std::uint32_t>(p + 1);
    } else if (scene.materials[m].portal) {
      code = kGlassOutsidePortals;
    }
    out.push_back(code);
  }
  return out;
}

}  // namespace

PrecomputePrediction predict_precompute(const Scene& scene, const PreparedMesh& mesh,
                                        const Receivers& receivers,
                                        std::span<const Vec3> ray_points,
                                        std::span<const ObjectMesh> objects,
                                        const TracedScene& traced, std::uint64_t seed, int ranks) {
  const std::uint64_t resident = resident_bytes();
  PrecomputePrediction out;
  out.gather = sample_gather_entries(receivers, mesh, traced, scene.precompute.gather_rays,
                                     scene.precompute.sensor_gather_rays, seed);
  if (scene.environment) {
    out.cuts = predict_cuts(scene.precompute.cuts, receivers, ray_points, traced, objects);
  }
  out.memory =
      predict_precompute_memory(scene, receivers, out.gather, out.cuts.held(), resident, ranks);
  return out;
}

Precomputed precompute_transfer(const Scene& scene, const PrecomputeOptions& options) {
  Precomputed out;
  out.sh_order = scene.precompute.sh_order;
  out.direct_mode = scene.precompute.direct;
  out.portal_sh_order = scene.precompute.portal_sh_order;

  const auto start = std::chrono::steady_clock::now();
  out.mesh = prepare_scene_mesh(scene);
  out.receivers = make_receivers(scene, out.mesh);
  out.triangle_portal = triangle_portals(scene, out.mesh);
  // The ranks' blocks of receivers (engine/ranks.h), the transfer's blocks.
  const RankShares ranks = options.ranks != nullptr
                               ? dealt_blocks(*options.ranks, out.receivers.size(), kBlock)
                               : single_process_shares(out.receivers.size(), kBlock);
  const TracedScene traced = build_traced_scene(out.mesh, scene.materials);
  const std::vector<Vec3> ray_points = receiver_ray_points(out.receivers, out.mesh);
  out.phases.push_back({"prepare", seconds_since(start), 0});
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto object_start = std::chrono::steady_clock::now();
    out.objects.push_back(prepare_object(scene, scene.objects[i]));
    out.object_seconds.push_back(seconds_since(object_start));
  }
  const auto predict_start = std::chrono::steady_clock::now();
  const PrecomputePrediction predicted = predict_precompute(
      scene, out.mesh, out.receivers, ray_points, out.objects, traced, options.seed, ranks.size());
  out.memory = predicted.memory;
  out.phases.push_back({"memory prediction", seconds_since(predict_start), 0});
  if (options.memory_bytes) {
    agree_on_failure(*ranks.exchange, memory_refusal(scene, out.memory, *options.memory_bytes,
                                                     options.memory_source));
  }

  const ExchangeMeter meter(&ranks);
  GatherOperator gather =
      build_gather_operator(out.receivers, out.mesh, traced, scene.precompute.gather_rays,
                            scene.precompute.sensor_gather_rays, options.seed, options.progress,
                            &ranks, &predicted.gather);
  out.phases.push_back({"gather operator", gather.seconds, gather.rays});
  meter.take(out.phases.back());

  // The source kinds, in the order their columns are registered and their direct phases run.
  LuminairePrecompute luminaires(scene, options.opening_samples);
  PortalPrecompute portals(scene, options.seed);
  NearfieldPrecompute nearfield(scene, options.seed);
  const std::array<SourcePrecompute*, 3> sources{&luminaires, &portals, &nearfield};

  const SourceContext context{out.receivers, ray_points,       out.mesh,
                              traced,        options.progress, &ranks};
  BounceSettings bounce;
  bounce.tolerance = scene.precompute.tolerance;
  bounce.max_bounces = scene.precompute.max_bounces;
  SourcesResult result = precompute_sources(context, gather, bounce, sources);
  out.bounces = result.bounces;
  for (PhaseTiming& t : result.phases) out.phases.push_back(std::move(t));
  out.luminaires = std::move(luminaires.transfers);
  out.portals = std::move(portals.transfers);
  out.warnings = std::move(portals.warnings);
  out.nearfield = std::move(nearfield.result);
  if (scene.environment) {
    out.cuts = precompute_cuts(scene.precompute.cuts, out.receivers, ray_points, traced,
                               out.objects, options.progress, &predicted.cuts);
    out.phases.push_back({"visibility cuts", out.cuts.seconds, out.cuts.rays});
  }
  // Kept for what the run time bounces itself: moved and added luminaires, the sun, emitters,
  // movable objects and live material edits (engine/albedo_edit.h); unless the scene leaves it
  // out to save its bytes.
  if (scene.precompute.runtime_bounce) out.gather.swap(gather.matrix);
  return out;
}

}  // namespace relight

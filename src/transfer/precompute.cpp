#include "transfer/precompute.h"

#include <chrono>
#include <cmath>

#include "light/luminaire_frame.h"
#include "math/sh.h"
#include "trace/traced_scene.h"
#include "transfer/bounce_solver.h"
#include "transfer/gather_operator.h"
#include "transfer/nearfield_transfer.h"
#include "transfer/sh_direct.h"
#include "transfer/transfer_blocks.h"

namespace relight {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Precomputed precompute_transfer(const Scene& scene, const PrecomputeOptions& options) {
  using Clock = std::chrono::steady_clock;
  Precomputed out;
  out.sh_order = scene.precompute.sh_order;
  out.direct_mode = scene.precompute.direct;

  auto start = Clock::now();
  out.mesh = prepare_scene_mesh(scene);
  out.receivers = make_receivers(scene, out.mesh);
  const std::vector<int> portal_of_material = scene.portal_of_material();
  for (std::uint32_t m : out.mesh.triangle_material) {
    const int p = portal_of_material.at(m);
    std::uint32_t code = 0;  // opaque
    if (p >= 0) {
      code = static_cast<std::uint32_t>(p + 1);
    } else if (scene.materials[m].portal) {
      code = kGlassOutsidePortals;
    }
    out.triangle_portal.push_back(code);
  }
  const TracedScene traced = build_traced_scene(out.mesh, scene.materials);
  out.phases.push_back({"prepare", seconds_since(start), 0});

  const GatherOperator gather =
      build_gather_operator(out.receivers, out.mesh, traced, scene.precompute.gather_rays,
                            scene.precompute.sensor_gather_rays, options.seed, options.progress);
  out.phases.push_back({"gather operator", gather.seconds, gather.rays});

  // Direct geometry per luminaire, and its SH-basis direct columns side by side.
  start = Clock::now();
  std::uint64_t direct_rays = 0;
  const std::vector<Vec3> ray_points = receiver_ray_points(out.receivers, out.mesh);
  const int k = sh_count(out.sh_order);
  const auto n = static_cast<Eigen::Index>(out.receivers.size());
  const auto luminaire_count = static_cast<Eigen::Index>(scene.luminaires.size());
  out.portal_sh_order = scene.precompute.portal_sh_order;
  const int kp = sh_count(out.portal_sh_order);
  const auto portal_count = static_cast<Eigen::Index>(scene.portals.size());
  Eigen::MatrixXf direct_columns(n, k * luminaire_count + kp * portal_count);
  for (Eigen::Index j = 0; j < luminaire_count; ++j) {
    const Luminaire& l = scene.luminaires[static_cast<std::size_t>(j)];
    const PlacedLuminaire placed = place_luminaire(l);
    const std::vector<Vec3> offsets =
        opening_sample_offsets(luminaire_opening(l, placed.distribution.opening()),
                               {placed.aim, placed.c0, placed.c90}, options.opening_samples);
    LuminaireTransfer t;
    t.direct = compute_direct_geometry(out.receivers, ray_points, traced, l.position, offsets,
                                       options.progress);
    direct_rays += t.direct.rays;
    direct_columns.middleCols(j * k, k) = sh_basis_direct(t.direct, out.sh_order);
    if (out.direct_mode == "sh") {
      const Eigen::MatrixXf column_block = direct_columns.middleCols(j * k, k);
      t.direct_sh_blocks = pack_blocks({&column_block});
    }
    out.luminaires.push_back(std::move(t));
  }
  out.phases.push_back({"direct visibility", seconds_since(start), direct_rays});

  // Per portal: the direct cubemaps, and the SH-basis direct columns after the luminaires'.
  start = Clock::now();
  std::uint64_t portal_rays = 0;
  if (portal_count > 0) {
    const std::vector<std::uint8_t> glass = [&] {
      std::vector<std::uint8_t> skip = portal_vertices(out.mesh, scene.materials);
      skip.resize(out.receivers.size(), 0);  // sensors always receive
      return skip;
    }();
    PortalDirectSettings settings;
    settings.face_size = scene.precompute.portal_face_size;
    settings.sh_order = out.portal_sh_order;
    settings.samples_per_cell = scene.precompute.portal_samples_per_cell;
    std::vector<PortalGeometry> geometry = portal_geometry(scene, out.mesh);
    out.warnings = shell_size_warnings(scene, geometry);
    for (Eigen::Index p = 0; p < portal_count; ++p) {
      PortalTransfer t;
      t.geometry = std::move(geometry[static_cast<std::size_t>(p)]);
      settings.seed = options.seed + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(p + 1);
      t.direct = compute_portal_direct(out.receivers, ray_points, glass, out.mesh, traced,
                                       t.geometry, settings, options.progress);
      portal_rays += t.direct.rays;
      direct_columns.middleCols(k * luminaire_count + p * kp, kp) = t.direct.sh_columns;
      t.direct.sh_columns.resize(0, 0);
      out.portals.push_back(std::move(t));
    }
    out.phases.push_back({"portal direct", seconds_since(start), portal_rays});
  }

  // Near-field emitters: shadowed SH transfer per receiver, its columns bounced too when asked.
  const int kn = scene.emitters.empty() ? 0 : sh_count(scene.precompute.nearfield_sh_order);
  const Eigen::Index nearfield_first = direct_columns.cols();
  if (kn > 0) {
    start = Clock::now();
    NearfieldTransferSettings settings;
    settings.order = scene.precompute.nearfield_sh_order;
    settings.sqrt_directions =
        static_cast<int>(std::lround(std::sqrt(scene.precompute.nearfield_directions)));
    settings.seed = options.seed;
    const Bounds b = scene.bounds();
    settings.max_distance = scene.precompute.nearfield_shadow_distance > 0
                                ? scene.precompute.nearfield_shadow_distance
                                : 0.25 * length(b.max - b.min);
    out.nearfield_sh_order = settings.order;
    out.nearfield_transfer =
        nearfield_transfer(traced.opaque, ray_points, out.receivers.normals, settings);
    if (scene.precompute.nearfield_interreflection) {
      direct_columns.conservativeResize(Eigen::NoChange, nearfield_first + kn);
      for (Eigen::Index r = 0; r < n; ++r) {
        for (Eigen::Index c = 0; c < kn; ++c) {
          direct_columns(r, nearfield_first + c) =
              out.nearfield_transfer[static_cast<std::size_t>(r * kn + c)];
        }
      }
    }
    const std::uint64_t rays =
        out.receivers.size() * static_cast<std::uint64_t>(scene.precompute.nearfield_directions);
    out.phases.push_back({"near-field transfer", seconds_since(start), rays});
  }

  BounceSettings bounce;
  bounce.tolerance = scene.precompute.tolerance;
  bounce.max_bounces = scene.precompute.max_bounces;
  const BounceResult result =
      solve_bounces(gather, out.receivers, direct_columns, bounce, options.progress);
  out.bounces = result.bounces;
  out.phases.push_back({"bounces", result.seconds, 0});

  start = Clock::now();
  for (Eigen::Index j = 0; j < luminaire_count; ++j) {
    const Eigen::MatrixXf r = result.indirect[0].middleCols(j * k, k);
    const Eigen::MatrixXf g = result.indirect[1].middleCols(j * k, k);
    const Eigen::MatrixXf b = result.indirect[2].middleCols(j * k, k);
    out.luminaires[static_cast<std::size_t>(j)].indirect_blocks = pack_blocks({&r, &g, &b});
  }
  for (Eigen::Index p = 0; p < portal_count; ++p) {
    const Eigen::Index first = k * luminaire_count + p * kp;
    const Eigen::MatrixXf r = result.indirect[0].middleCols(first, kp);
    const Eigen::MatrixXf g = result.indirect[1].middleCols(first, kp);
    const Eigen::MatrixXf b = result.indirect[2].middleCols(first, kp);
    out.portals[static_cast<std::size_t>(p)].indirect_blocks = pack_blocks({&r, &g, &b});
  }
  if (kn > 0 && scene.precompute.nearfield_interreflection) {
    out.nearfield_interreflected.resize(static_cast<std::size_t>(n * kn * 3));
    for (Eigen::Index r = 0; r < n; ++r) {
      for (Eigen::Index c = 0; c < kn; ++c) {
        for (int ch = 0; ch < 3; ++ch) {
          out.nearfield_interreflected[static_cast<std::size_t>((r * kn + c) * 3 + ch)] =
              result.indirect[static_cast<std::size_t>(ch)](r, nearfield_first + c);
        }
      }
    }
  }
  out.phases.push_back({"pack", seconds_since(start), 0});
  return out;
}

}  // namespace relight

// The direct component of light through a portal (Yue et al.
// 2009 §4.1.2 and Figure 5(a)): per receiver, a cubemap of the light arriving from the
// portal's shell through the portal, geometry only — cell c holds
//   t_c = ∫_{ω ∈ c, through the portal, unoccluded} cos θ_r dω,
// so that the irradiance from a shell of radiance L is E = Σ_c t_c · L_c. Per receiver: the
// cells the portal covers, in front of the receiver, are found without rays from the
// portal's convex pieces (sources/portals/portal_outline.h, math/cubemap_polygon.h); then each
// such cell is integrated over its own directions — about `samples_per_cell` jittered
// sub-cells (k×k), each direction checked to pass through the portal (it must meet this
// portal first: the pieces' cones, and a ray into the portals' BVH where other portals could
// come first) and traced once against opaque geometry to infinity, which checks the
// visibility of the portal and the paper's *backward occlusion* (the continuation past the
// portal must reach the shell) together. Cells whose four corners all see the portal are
// inside the window's outline and need no more; cells the outline crosses are traced on a
// 4× finer grid. So a cell inside the window carries no sampling noise from the outline — the
// sun, which the shell puts in one cell, lights neighbouring receivers alike — and only the
// outline is noisy, on the finer scale. Each cubemap is stored in the smallest of pulse, pulse
// runs or per-face Haar, 8-bit (sources/portals/cubemap_encoding.h).
//
// The same directions give the response to each SH basis Y_k (l < sh_order) as direct
// irradiance columns for the bounce solver (the indirect component, §4.1.1): where the
// paper shoots a photon map per basis, here every basis shares these rays and the gather
// operator's.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/ranks.h"
#include "engine/receivers.h"
#include "sources/portals/cubemap_encoding.h"
#include "sources/portals/portal_geometry.h"
#include "trace/traced_scene.h"

namespace relight {

struct PortalDirectSettings {
  int face_size = 32;
  int sh_order = 6;
  int samples_per_cell = 4;  // directions per cell inside the window (k×k, k = round(√·))
  // Up to this many edges over its convex pieces, whether a direction passes through the portal
  // is answered by the pieces' cones (sources/portals/portal_outline.h), past it by a ray into
  // the portals' BVH (a curved window cut into many triangles); both give the same records.
  std::size_t max_cone_edges = 64;
  std::uint64_t seed = 1;
};

struct PortalDirect {
  int face_size = 32;
  // One cubemap record per receiver, back to back; receivers + 1 offsets: record r is
  // [offsets[r], offsets[r+1]). On one of several ranks, its own receivers' only, in the order
  // of its local rows (engine/ranks.h).
  std::vector<std::uint8_t> records;
  std::vector<std::uint64_t> offsets;
  CubemapEncodingStats stats;
  // receivers × sh_count(order): direct E for radiance Y_k; on one of several ranks, filled in
  // for its own receivers only.
  Eigen::MatrixXf sh_columns;
  Vec3 outward;  // unit: the side of the portal the light comes from
  std::uint64_t rays = 0;
  std::uint64_t samples = 0;
};

// `skip[r]` != 0 leaves receiver r empty (glass vertices). `ray_points` are
// receiver_ray_points(receivers, mesh). With several `ranks` (engine/ranks.h; shares on
// multiples of kBlock; collective), this process traces its share and keeps its records and SH
// columns; `stats`, `outward`, `rays` and `samples` are every rank's, as one process finds them.
PortalDirect compute_portal_direct(const Receivers& receivers, const std::vector<Vec3>& ray_points,
                                   const std::vector<std::uint8_t>& skip, const PreparedMesh& mesh,
                                   const TracedScene& traced, const PortalGeometry& portal,
                                   const PortalDirectSettings& settings, bool progress,
                                   const RankShares* ranks = nullptr);

}  // namespace relight

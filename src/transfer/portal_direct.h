// The direct component of light through a portal (the interior-scene paper, Yue et al.
// 2009, §4.1.2 and Figure 5(a)): per receiver, a cubemap of the light arriving from the
// portal's shell through the portal, geometry only — cell c holds
//   t_c = ∫_{ω ∈ c, through the portal, unoccluded} cos θ_r dω,
// so that the irradiance from a shell of radiance L is E = Σ_c t_c · L_c. Estimated from
// points y sampled on the portal: the triangle by its solid angle seen from the receiver,
// the point uniformly on it (scrambled (0,2)-sequence), each weighted by cos θ_r / pdf_ω with
// pdf_ω = P(triangle)·d²/(A·cos θ_y). One ray from the receiver through y to infinity checks
// both the visibility of y and the paper's *backward occlusion* (the continuation past the
// portal must reach the shell). The number of points follows the portal's solid angle —
// about `samples_per_cell` per cubemap cell it covers — so a near window gets as many per
// cell as a far one. Each cubemap is stored in the smaller of pulse or per-face Haar, 8-bit
// (transfer/cubemap_encoding.h).
//
// The same samples give the response to each SH basis Y_k (l < sh_order) as direct
// irradiance columns for the bounce solver (the indirect component, §4.1.1): where the
// paper shoots a photon map per basis, here every basis shares these rays and the gather
// operator's.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "trace/traced_scene.h"
#include "transfer/cubemap_encoding.h"
#include "transfer/portal_geometry.h"
#include "transfer/receivers.h"

namespace relight {

struct PortalDirectSettings {
  int face_size = 32;
  int sh_order = 6;
  int samples_per_cell = 4;
  int min_samples = 64;
  int max_samples = 4096;
  std::uint64_t seed = 1;
};

struct PortalDirect {
  int face_size = 32;
  std::vector<std::uint8_t> records;   // one cubemap record per receiver, back to back
  std::vector<std::uint64_t> offsets;  // receivers + 1: record r is [offsets[r], offsets[r+1])
  CubemapEncodingStats stats;
  Eigen::MatrixXf sh_columns;  // receivers × sh_count(order): direct E for radiance Y_k
  Vec3 outward;                // unit: the side of the portal the light comes from
  std::uint64_t rays = 0;
  std::uint64_t samples = 0;
};

// `skip[r]` != 0 leaves receiver r empty (glass vertices). `ray_points` are
// receiver_ray_points(receivers, mesh).
PortalDirect compute_portal_direct(const Receivers& receivers, const std::vector<Vec3>& ray_points,
                                   const std::vector<std::uint8_t>& skip, const PreparedMesh& mesh,
                                   const TracedScene& traced, const PortalGeometry& portal,
                                   const PortalDirectSettings& settings, bool progress);

}  // namespace relight

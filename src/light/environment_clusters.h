// An environment clustered on the visibility cuts' direction tree (Iwasaki et al., Cyberworlds, §V,
// Eq. 3: the capture paper, papers/003): per node k of the tree the first moment of the
// environment's radiance over the directions its leaves stand for,
//     M_k = ∫_{cell(k)} L(ω) ω dω   (per linear Rec.709 channel; cd/m² · sr),
// where a leaf's cell is its Voronoi cell on the sphere (the directions nearer to it than to
// any other leaf: math/point_grid.h nearest) and an inner node's the union of its leaves'.
// With a binary visibility cut at a point of normal n (sources/environment/self_visibility.h),
//     E = Σ_{k visible} n · M_k
// is the irradiance there, exact on every node whose leaves' visibility agrees and whose
// directions lie above the surface: the cosine is integrated with the light, not sampled at
// the leaves. The paper's Eq. 3 clusters V·cos instead and multiplies by ∫ L; the renderers
// multiply n · M_k by the BRDF toward the eye at the node's mean direction.
//
// Quadrature, so that Σ_leaves M_k = ∫ L ω dω:
//  * uniform: L · (4π/N) · ω_i per leaf i (the leaves' cells are equal to within the
//    repulsion's spread).
//  * map: every texel split into k × k parts of exact solid angle, k the least for which a
//    part is at most half the leaves' spacing across, each part's L·Ω·ω given to the leaf
//    nearest its centre. A texel finer than that is given whole.
//  * sky: the dome and ground on an equirectangular grid at the leaves' spacing (midpoint
//    values, exact solid angles; the dome is smooth: half the spacing read the same to 4e-5
//    and took 3 times as long), the sun disc's ∫L dω spread equally over 64
//    directions of its area (light/sky_model.h sun_disc_spiral), each given to its nearest leaf
//    with its own direction: a sun near a cell's edge shares its light between two leaves.
// With `traced` (light/compact_sources.h), its sources are left out: a sky's sun disc, a map's
// texels that a source carries; the renderers trace them.
// Pinned by tests/light/environment_clusters_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "light/compact_sources.h"
#include "light/environment.h"
#include "math/direction_tree.h"
#include "math/placement.h"
#include "math/point_grid.h"
#include "math/rgb.h"

namespace relight {

// ∫ L ω dω per channel, in single precision (the run time sums it per receiver).
struct RgbMoment {
  float r[3] = {0, 0, 0}, g[3] = {0, 0, 0}, b[3] = {0, 0, 0};

  RgbMoment& operator+=(const RgbMoment& o) {
    for (int i = 0; i < 3; ++i) {
      r[i] += o.r[i];
      g[i] += o.g[i];
      b[i] += o.b[i];
    }
    return *this;
  }
  // += weight · o: a cut's nodes summed first and turned to irradiance once (n · Σ v M is
  // Σ v n · M, with one dot product a receiver instead of one a node).
  RgbMoment& add(const RgbMoment& o, float weight) {
    for (int i = 0; i < 3; ++i) {
      r[i] += weight * o.r[i];
      g[i] += weight * o.g[i];
      b[i] += weight * o.b[i];
    }
    return *this;
  }
  // n · M per channel: the irradiance the moment's directions give a surface of normal n.
  Rgb irradiance(Vec3 n) const {
    return {n.x * r[0] + n.y * r[1] + n.z * r[2], n.x * g[0] + n.y * g[1] + n.z * g[2],
            n.x * b[0] + n.y * b[1] + n.z * b[2]};
  }
};

// The direction of a node's light, where a BRDF toward the eye is evaluated for it (the
// capture paper's Eq. 3): its luminance moment's (math/rgb.h's weights), or `fallback` (the
// node's axis) where that moment is 0.
Vec3 moment_direction(const RgbMoment& m, Vec3 fallback);
// moment_direction of every node k ≥ 1 of `tree` (index 0 unused), with its axis as fallback.
std::vector<Vec3> moment_directions(std::span<const RgbMoment> moments, const DirectionTree& tree);

// The nearest-leaf lookup of a tree: a PointGrid over its leaves at cells of twice their
// spacing.
PointGrid leaf_grid(const DirectionTree& tree);

// What places the parts of an environment's equirectangular grid in a frame: a map's or a
// sky's, the grid (texels across, down, parts a texel's side), the frame's turn and the map's.
struct EnvironmentGridKey {
  bool map = false;
  int width = 0, height = 0, parts = 0;
  double frame_rotate_deg = 0, map_rotate_deg = 0;
  bool operator==(const EnvironmentGridKey&) const = default;
};
// Every part of such a grid with its map direction, its direction in the frame and the nearest
// leaf to that: what environment_moments finds once for a grid and frame and keeps, so that a
// sky or a map of the same size changing frame to frame finds only the radiance again.
struct EnvironmentGridParts {
  EnvironmentGridKey key;
  const PointGrid* leaves = nullptr;  // the lookup the leaves came from
  std::vector<Vec3> map_direction, direction;
  std::vector<std::uint32_t> leaf;
};

// M_k per heap node k (index 0 unused, leaves N … 2N − 1), in the frame of an object turned by
// `frame_rotate_deg` about the vertical (math/placement.h): a world direction ω counts at the
// object's direction the turn takes back to it, so that cuts stored in the object's frame meet
// the environment as the object now sees it. `kept` (optional): the grid's parts as the last
// call in this frame found them, used when they are the same and made again when not (grids of
// up to 2^18 parts; larger ones are placed part by part each call).
std::vector<RgbMoment> environment_moments(const Environment& env, const DirectionTree& tree,
                                           const PointGrid& leaves, double frame_rotate_deg = 0,
                                           const CompactSources* traced = nullptr,
                                           EnvironmentGridParts* kept = nullptr);

}  // namespace relight

// Visibility cut fields (VCF; Iwasaki et al., Cyberworlds, §V.A.1, Fig. 4: the capture paper,
// papers/003): the occlusion a movable object casts, precomputed around it so that its shadows
// under an environment follow it with no tracing. Sample points lie on `sphere_count` concentric
// spheres about the object's bounding sphere (centre c, radius R) as the scene places it, radii
// from inner_radius · R to outer_radius · R in geometric steps, each sphere with 6 · P² points
// (P = sphere_points) at the cell centres of a cube map's faces projected onto it (math/cubemap.h
// layout). At each point x_s the object's binary occlusion V(x_s, ω) — 0 where the ray from x_s
// toward ω meets the object — over the direction tree's leaves is stored as a cut that merges nodes
// only where their leaves agree (threshold 0), so its shadow edges stay as sharp as the leaves;
// only the directions within the cone of the bounding sphere from x_s are traced (the rest see past
// the object). The fields are in the object's own frame: a receiver x is looked up at the
// placement's inverse of x, its directions turned back by the placement's rotation.
//
// Between samples a receiver's cut is interpolated (math/cut_merge.h) from the eight samples
// around it: the two spheres bracketing its distance (linear in log radius) times the 2 × 2
// cell centres of its face around its direction (bilinear in the face's coordinates, clamped at
// the face's edges). Beyond the outer sphere the object casts nothing (the paper's cut-off);
// within the inner one the inner sphere's samples stand in. Pinned by
// tests/sources/environment/visibility_field_test.cpp.
#pragma once

#include <array>
#include <cstdint>

#include "engine/runtime_scene.h"
#include "math/cut_encoding.h"
#include "math/direction_tree.h"
#include "scene/scene.h"
#include "sources/objects/object_mesh.h"

namespace relight {

struct VisibilityFieldLayout {
  BoundingSphere bounds;  // the object's, as the scene places it
  int spheres = 32, points = 32;
  double inner = 1.2, outer = 10;  // in radii

  std::size_t sample_count() const {
    return static_cast<std::size_t>(spheres) * 6 * static_cast<std::size_t>(points) * points;
  }
  double sphere_radius(int i) const;
  // Sample s: (sphere · 6 + face) · P² + row · P + column.
  Vec3 sample_point(std::size_t s) const;
  // The samples around `p` (the object's frame) and their weights, summing to 1; 0 samples
  // beyond the outer sphere, else 8 (some may repeat at a face's edge).
  int samples_around(Vec3 p, std::array<std::uint32_t, 8>& ids,
                     std::array<float, 8>& weights) const;
};

// The samples of every field the settings make (VisibilityFieldLayout::sample_count).
std::size_t field_sample_count(const CutsSettings& settings);

struct VisibilityField {
  VisibilityFieldLayout layout;
  std::uint64_t rays = 0;
  double seconds = 0;
};

// The mean nodes of a cut of the field, from `samples` samples spread evenly over its spheres and
// traced as precompute_visibility_field traces them (for the precompute's memory prediction).
double sample_field_nodes(const ObjectMesh& object, const DirectionTree& tree,
                          const CutsSettings& settings, std::size_t samples);

// The field of `object` over `tree`'s directions with the settings' spheres: one cut per
// sample appended to `cuts` (a store of the same tree).
VisibilityField precompute_visibility_field(const ObjectMesh& object, const DirectionTree& tree,
                                            const CutsSettings& settings, HeightCuts& cuts);

}  // namespace relight

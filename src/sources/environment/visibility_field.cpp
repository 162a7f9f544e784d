#include "sources/environment/visibility_field.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/cubemap.h"
#include "math/cut_encoding.h"
#include "math/direction_cut.h"
#include "math/vec3.h"

namespace relight {

namespace {

// A cone of directions: unit axis, half-angle in radians.
struct Cone {
  Vec3 axis;
  double half_angle;
};

// A cut node found by the descent, with its first leaf (the descent finds them out of order).
struct Emitted {
  std::uint64_t first_leaf;
  std::uint32_t node;
  float value;
};

// The object's occlusion seen from x as a cut at threshold 0, built from the root down: a node
// whose cone misses the bounding cone is visible whole without a ray; a leaf is traced; a node
// whose children agree is one node of the cut, else its children are.
struct OcclusionDescent {
  const DirectionTree& tree;
  const std::vector<double>& spread;  // per node: its cone's half-angle
  const RayTracer& object;
  Vec3 x;
  Cone cone;
  std::vector<Emitted>& out;
  std::uint64_t& rays;

  // The node's value when its leaves agree (then nothing is emitted for it), else −1 (its
  // parts are emitted).
  float visit(std::size_t k) const {
    const std::size_t n = tree.leaf_count();
    const double between = std::acos(std::clamp(dot(tree.axis[k], cone.axis), -1.0, 1.0));
    if (between > spread[k] + cone.half_angle + 1e-9) return 1.0f;
    if (k >= n) {
      ++rays;
      return object.occluded({x, tree.leaves[k - n]}) ? 0.0f : 1.0f;
    }
    const float left = visit(2 * k), right = visit(2 * k + 1);
    if (left >= 0 && left == right) return left;
    emit(2 * k, left);
    emit(2 * k + 1, right);
    return -1.0f;
  }
  void emit(std::size_t k, float v) const {
    if (v < 0) return;
    const int h = tree.height(k);
    out.push_back({(std::uint64_t{k} << h) - tree.leaf_count(), static_cast<std::uint32_t>(k), v});
  }
};

}  // namespace

double VisibilityFieldLayout::sphere_radius(int i) const {
  if (spheres <= 1) return inner * bounds.radius;
  return bounds.radius * inner * std::pow(outer / inner, static_cast<double>(i) / (spheres - 1));
}

Vec3 VisibilityFieldLayout::sample_point(std::size_t s) const {
  const std::size_t per_face = static_cast<std::size_t>(points) * points;
  const auto sphere = static_cast<int>(s / (6 * per_face));
  const CubemapTexel texel = cubemap_texel_from_index(points, s % (6 * per_face));
  return bounds.centre + cubemap_texel_direction(points, texel) * sphere_radius(sphere);
}

int VisibilityFieldLayout::samples_around(Vec3 p, std::array<std::uint32_t, 8>& ids,
                                          std::array<float, 8>& weights) const {
  const Vec3 d = p - bounds.centre;
  const double r = length(d);
  const double r_outer = sphere_radius(spheres - 1);
  if (!(r <= r_outer)) return 0;
  // The bracketing spheres, linear in log radius; inside the inner sphere, the inner one.
  int s0 = 0, s1 = 0;
  double f = 0;
  const double r_inner = sphere_radius(0);
  if (spheres > 1 && r > r_inner) {
    const double x = std::log(r / r_inner) / std::log(outer / inner) * (spheres - 1);
    s0 = std::min(static_cast<int>(x), spheres - 2);
    s1 = s0 + 1;
    f = std::clamp(x - s0, 0.0, 1.0);
  }
  // The 2 × 2 cell centres of the face around the direction, clamped at the face's edges.
  const CubemapCoord c = cubemap_coord(r > 0 ? d : Vec3{0, 1, 0});
  const double x = c.s * points - 0.5, y = c.t * points - 0.5;
  const int i0 = std::clamp(static_cast<int>(std::floor(x)), 0, points - 1);
  const int j0 = std::clamp(static_cast<int>(std::floor(y)), 0, points - 1);
  const int i1 = std::min(i0 + 1, points - 1), j1 = std::min(j0 + 1, points - 1);
  const double fx = std::clamp(x - i0, 0.0, 1.0), fy = std::clamp(y - j0, 0.0, 1.0);
  const std::size_t per_sphere = 6 * static_cast<std::size_t>(points) * points;
  int k = 0;
  for (int a = 0; a < 2; ++a) {
    const int sphere = a == 0 ? s0 : s1;
    const double ws = a == 0 ? 1 - f : f;
    for (int b = 0; b < 4; ++b) {
      const int i = (b & 1) != 0 ? i1 : i0, j = (b & 2) != 0 ? j1 : j0;
      const double w = ws * ((b & 1) != 0 ? fx : 1 - fx) * ((b & 2) != 0 ? fy : 1 - fy);
      ids[static_cast<std::size_t>(k)] =
          static_cast<std::uint32_t>(static_cast<std::size_t>(sphere) * per_sphere +
                                     cubemap_texel_index(points, {c.face, i, j}));
      weights[static_cast<std::size_t>(k)] = static_cast<float>(w);
      ++k;
    }
  }
  return 8;
}

namespace {

// What every sample of one field's cuts needs: its layout, the object's tracer and each tree
// node's cone.
struct FieldTracing {
  VisibilityFieldLayout layout;
  const DirectionTree& tree;
  RayTracer tracer;
  std::vector<double> spread;

  FieldTracing(const ObjectMesh& object, const DirectionTree& tree, const CutsSettings& settings)
      : tree(tree),
        tracer(object.positions, object.triangles, sequential_ids(object.triangles.size())),
        spread(tree.cos_half_angle.size()) {
    layout.bounds = sphere_around(object.positions);
    layout.spheres = settings.sphere_count;
    layout.points = settings.sphere_points;
    layout.inner = settings.inner_radius;
    layout.outer = settings.outer_radius;
    for (std::size_t k = 0; k < spread.size(); ++k) {
      spread[k] = std::acos(std::clamp(tree.cos_half_angle[k], -1.0, 1.0));
    }
  }

  // Sample s's cut; `nodes` is scratch, `rays` counts the rays traced.
  void cut(std::size_t s, std::vector<Emitted>& nodes, DirectionCut& cut,
           std::uint64_t& rays) const {
    const Vec3 x = layout.sample_point(s);
    const BoundingSphere& b = layout.bounds;
    const Vec3 to_centre = b.centre - x;
    const double d = length(to_centre);
    // Only directions within the bounding sphere's cone can meet the object.
    const Cone cone{d > 0 ? to_centre / d : Vec3{0, 1, 0},
                    d > b.radius ? std::asin(b.radius / d) : kPi};
    nodes.clear();
    const OcclusionDescent descent{tree, spread, tracer, x, cone, nodes, rays};
    if (const float v = descent.visit(1); v >= 0) nodes.push_back({0, 1, v});
    std::sort(nodes.begin(), nodes.end(),
              [](const Emitted& l, const Emitted& r) { return l.first_leaf < r.first_leaf; });
    cut.nodes.clear();
    cut.values.clear();
    cut.nodes.reserve(nodes.size());
    cut.values.reserve(nodes.size());
    for (const Emitted& e : nodes) {
      cut.nodes.push_back(e.node);
      cut.values.push_back(e.value);
    }
  }
};

}  // namespace

std::size_t field_sample_count(const CutsSettings& settings) {
  VisibilityFieldLayout layout;
  layout.spheres = settings.sphere_count;
  layout.points = settings.sphere_points;
  return layout.sample_count();
}

double sample_field_nodes(const ObjectMesh& object, const DirectionTree& tree,
                          const CutsSettings& settings, std::size_t samples) {
  const FieldTracing field(object, tree, settings);
  const std::size_t count = field.layout.sample_count();
  samples = std::min(samples, count);
  if (samples == 0) return 0;
  std::atomic<std::uint64_t> nodes{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples), [&](const auto& range) {
    std::vector<Emitted> scratch;
    DirectionCut cut;
    std::uint64_t rays = 0, here = 0;
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      field.cut(i * count / samples, scratch, cut, rays);
      here += cut.nodes.size();
    }
    nodes += here;
  });
  return static_cast<double>(nodes.load()) / static_cast<double>(samples);
}

VisibilityField precompute_visibility_field(const ObjectMesh& object, const DirectionTree& tree,
                                            const CutsSettings& settings, HeightCuts& store) {
  const auto start = std::chrono::steady_clock::now();
  const FieldTracing field(object, tree, settings);
  VisibilityField out;
  out.layout = field.layout;
  std::atomic<std::uint64_t> rays{0};
  append_cuts_in_windows(store, field.layout.sample_count(), [&](std::size_t first, auto cuts) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cuts.size(), 8), [&](const auto& range) {
      std::uint64_t traced = 0;
      std::vector<Emitted> nodes;
      for (std::size_t i = range.begin(); i < range.end(); ++i) {
        field.cut(first + i, nodes, cuts[i], traced);
      }
      rays += traced;
    });
  });
  out.rays = rays;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace relight

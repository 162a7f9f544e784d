#include "sources/environment/cuts_precompute.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>

#include <tbb/parallel_for.h>

#include "common/progress.h"
#include "sources/environment/self_visibility.h"

namespace relight {

namespace {

// Appends to `store` the self-visibility cut of every point (rays from `ray_points`, pushed
// off the surface along `normals`) against `occluders`; returns the rays traced.
std::uint64_t append_self_visibility(HeightCuts& store, const Occluders& occluders,
                                     const DirectionTree& tree, std::span<const Vec3> ray_points,
                                     std::span<const Vec3> normals, double threshold,
                                     Progress* bar) {
  std::atomic<std::uint64_t> rays{0};
  append_cuts_in_windows(store, ray_points.size(), [&](std::size_t first, auto cuts) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cuts.size(), 16), [&](const auto& range) {
      std::uint64_t here = 0;
      for (std::size_t i = range.begin(); i < range.end(); ++i) {
        const std::size_t r = first + i;
        const Vec3 n = normals[r];
        cuts[i] = self_visibility_cut(occluders, tree, offset_from_surface(ray_points[r], n), n,
                                      threshold, here);
      }
      rays += here;
      if (bar != nullptr) bar->advance(range.size());
    });
  });
  return rays;
}

// Cuts a prediction samples of each store: enough for their mean within a few per cent.
constexpr std::size_t kSampledCuts = 256;

// The mean nodes of the self-visibility cuts of `kSampledCuts` of the points, evenly spaced.
double sampled_self_visibility_nodes(const Occluders& occluders, const DirectionTree& tree,
                                     std::span<const Vec3> ray_points,
                                     std::span<const Vec3> normals, double threshold) {
  const std::size_t samples = std::min(kSampledCuts, ray_points.size());
  if (samples == 0) return 0;
  std::atomic<std::uint64_t> nodes{0};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples), [&](const auto& range) {
    std::uint64_t rays = 0, here = 0;
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const std::size_t r = i * ray_points.size() / samples;
      here += self_visibility_cut(occluders, tree, offset_from_surface(ray_points[r], normals[r]),
                                  normals[r], threshold, rays)
                  .nodes.size();
    }
    nodes += here;
  });
  return static_cast<double>(nodes.load()) / static_cast<double>(samples);
}

DirectionTree cuts_tree(const CutsSettings& settings) {
  return build_direction_tree(repulsed_directions(static_cast<std::size_t>(settings.directions)));
}

}  // namespace

CutsPrediction predict_cuts(const CutsSettings& settings, const Receivers& receivers,
                            std::span<const Vec3> ray_points, const TracedScene& traced,
                            std::span<const ObjectMesh> objects) {
  CutsPrediction out;
  out.tree = cuts_tree(settings);
  const DirectionTree& tree = out.tree;
  const auto total = [](double mean, std::size_t cuts) {
    return static_cast<std::uint64_t>(std::ceil(mean * static_cast<double>(cuts)));
  };
  out.receiver_nodes =
      total(sampled_self_visibility_nodes(Occluders(traced.opaque, &traced.portals), tree,
                                          ray_points, receivers.normals, settings.threshold),
            ray_points.size());
  out.bytes = height_cuts_bytes(ray_points.size(), out.receiver_nodes);
  // A window's cuts unencoded: a node index and a value each, and two vectors a cut.
  const auto window = [&out](std::uint64_t nodes, std::size_t cuts) {
    if (cuts == 0) return;
    const std::uint64_t held = std::min<std::uint64_t>(cuts, kCutWindow);
    out.window = std::max(out.window, held * (nodes / cuts * 8 + 2 * sizeof(std::vector<float>)));
  };
  window(out.receiver_nodes, ray_points.size());
  for (const ObjectMesh& object : objects) {
    const std::size_t samples = field_sample_count(settings);
    out.field_nodes.push_back(
        total(sample_field_nodes(object, tree, settings, kSampledCuts), samples));
    const RayTracer own(object.positions, object.triangles,
                        sequential_ids(object.triangles.size()));
    out.object_vertex_nodes.push_back(
        total(sampled_self_visibility_nodes(own, tree, object.ray_points, object.normals,
                                            settings.threshold),
              object.ray_points.size()));
    out.bytes += height_cuts_bytes(samples, out.field_nodes.back()) +
                 height_cuts_bytes(object.ray_points.size(), out.object_vertex_nodes.back());
    window(out.field_nodes.back(), samples);
    window(out.object_vertex_nodes.back(), object.ray_points.size());
  }
  return out;
}

CutsTransfer precompute_cuts(const CutsSettings& settings, const Receivers& receivers,
                             std::span<const Vec3> ray_points, const TracedScene& traced,
                             std::span<const ObjectMesh> objects, bool progress,
                             const CutsPrediction* predicted) {
  const auto start = std::chrono::steady_clock::now();
  CutsTransfer out;
  const DirectionTree built = predicted != nullptr ? DirectionTree{} : cuts_tree(settings);
  const DirectionTree& tree = predicted != nullptr ? predicted->tree : built;
  out.directions = tree.leaves;
  out.threshold = settings.threshold;
  out.self_visibility = make_height_cuts(tree);
  // Sized by the prediction plus a margin: a store that grows past its capacity holds its old
  // and its new arrays at once.
  const auto reserve = [](HeightCuts& store, std::size_t cuts, std::uint64_t nodes) {
    reserve_height_cuts(store, cuts, nodes + nodes / 16);
  };
  if (predicted != nullptr)
    reserve(out.self_visibility, ray_points.size(), predicted->receiver_nodes);

  Progress bar("self-visibility cuts", receivers.size(), progress);
  out.rays = append_self_visibility(out.self_visibility, Occluders(traced.opaque, &traced.portals),
                                    tree, ray_points, receivers.normals, settings.threshold, &bar);
  bar.finish();
  // The objects: each one's field, and its vertices' cuts of itself.
  out.object_self_visibility = make_height_cuts(tree);
  out.field_cuts = make_height_cuts(tree);
  out.field_first.push_back(0);
  if (predicted != nullptr) {
    if (predicted->field_nodes.size() != objects.size() ||
        predicted->object_vertex_nodes.size() != objects.size()) {
      throw std::invalid_argument("visibility cuts: a prediction of other objects");
    }
    std::uint64_t fields = 0, own = 0, field_cuts = 0, own_cuts = 0;
    for (std::size_t o = 0; o < objects.size(); ++o) {
      fields += predicted->field_nodes[o];
      own += predicted->object_vertex_nodes[o];
      own_cuts += objects[o].ray_points.size();
      field_cuts += field_sample_count(settings);
    }
    reserve(out.field_cuts, field_cuts, fields);
    reserve(out.object_self_visibility, own_cuts, own);
  }
  for (const ObjectMesh& object : objects) {
    const VisibilityField field =
        precompute_visibility_field(object, tree, settings, out.field_cuts);
    out.fields.push_back(field.layout);
    out.field_first.push_back(out.field_cuts.view().cut_count());
    out.rays += field.rays;
    const RayTracer own(object.positions, object.triangles,
                        sequential_ids(object.triangles.size()));
    out.rays += append_self_visibility(out.object_self_visibility, own, tree, object.ray_points,
                                       object.normals, settings.threshold, nullptr);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace relight

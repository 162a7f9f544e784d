#include "sources/environment/environment_objects.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>

#include <immintrin.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "common/cpu_features.h"
#include "light/disc_visibility.h"
#include "sources/environment/compact_light.h"

namespace relight {

namespace {

constexpr int kMaxFactors = 15;  // math/cut_merge.h multiply_cuts
constexpr std::size_t kNoObject = ~std::size_t{0};

// A turn in whole micro-degrees, in [0, 360°): the key of the caches.
std::int64_t turn_key(double deg) {
  double d = std::fmod(deg, 360.0);
  if (d < 0) d += 360.0;
  auto key = static_cast<std::int64_t>(std::llround(d * 1e6));
  return key == 360'000'000 ? 0 : key;
}

// The point x (world) in the frame of an object placed by p about `pivot`: the placement undone.
Vec3 to_object_frame(Vec3 x, Vec3 pivot, const Placement& p) {
  return pivot + placed_direction(x - p.translate - pivot, {{0, 0, 0}, -p.rotate_deg});
}

// The heap index of a cut's node i (N leaves), starting at `leaf`, which moves past it.
std::size_t node_at(const std::uint8_t* height, std::size_t i, std::uint32_t leaves,
                    std::uint64_t& leaf) {
  const auto node = static_cast<std::size_t>((leaves + leaf) >> height[i]);
  leaf += std::uint64_t{1} << height[i];
  return node;
}

// The same for nodes i … i + 3.
std::array<std::size_t, 4> four_nodes(const std::uint8_t* height, std::size_t i,
                                      std::uint32_t leaves, std::uint64_t& leaf) {
  std::array<std::size_t, 4> node{};
  for (std::size_t j = 0; j < 4; ++j) node[j] = node_at(height, i + j, leaves, leaf);
  return node;
}

// Σ value · n · M over a cut's nodes.
Rgb cut_irradiance_portable(const ValueCut& cut, std::uint32_t leaves, std::span<const RgbMoment> m,
                            Vec3 n) {
  // No test of v > 0: a fifth of a product's nodes are 0 in no order a branch predicts, and
  // values are never negative. Four sums, a node in four to each, so that a node's adds need not
  // wait for the last node's; four beat two (measured: docs/decisions.md).
  RgbMoment s0, s1, s2, s3;
  const std::size_t count = cut.size();
  const std::uint8_t* height = cut.height.data();
  const float* value = cut.value.data();
  std::uint64_t leaf = 0;
  std::size_t i = 0;
  for (; i + 3 < count; i += 4) {
    const std::array<std::size_t, 4> k = four_nodes(height, i, leaves, leaf);
    s0.add(m[k[0]], value[i]);
    s1.add(m[k[1]], value[i + 1]);
    s2.add(m[k[2]], value[i + 2]);
    s3.add(m[k[3]], value[i + 3]);
  }
  for (; i < count; ++i) s0.add(m[node_at(height, i, leaves, leaf)], value[i]);
  s0 += s1;
  s2 += s3;
  s0 += s2;
  return s0.irradiance(n);
}

// The same with AVX2 and FMA: a moment's first eight floats in one register times the node's
// value, its ninth apart (measured: docs/decisions.md).
static_assert(sizeof(RgbMoment) == 9 * sizeof(float));
__attribute__((target("avx2,fma"))) Rgb cut_irradiance_avx2(const ValueCut& cut,
                                                            std::uint32_t leaves,
                                                            std::span<const RgbMoment> m, Vec3 n) {
  const float* base = m.data()->r;
  __m256 a0 = _mm256_setzero_ps(), a1 = a0, a2 = a0, a3 = a0;
  float c0 = 0, c1 = 0, c2 = 0, c3 = 0;
  const std::size_t count = cut.size();
  const std::uint8_t* height = cut.height.data();
  const float* value = cut.value.data();
  std::uint64_t leaf = 0;
  std::size_t i = 0;
  for (; i + 3 < count; i += 4) {
    const std::array<std::size_t, 4> k = four_nodes(height, i, leaves, leaf);
    const float* p0 = base + 9 * k[0];
    const float* p1 = base + 9 * k[1];
    const float* p2 = base + 9 * k[2];
    const float* p3 = base + 9 * k[3];
    a0 = _mm256_fmadd_ps(_mm256_loadu_ps(p0), _mm256_set1_ps(value[i]), a0);
    a1 = _mm256_fmadd_ps(_mm256_loadu_ps(p1), _mm256_set1_ps(value[i + 1]), a1);
    a2 = _mm256_fmadd_ps(_mm256_loadu_ps(p2), _mm256_set1_ps(value[i + 2]), a2);
    a3 = _mm256_fmadd_ps(_mm256_loadu_ps(p3), _mm256_set1_ps(value[i + 3]), a3);
    c0 += p0[8] * value[i];
    c1 += p1[8] * value[i + 1];
    c2 += p2[8] * value[i + 2];
    c3 += p3[8] * value[i + 3];
  }
  for (; i < count; ++i) {
    const float* p = base + 9 * node_at(height, i, leaves, leaf);
    a0 = _mm256_fmadd_ps(_mm256_loadu_ps(p), _mm256_set1_ps(value[i]), a0);
    c0 += p[8] * value[i];
  }
  alignas(32) float sum[8];
  _mm256_store_ps(sum, _mm256_add_ps(_mm256_add_ps(a0, a1), _mm256_add_ps(a2, a3)));
  RgbMoment total;
  std::copy_n(sum, 3, total.r);
  std::copy_n(sum + 3, 3, total.g);
  total.b[0] = sum[6];
  total.b[1] = sum[7];
  total.b[2] = (c0 + c1) + (c2 + c3);
  return total.irradiance(n);
}

Rgb cut_irradiance(const ValueCut& cut, std::uint32_t leaves, std::span<const RgbMoment> m,
                   Vec3 n) {
  static const bool avx2 = has_avx2_fma();
  return avx2 ? cut_irradiance_avx2(cut, leaves, m, n) : cut_irradiance_portable(cut, leaves, m, n);
}

}  // namespace

struct EnvironmentObjects::Scratch {
  std::array<ValueCut, kMaxFactors> factors;
  ValueCut interpolated;
  std::vector<float> leaves;     // a turned field's interpolated cut, leaf by leaf
  std::vector<Vec3> directions;  // the leaves traced in a cone, in leaf order
  std::vector<std::uint8_t> blocked;
  std::vector<std::uint64_t> walk;    // a cone's walk, recorded for its replay
  std::vector<std::uint8_t> open;     // per leaf the walk traces: its ray open
  std::vector<std::uint32_t> traced;  // the leaves whose rays are traced (index into open)
};

EnvironmentObjects::EnvironmentObjects(const CutsTransferView& cuts, const DirectionTree& tree,
                                       const PointGrid& leaves, const RuntimeScene& room,
                                       std::span<const ObjectMesh> meshes)
    : cuts_(cuts), tree_(tree), leaves_(leaves), room_(room), meshes_(meshes) {
  const int log_n = std::bit_width(tree.leaf_count()) - 1;
  coarse_depth_ = std::min(10, log_n);
  static_words_ = ((std::size_t{1} << coarse_depth_) + 63) / 64;
  std::size_t vertices = 0;
  for (const ObjectMesh& m : meshes) vertices += m.positions.size();
  static_bits_.assign(vertices * static_words_, ~std::uint64_t{0});
  room_delta_.assign(3 * room.receivers(), 0.0f);
  object_direct_.assign(3 * vertices, 0.0f);
  cones_.resize(tree.cos_half_angle.size());
  for (std::size_t k = 1; k < cones_.size(); ++k) {
    const double spread = std::acos(std::clamp(tree.cos_half_angle[k], -1.0, 1.0));
    cones_[k] = {tree.axis[k], tree.cos_half_angle[k], spread, std::sin(spread)};
  }
}

const std::vector<std::uint32_t>& EnvironmentObjects::leaf_turn(double relative_deg) const {
  const std::lock_guard lock(turn_mutex_);
  std::unique_ptr<LeafTurn>& slot = turns_[turn_key(relative_deg)];
  if (!slot) {
    slot = std::make_unique<LeafTurn>();
    slot->table.resize(tree_.leaf_count());
    const VerticalTurn turn(relative_deg);
    for (std::size_t i = 0; i < slot->table.size(); ++i) {
      slot->table[i] = leaves_.nearest(turn(tree_.leaves[i]));
    }
  }
  slot->used = true;
  return slot->table;
}

std::span<const RgbMoment> EnvironmentObjects::frame_moments(double frame_deg) {
  const std::int64_t key = turn_key(frame_deg);
  if (key == 0) return world_moments_;
  FrameLight& f = turned_[key];
  if (f.moments.empty()) {
    f.moments = environment_moments(*env_, tree_, leaves_, frame_deg, compact_, &f.parts);
    f.directions = moment_directions(f.moments, tree_);
  }
  return f.moments;
}

template <typename OnNode, typename OnLeaves>
void EnvironmentObjects::walk_cone(Vec3 axis, double half, Vec3 up, const OnNode& on_node,
                                   const OnLeaves& on_leaves) const {
  const std::size_t n_leaves = tree_.leaf_count();
  const double cos_half = std::cos(half), sin_half = std::sin(half);
  // A node's cone holds its leaves' directions, so a node within the cone (the angle between
  // the axes and its spread within `half`) and wholly above the horizon holds only leaves the
  // walk would reach one by one; kept off the test by a margin so that a leaf on the edge is
  // decided by its own test.
  constexpr double kMargin = 1e-9;
  // Top down, left first, so that nodes come out in leaf order.
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 1;
  while (top > 0) {
    const std::uint32_t k = stack[--top];
    const int h = tree_.height(k);
    const std::uint64_t first = (std::uint64_t{k} << h) - n_leaves;
    const NodeCone& c = cones_[k];
    const double along = dot(c.axis, axis), above = dot(c.axis, up);
    // Disjoint when the angle between the axes exceeds the two half-angles together.
    if ((c.spread + half < kPi && along < c.cos_spread * cos_half - c.sin_spread * sin_half) ||
        // Wholly below the receiver's horizon, where its own cut is 0.
        (c.spread < kPi / 2 && above < -c.sin_spread)) {
      on_node(first, h);
    } else if (k >= n_leaves ||
               (c.spread < kPi / 2 && above > c.sin_spread + kMargin &&
                (half >= kPi ||
                 (c.spread <= half &&
                  along > cos_half * c.cos_spread + sin_half * c.sin_spread + kMargin)))) {
      on_leaves(first, std::uint64_t{1} << h);
    } else {
      stack[top++] = 2 * k + 1;
      stack[top++] = 2 * k;
    }
  }
}

template <typename LeafValue>
void EnvironmentObjects::cone_cut(Vec3 axis, double half, Vec3 up, const LeafValue& leaf_value,
                                  ValueCut& out) const {
  out.clear();
  // push_cut_node merges siblings of equal value back.
  walk_cone(
      axis, half, up, [&](std::uint64_t first, int h) { push_cut_node(out, first, h, 1.0f); },
      [&](std::uint64_t first, std::uint64_t count) {
        for (std::uint64_t leaf = first; leaf < first + count; ++leaf) {
          push_cut_node(out, leaf, 0, leaf_value(leaf));
        }
      });
}

bool EnvironmentObjects::field_factor(std::size_t o, Vec3 x, Vec3 n, double frame_deg,
                                      const PlacedObjects& placed, Scratch& s,
                                      ValueCut& out) const {
  const MovablePlacement& p = placements_[o];
  if (!p.visible) return false;
  const VisibilityFieldLayout& layout = cuts_.fields[o];
  const Vec3 pivot = meshes_[o].pivot;
  const Vec3 v = placed_point(layout.bounds.centre, pivot, p) - x;
  const double d = length(v), radius = layout.bounds.radius;
  if (d > layout.sphere_radius(layout.spheres - 1) || dot(n, v) < -radius) return false;
  // The object's bounding cone and the receiver's normal in the receiver's frame.
  const VerticalTurn frame(frame_deg);
  const Vec3 axis = frame.inverse(d > 0 ? v / d : Vec3{0, 1, 0});
  const double half = d > radius ? std::asin(radius / d) : kPi;
  const Vec3 up = frame.inverse(n);
  if (d < layout.sphere_radius(0)) {
    // Within the inner sphere the field has no samples: the object traced, leaf by leaf in its
    // cone above the horizon (a floor beside a box, a chair under a table), from one point in
    // packets of eight; a leaf whose ray misses the object's box is open without a ray (in the
    // showroom's chair drag, 63 % of them).
    const Vec3 origin = offset_from_surface(x, n);
    const Bounds& box = placed.boxes[o];
    constexpr double kBoxMargin = 1e-4;  // m: well past the rays' single precision
    // One walk, recorded (a node open as first · 128 + height, a node's leaves to trace as
    // first · 128 + 64 + height) and replayed once the packets are traced: per leaf to trace,
    // open (1) or blocked (0).
    constexpr std::uint64_t kLeaves = 64;
    s.directions.clear();
    s.walk.clear();
    s.open.clear();
    s.traced.clear();
    walk_cone(
        axis, half, up,
        [&](std::uint64_t first, int h) {
          s.walk.push_back(first << 7 | static_cast<std::uint64_t>(h));
        },
        [&](std::uint64_t first, std::uint64_t count) {
          s.walk.push_back(first << 7 | kLeaves |
                           static_cast<std::uint64_t>(std::countr_zero(count)));
          for (std::uint64_t leaf = first; leaf < first + count; ++leaf) {
            const Vec3 direction = frame(tree_.leaves[leaf]);
            if (ray_meets_box(origin, direction, box, kBoxMargin)) {
              s.traced.push_back(static_cast<std::uint32_t>(s.open.size()));
              s.directions.push_back(direction);
            }
            s.open.push_back(1);
          }
        });
    s.blocked.resize(s.directions.size());
    placed.own[o].occluded_from(origin, s.directions, s.blocked);
    for (std::size_t i = 0; i < s.traced.size(); ++i) {
      if (s.blocked[i] != 0) s.open[s.traced[i]] = 0;
    }
    out.clear();
    const std::uint8_t* open = s.open.data();
    for (const std::uint64_t w : s.walk) {
      const std::uint64_t first = w >> 7;
      const int h = static_cast<int>(w & 63);
      if ((w & kLeaves) == 0) {
        push_cut_node(out, first, h, 1.0f);
        continue;
      }
      // The node's leaves as runs of one value.
      const std::uint64_t count = std::uint64_t{1} << h;
      std::uint64_t run = 0;
      while (run < count) {
        std::uint64_t end = run + 1;
        while (end < count && open[end] == open[run]) ++end;
        push_cut_run(out, first + run, end - run, open[run] != 0 ? 1.0f : 0.0f);
        run = end;
      }
      open += count;
    }
    return true;
  }
  std::array<std::uint32_t, 8> ids{};
  std::array<float, 8> weights{};
  if (layout.samples_around(to_object_frame(x, pivot, p), ids, weights) == 0) return false;
  std::array<WeightedCut, 8> operands;
  for (std::size_t k = 0; k < 8; ++k) {
    operands[k] = {&cuts_.field_cuts, static_cast<std::size_t>(cuts_.field_first[o]) + ids[k],
                   weights[k]};
  }
  const double relative = frame_deg - p.rotate_deg;
  if (turn_key(relative) == 0) {
    interpolate_cuts(operands, out);
    return true;
  }
  // Turned: the field leaf by leaf within the object's bounding cone, in the receiver's frame.
  interpolate_cuts(operands, s.interpolated);
  // Expanded: a cone holds hundreds to thousands of leaves (~800 on average in the showroom's
  // drag), each a random read, against a binary search of the cut's nodes. (Writing only the
  // nodes other than 1 and putting them back after is no faster.)
  s.leaves.resize(tree_.leaf_count());
  expand_cut(s.interpolated, s.leaves);
  const std::vector<std::uint32_t>& turn = leaf_turn(relative);
  cone_cut(
      axis, half, up, [&](std::size_t leaf) { return s.leaves[turn[leaf]]; }, out);
  return true;
}

std::size_t EnvironmentObjects::factors_at(Vec3 x, Vec3 n, double frame, std::size_t skip,
                                           bool moving, const PlacedObjects& placed, Scratch& s,
                                           std::size_t first) const {
  std::size_t count = first;
  for (std::size_t o = 0; o < meshes_.size() && count < kMaxFactors; ++o) {
    if (o == skip || (moving_[o] != 0) != moving) continue;
    if (field_factor(o, x, n, frame, placed, s, s.factors[count])) ++count;
  }
  return count - first;
}

void EnvironmentObjects::object_cut(std::size_t q, std::size_t a, const PlacedObjects& placed,
                                    bool rebuild, Scratch& s) {
  const Vec3 x = placed.ray_points[q], n = placed.normals[q];
  const double frame = placements_[a].rotate_deg;
  std::array<const ValueCut*, kMaxFactors + 1> factors{};
  for (std::size_t k = 0; k < kMaxFactors; ++k) factors[k + 1] = &s.factors[k];
  if (rebuild) {
    // The rest: its cut of itself, the static scene from its coarse view, the objects that
    // stay where they are.
    const std::size_t coarse = std::size_t{1} << coarse_depth_;
    const int coarse_height = std::bit_width(tree_.leaf_count()) - 1 - coarse_depth_;
    ValueCut& scene = s.factors[0];
    scene.clear();
    const std::uint64_t* bits = &static_bits_[q * static_words_];
    for (std::size_t i = 0; i < coarse; ++i) {
      const float v = ((bits[i / 64] >> (i % 64)) & 1) != 0 ? 1.0f : 0.0f;
      push_cut_node(scene, std::uint64_t{i} << coarse_height, coarse_height, v);
    }
    const std::size_t count = 1 + factors_at(x, n, frame, a, false, placed, s, 1);
    multiply_cuts(cuts_.object_self_visibility, q, std::span(factors.data() + 1, count),
                  object_rests_[q]);
  }
  // Times the moving objects' fields.
  const std::size_t count = factors_at(x, n, frame, a, true, placed, s, 0);
  if (count == 0) {
    object_products_[q] = object_rests_[q];
    return;
  }
  factors[0] = &object_rests_[q];
  multiply_cuts(std::span(factors.data(), count + 1), object_products_[q]);
}

const ValueCut* EnvironmentObjects::room_visibility(std::size_t r) const {
  if (env_ == nullptr || r >= room_products_.size() || room_products_[r].size() == 0) {
    return nullptr;
  }
  return &room_products_[r];
}

const ValueCut* EnvironmentObjects::object_visibility(std::size_t q,
                                                      const PlacedObjects& placed) const {
  const std::size_t a = placed.object_of_vertex(q);
  if (env_ == nullptr || a >= placements_.size() || !placements_[a].visible ||
      q >= object_products_.size()) {
    return nullptr;
  }
  return &object_products_[q];
}

const EnvironmentObjects::FrameLight* EnvironmentObjects::object_frame(std::size_t a) const {
  const auto it = turned_.find(turn_key(placements_.at(a).rotate_deg));
  // An entry the environment's change emptied and no update has made again: none.
  return it != turned_.end() && !it->second.moments.empty() ? &it->second : nullptr;
}

std::span<const RgbMoment> EnvironmentObjects::object_moments(std::size_t a) const {
  const FrameLight* f = object_frame(a);
  return f != nullptr ? std::span<const RgbMoment>(f->moments) : world_moments_;
}

std::span<const Vec3> EnvironmentObjects::object_light_directions(std::size_t a) const {
  const FrameLight* f = object_frame(a);
  return f != nullptr ? std::span<const Vec3>(f->directions) : world_directions_;
}

void EnvironmentObjects::trace_static(std::size_t q, const PlacedObjects& placed,
                                      double frame_deg) {
  const Vec3 n = placed.normals[q];
  const Vec3 origin = offset_from_surface(placed.ray_points[q], n);
  const std::size_t first = std::size_t{1} << coarse_depth_;
  std::uint64_t* bits = &static_bits_[q * static_words_];
  std::fill_n(bits, static_words_, ~std::uint64_t{0});
  const VerticalTurn turn(frame_deg);
  for (std::size_t i = 0; i < first; ++i) {
    const std::size_t k = first + i;
    const Vec3 dir = turn(cones_[k].axis);
    // Below the surface: the vertex's own cut is 0 there.
    if (dot(dir, n) < -cones_[k].sin_spread) continue;
    if (room_.occluders().occluded({origin, dir})) bits[i / 64] &= ~(std::uint64_t{1} << (i % 64));
  }
}

bool EnvironmentObjects::update(const Environment* env, std::span<const RgbMoment> moments,
                                std::span<const Vec3> directions,
                                std::span<const float> room_direct, const RoomCompact& compact,
                                const PlacedObjects& placed,
                                std::span<const MovablePlacement> placements, bool env_changed) {
  const auto start = std::chrono::steady_clock::now();
  const bool moved_any = !valid_ || !std::equal(placements.begin(), placements.end(),
                                                placements_.begin(), placements_.end());
  if (!moved_any && !env_changed && env == env_) return false;
  env_ = env;
  world_moments_ = moments;
  world_directions_ = directions;
  compact_ = &compact.sources;
  if (env_changed) {
    for (auto& [turn, light] : turned_) light.moments.clear();
  }
  const std::size_t objects = meshes_.size();
  tbb::enumerable_thread_specific<Scratch> scratch;
  if (moved_any) {
    std::vector<std::uint8_t> moved(objects, 0);
    for (std::size_t a = 0; a < objects; ++a) {
      moved[a] = !valid_ || !(placements_[a] == placements[a]) ? 1 : 0;
    }
    // The static scene as each moved object's vertices see it.
    for (std::size_t a = 0; a < objects; ++a) {
      if (!moved[a] || !placements[a].visible) continue;
      const std::size_t first = placed.first_vertex[a], last = placed.first_vertex[a + 1];
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 16), [&](const auto& r) {
        for (std::size_t q = r.begin(); q < r.end(); ++q) {
          trace_static(q, placed, placements[a].rotate_deg);
        }
      });
    }
    placements_.assign(placements.begin(), placements.end());
    // The same objects moving again (a drag): the products of the others are kept.
    const bool rebuild = !rests_valid_ || moved != moving_;
    moving_ = moved;
    rests_valid_ = true;
    // Every receiver's visibility with the objects as placed: the room's where an object
    // reaches it (none: its own cut alone), every visible object's vertices.
    room_products_.resize(room_.receivers());
    room_rests_.resize(room_.receivers());
    room_reached_.resize(room_.receivers(), 1);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, room_.receivers(), 64),
                      [&](const auto& r) {
                        Scratch& s = scratch.local();
                        for (std::size_t i = r.begin(); i < r.end(); ++i)
                          room_product(i, placed, rebuild, s);
                      });
    object_products_.resize(placed.vertex_count());
    object_rests_.resize(placed.vertex_count());
    for (std::size_t a = 0; a < objects; ++a) {
      const std::size_t first = placed.first_vertex[a], last = placed.first_vertex[a + 1];
      if (!placements[a].visible) {
        for (std::size_t q = first; q < last; ++q) object_products_[q].clear();
        continue;
      }
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 16), [&](const auto& r) {
        Scratch& s = scratch.local();
        for (std::size_t q = r.begin(); q < r.end(); ++q) {
          object_cut(q, a, placed, rebuild || moved[a], s);
        }
      });
    }
    // The leaf tables of turns this placement did not use are dropped (an object turned
    // frame after frame would leave one behind each frame).
    std::erase_if(turns_, [](const auto& entry) { return !entry.second->used; });
    for (auto& [turn, table] : turns_) table->used = false;
  }
  valid_ = true;
  std::fill(room_delta_.begin(), room_delta_.end(), 0.0f);
  std::fill(object_direct_.begin(), object_direct_.end(), 0.0f);
  room_compact_.assign(room_delta_.size(), 0.0f);
  object_compact_.assign(object_direct_.size(), 0.0f);
  if (env == nullptr) {
    seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
  }
  // Every frame's moments before the parallel loops read them; the frames no object stands
  // in are dropped.
  std::vector<std::span<const RgbMoment>> object_moments;
  for (std::size_t a = 0; a < objects; ++a) {
    object_moments.push_back(frame_moments(placements[a].rotate_deg));
  }
  std::erase_if(turned_, [&](const auto& entry) {
    return std::none_of(placements.begin(), placements.end(), [&](const MovablePlacement& p) {
      return turn_key(p.rotate_deg) == entry.first;
    });
  });
  const auto leaves = static_cast<std::uint32_t>(tree_.leaf_count());
  // The room's receivers: what the objects take away.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, room_.receivers(), 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      if (room_products_[i].size() == 0) continue;
      const Rgb e = cut_irradiance(room_products_[i], leaves, world_moments_, room_.normal(i));
      // Against the cuts' part of the room's direct light.
      store_rgb(e - (load_rgb(&room_direct[3 * i]) - load_rgb(&compact.direct[3 * i])),
                &room_delta_[3 * i]);
    }
  });
  // The objects' vertices: all of their direct light, in their own frames.
  for (std::size_t a = 0; a < objects; ++a) {
    if (!placements[a].visible) continue;
    const std::size_t first = placed.first_vertex[a], last = placed.first_vertex[a + 1];
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 64), [&](const auto& r) {
      for (std::size_t q = r.begin(); q < r.end(); ++q) {
        const Rgb e = cut_irradiance(object_products_[q], leaves, object_moments[a],
                                     meshes_[a].normals[q - first]);
        object_direct_[3 * q] = static_cast<float>(e.r);
        object_direct_[3 * q + 1] = static_cast<float>(e.g);
        object_direct_[3 * q + 2] = static_cast<float>(e.b);
      }
    });
  }
  if (!compact.sources.sources.empty()) trace_compact(compact, placed, placements);
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

void EnvironmentObjects::trace_compact(const RoomCompact& compact, const PlacedObjects& placed,
                                       std::span<const MovablePlacement> placements) {
  const std::span<const CompactSource> sources = compact.sources.sources;
  const std::size_t count = sources.size();
  const Occluders occluders(room_.occluders(), &placed.tracer);
  // The room's receivers: where a source's cone meets a placed object, what it hides.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, room_.receivers(), 256), [&](const auto& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      const Vec3 n = room_.normal(i), x = offset_from_surface(room_.ray_point(i), n);
      Rgb delta;
      for (std::size_t k = 0; k < count; ++k) {
        const CompactSource& s = sources[k];
        const double c = dot(n, s.disc.direction);
        const double seen = compact.fraction[i * count + k];
        if (c <= 0 || seen <= 0) continue;
        bool near = false;
        for (std::size_t o = 0; o < placed.object_count() && !near; ++o) {
          near = placed.visible(o) &&
                 disc_may_reach(s.disc, x, placed.bounds[o].centre, placed.bounds[o].radius);
        }
        if (!near) continue;
        delta += s.illuminance * ((compact_fraction(occluders, s, x) - seen) * c);
      }
      store_rgb(delta, &room_compact_[3 * i]);
    }
  });
  // The objects' vertices: all of it.
  for (std::size_t a = 0; a < meshes_.size(); ++a) {
    if (!placements[a].visible) continue;
    const std::size_t first = placed.first_vertex[a], last = placed.first_vertex[a + 1];
    tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, 64), [&](const auto& r) {
      for (std::size_t q = r.begin(); q < r.end(); ++q) {
        const Vec3 n = placed.normals[q], x = offset_from_surface(placed.ray_points[q], n);
        store_rgb(compact_irradiance(occluders, sources, x, n), &object_compact_[3 * q]);
      }
    });
  }
}

void EnvironmentObjects::room_product(std::size_t i, const PlacedObjects& placed, bool rebuild,
                                      Scratch& s) {
  const Vec3 x = room_.ray_point(i), n = room_.normal(i);
  std::array<const ValueCut*, kMaxFactors + 1> factors{};
  for (std::size_t k = 0; k < kMaxFactors; ++k) factors[k + 1] = &s.factors[k];
  if (rebuild) {
    // The rest: the receiver's cut times the objects that stay where they are (none: empty,
    // the stored cut stands for it).
    const std::size_t count = factors_at(x, n, 0, kNoObject, false, placed, s, 0);
    if (count == 0) {
      room_rests_[i].clear();
    } else {
      multiply_cuts(cuts_.self_visibility, i, std::span(factors.data() + 1, count), room_rests_[i]);
    }
  }
  const std::size_t count = factors_at(x, n, 0, kNoObject, true, placed, s, 0);
  const bool reached = count > 0 || room_rests_[i].size() > 0;
  // Reached by no moving object, now or before, and the rest kept: the product stands.
  if (!rebuild && count == 0 && room_reached_[i] == 0) return;
  room_reached_[i] = count > 0 ? 1 : 0;
  if (!reached) {
    room_products_[i].clear();
  } else if (count == 0) {
    room_products_[i] = room_rests_[i];
  } else if (room_rests_[i].size() == 0) {
    multiply_cuts(cuts_.self_visibility, i, std::span(factors.data() + 1, count),
                  room_products_[i]);
  } else {
    factors[0] = &room_rests_[i];
    multiply_cuts(std::span(factors.data(), count + 1), room_products_[i]);
  }
}

}  // namespace relight

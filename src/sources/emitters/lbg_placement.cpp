#include "sources/emitters/lbg_placement.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace relight {

namespace {

constexpr int kMaxIterations = 50;
constexpr double kRelativeChange = 1e-4;
constexpr double kSplitFraction = 1e-3;  // of the points' bounding-box diagonal

double distance2(Vec3 a, Vec3 b) {
  const Vec3 d = a - b;
  return dot(d, d);
}

// SplitMix64 (Steele, Lea and Flood 2014): the same stream on every platform, unlike the
// standard library's distributions.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)

 private:
  std::uint64_t state_;
};

// Uniform on the unit sphere (Archimedes: z uniform in [−1, 1], φ uniform).
Vec3 random_direction(SplitMix64& rng) {
  const double z = 2 * rng.uniform() - 1;
  const double phi = 2 * kPi * rng.uniform();
  const double s = std::sqrt(std::max(0.0, 1 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

// A k-d tree over the codewords for the nearest-codeword queries of one Lloyd iteration. The
// answer is the lowest index among the nearest, whatever the tree's shape.
class NearestCodeword {
 public:
  explicit NearestCodeword(std::span<const Vec3> codewords)
      : codewords_(codewords), order_(codewords.size()), axis_(codewords.size()) {
    std::iota(order_.begin(), order_.end(), 0u);
    build(0, order_.size());
  }

  // The nearest codeword to p and its squared distance; `hint` (any index, best a near one)
  // only bounds the search.
  std::uint32_t find(Vec3 p, std::uint32_t hint, double& best_d2) const {
    std::uint32_t best = hint;
    best_d2 = distance2(p, codewords_[hint]);
    search(0, order_.size(), p, best, best_d2);
    return best;
  }

 private:
  static constexpr std::size_t kLeaf = 8;

  void build(std::size_t lo, std::size_t hi) {
    if (hi - lo <= kLeaf) return;
    Vec3 box_lo = codewords_[order_[lo]], box_hi = box_lo;
    for (std::size_t i = lo; i < hi; ++i) {
      box_lo = min(box_lo, codewords_[order_[i]]);
      box_hi = max(box_hi, codewords_[order_[i]]);
    }
    const Vec3 extent = box_hi - box_lo;
    const int axis =
        extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
    const std::size_t mid = lo + (hi - lo) / 2;
    const auto by_axis = [&](std::uint32_t a, std::uint32_t b) {
      const double ca = codewords_[a][axis], cb = codewords_[b][axis];
      return ca < cb || (ca == cb && a < b);
    };
    const auto first = order_.begin();
    std::nth_element(first + static_cast<std::ptrdiff_t>(lo),
                     first + static_cast<std::ptrdiff_t>(mid),
                     first + static_cast<std::ptrdiff_t>(hi), by_axis);
    axis_[mid] = static_cast<std::uint8_t>(axis);
    build(lo, mid);
    build(mid + 1, hi);
  }

  void consider(std::uint32_t i, Vec3 p, std::uint32_t& best, double& best_d2) const {
    const double d2 = distance2(p, codewords_[i]);
    if (d2 < best_d2 || (d2 == best_d2 && i < best)) {
      best = i;
      best_d2 = d2;
    }
  }

  // [lo, mid) lie on the low side of the median's plane, (mid, hi) on the high side; the far
  // side is searched when the plane is no farther than the best so far (ties: lower index).
  void search(std::size_t lo, std::size_t hi, Vec3 p, std::uint32_t& best, double& best_d2) const {
    if (hi - lo <= kLeaf) {
      for (std::size_t i = lo; i < hi; ++i) consider(order_[i], p, best, best_d2);
      return;
    }
    const std::size_t mid = lo + (hi - lo) / 2;
    const int axis = axis_[mid];
    consider(order_[mid], p, best, best_d2);
    const double diff = p[axis] - codewords_[order_[mid]][axis];
    if (diff < 0) {
      search(lo, mid, p, best, best_d2);
      if (diff * diff <= best_d2) search(mid + 1, hi, p, best, best_d2);
    } else {
      search(mid + 1, hi, p, best, best_d2);
      if (diff * diff <= best_d2) search(lo, mid, p, best, best_d2);
    }
  }

  std::span<const Vec3> codewords_;
  std::vector<std::uint32_t> order_;
  std::vector<std::uint8_t> axis_;  // split axis of the node whose median sits at this slot
};

// Lloyd iterations from the given codewords; `cell` holds each point's codeword (on entry a
// guess, any valid index). Returns each cluster's distortion in the last assignment.
std::vector<double> lloyd(std::span<const Vec3> points, std::vector<Vec3>& codewords,
                          std::vector<std::uint32_t>& cell) {
  const std::size_t n = points.size(), k = codewords.size();
  std::vector<double> d2(n);
  std::vector<Vec3> sums(k);
  std::vector<std::size_t> counts(k);
  std::vector<double> cluster_distortion(k);
  double previous = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const NearestCodeword tree(codewords);
    std::atomic<bool> changed{false};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& range) {
      bool any = false;
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const std::uint32_t c = tree.find(points[i], cell[i], d2[i]);
        any = any || c != cell[i];
        cell[i] = c;
      }
      if (any) changed.store(true, std::memory_order_relaxed);
    });
    // Sums in point order: the result does not depend on the threads.
    std::fill(sums.begin(), sums.end(), Vec3{});
    std::fill(counts.begin(), counts.end(), 0);
    std::fill(cluster_distortion.begin(), cluster_distortion.end(), 0.0);
    double distortion = 0;
    for (std::size_t i = 0; i < n; ++i) {
      sums[cell[i]] += points[i];
      ++counts[cell[i]];
      cluster_distortion[cell[i]] += d2[i];
      distortion += d2[i];
    }
    for (std::size_t c = 0; c < k; ++c) {
      if (counts[c] > 0) codewords[c] = sums[c] / static_cast<double>(counts[c]);
    }
    // Unchanged cells: the codewords were already these means (the same sums), a fixed point.
    // The first iteration's cells are compared with a guess, so they always count as changed.
    if (iteration > 0 && !changed.load()) break;
    if (previous - distortion < kRelativeChange * distortion) break;
    previous = distortion;
  }
  return cluster_distortion;
}

}  // namespace

std::vector<Vec3> lbg_sample_positions(std::span<const Vec3> points, int count,
                                       std::uint64_t seed) {
  if (count <= 0) return {};
  if (points.empty()) throw std::invalid_argument("lbg_sample_positions: no points");
  Vec3 lo = points.front(), hi = points.front(), sum{};
  for (const Vec3& p : points) {
    lo = min(lo, p);
    hi = max(hi, p);
    sum += p;
  }
  const double step = kSplitFraction * length(hi - lo);
  SplitMix64 rng(seed);

  std::vector<Vec3> codewords{sum / static_cast<double>(points.size())};
  std::vector<std::uint32_t> cell(points.size(), 0);
  std::vector<double> distortion = lloyd(points, codewords, cell);
  const auto wanted = static_cast<std::size_t>(count);
  while (codewords.size() < wanted) {
    const std::size_t k = codewords.size();
    std::vector<bool> split(k, true);
    if (wanted - k < k) {  // split only the (wanted − k) clusters of largest distortion
      std::vector<std::uint32_t> rank(k);
      std::iota(rank.begin(), rank.end(), 0u);
      std::stable_sort(rank.begin(), rank.end(), [&](std::uint32_t a, std::uint32_t b) {
        return distortion[a] > distortion[b];
      });
      std::fill(split.begin(), split.end(), false);
      for (std::size_t i = 0; i < wanted - k; ++i) split[rank[i]] = true;
    }
    std::vector<Vec3> next;
    std::vector<std::uint32_t> renumber(k);  // old codeword -> its (first) successor
    for (std::size_t c = 0; c < k; ++c) {
      renumber[c] = static_cast<std::uint32_t>(next.size());
      if (split[c]) {
        const Vec3 offset = step * random_direction(rng);
        next.push_back(codewords[c] + offset);
        next.push_back(codewords[c] - offset);
      } else {
        next.push_back(codewords[c]);
      }
    }
    for (std::uint32_t& c : cell) c = renumber[c];
    codewords = std::move(next);
    distortion = lloyd(points, codewords, cell);
  }
  return codewords;
}

}  // namespace relight

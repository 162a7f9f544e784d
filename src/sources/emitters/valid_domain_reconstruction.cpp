#include "sources/emitters/valid_domain_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace relight {

namespace {

// The samples' common coefficient count; throws if they disagree or have none.
std::size_t coefficient_count(std::span<const IncidentSample> samples) {
  if (samples.empty()) throw std::invalid_argument("reconstruct_valid_domain: no samples");
  const std::size_t k = samples.front().sh.size();
  for (const IncidentSample& s : samples) {
    if (s.sh.size() != k || k == 0) {
      throw std::invalid_argument("reconstruct_valid_domain: samples of different orders");
    }
  }
  return k;
}

struct Valid {
  std::uint32_t id;
  double distance;
};

// Σ w_i l_i / Σ w_i with w_i = 1/d_i, or the plain mean of the samples at distance 0. The
// weights are scaled by the smallest distance (w_i = d_min/d_i ∈ (0, 1]), which leaves the
// normalised weights unchanged and cannot overflow.
void interpolate(std::span<const IncidentSample> samples, std::span<const Valid> valid,
                 std::span<Rgb> row) {
  double nearest = valid.front().distance;
  for (const Valid& v : valid) nearest = std::min(nearest, v.distance);
  double total = 0;
  for (Rgb& c : row) c = {};
  for (const Valid& v : valid) {
    const double w = nearest == 0 ? (v.distance == 0 ? 1 : 0) : nearest / v.distance;
    if (w == 0) continue;
    total += w;
    const std::vector<Rgb>& sh = samples[v.id].sh;
    for (std::size_t j = 0; j < row.size(); ++j) row[j] += w * sh[j];
  }
  for (Rgb& c : row) c = c / total;
}

}  // namespace

LinearOctree build_sample_octree(std::span<const IncidentSample> samples,
                                 std::span<const Vec3> points) {
  LinearOctree octree(points);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    octree.insert(static_cast<std::uint32_t>(i), samples[i].position, samples[i].radius);
  }
  return octree;
}

void reconstruct_valid_domain(std::span<const IncidentSample> samples, const LinearOctree& octree,
                              std::span<const Vec3> points, std::span<const std::uint32_t> fallback,
                              std::span<Rgb> out) {
  if (points.empty()) return;
  const std::size_t k = coefficient_count(samples);
  if (fallback.size() != points.size() || out.size() != points.size() * k) {
    throw std::invalid_argument("reconstruct_valid_domain: fallback or output of the wrong size");
  }
  for (const std::uint32_t f : fallback) {
    if (f >= samples.size()) {
      throw std::invalid_argument("reconstruct_valid_domain: fallback sample out of range");
    }
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256), [&](const auto& range) {
    std::vector<Valid> valid;
    for (std::size_t p = range.begin(); p != range.end(); ++p) {
      const Vec3 x = points[p];
      valid.clear();
      octree.for_each_candidate(x, [&](std::uint32_t id) {
        const IncidentSample& s = samples[id];
        const Vec3 d = x - s.position;
        const double d2 = dot(d, d);
        if (d2 <= s.radius * s.radius) valid.push_back({id, std::sqrt(d2)});
      });
      if (valid.empty()) valid.push_back({fallback[p], 0});  // distance 0: that sample alone
      interpolate(samples, valid, out.subspan(p * k, k));
    }
  });
}

}  // namespace relight

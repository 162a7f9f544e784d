#include "sources/emitters/nearfield_transfer.h"

#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "engine/transfer_blocks.h"
#include "math/sampling.h"
#include "math/sh.h"

namespace relight {

std::vector<float> nearfield_transfer(const RayTracer& occluders, std::span<const Vec3> positions,
                                      std::span<const Vec3> normals,
                                      const NearfieldTransferSettings& settings,
                                      const RankShares* ranks) {
  if (positions.size() != normals.size()) {
    throw std::invalid_argument("nearfield transfer: positions and normals differ in count");
  }
  if (settings.order < 1 || settings.sqrt_directions < 1) {
    throw std::invalid_argument("nearfield transfer: order and directions must be >= 1");
  }
  const int m = settings.sqrt_directions;
  const auto k = static_cast<std::size_t>(sh_count(settings.order));
  const double weight = 4 * kPi / (m * m);
  std::vector<float> out(positions.size() * k, 0.0f);
  const RankShares own =
      ranks != nullptr ? *ranks : single_process_shares(positions.size(), kBlock);
  const std::vector<std::size_t> blocks = own.my_blocks();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size()), [&](const auto& range) {
    std::vector<double> y(k), t(k);
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      for (std::size_t r = own.first(blocks[i]); r < own.last(blocks[i]); ++r) {
        std::fill(t.begin(), t.end(), 0.0);
        const Vec3 n = normals[r];
        const Vec3 origin = offset_from_surface(positions[r], n);
        // Per-receiver scrambling decorrelates the jitter between neighbours.
        const auto scramble = static_cast<std::uint32_t>(settings.seed * 0x9E3779B97F4A7C15ull + r);
        for (int i = 0; i < m; ++i) {
          for (int j = 0; j < m; ++j) {
            const auto index = static_cast<std::uint32_t>(i * m + j);
            const double u1 = (i + unit_interval(van_der_corput(index, scramble))) / m;
            const double u2 = (j + unit_interval(sobol2(index, scramble))) / m;
            const Vec3 w = sample_uniform_sphere(u1, u2);
            const double cosine = dot(n, w);
            if (cosine <= 0) continue;
            Ray ray{origin, w};
            ray.t_far = settings.max_distance;
            if (occluders.occluded(ray)) continue;
            sh_eval(settings.order, w, y);
            for (std::size_t c = 0; c < k; ++c) t[c] += weight * cosine * y[c];
          }
        }
        for (std::size_t c = 0; c < k; ++c) out[r * k + c] = static_cast<float>(t[c]);
      }
    }
  });
  // On several ranks each keeps its own rows, which rank 0 gathers as it writes the file.
  return out;
}

}  // namespace relight

// Flux-preserving frosted-glass blur of a shell cubemap in the portal frame; see
// sources/portals/shell_frost.h.
#include "sources/portals/shell_frost.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/cubemap.h"

namespace relight {

namespace {

constexpr double kCutoffExponent = 36.0;  // K = exp(−36) ≈ 2.3e-16 at the truncation
constexpr int kTile = 4;                  // texels per tile side

Vec3 unit_outward(Vec3 outward) {
  const double len = length(outward);
  if (!is_finite(outward) || !(len > 0))
    throw std::invalid_argument("frost: the outward normal must be finite and non-zero");
  return outward / len;
}

// K(ω_i, ω_j) from d = ω_i·ω_j, rounded to float: the value both the normalisation Z and the blur
// use, whether the plan stores it or it is recomputed (so the flux identity holds to double
// rounding either way), 0 beyond the truncation.
double kernel(const FrostPlan& plan, double d) {
  if (d < plan.min_dot) return 0.0;
  return static_cast<float>(std::exp((d - 1.0) * plan.inv_sigma2));
}

// Calls visit(i, j, K(ω_i, ω_j)) for every front texel i of `tile` and every front texel j of
// the tiles within reach, in the order the stored kernel rows follow (K = 0 beyond the
// truncation).
template <class Visit>
void for_each_pair_in_reach(const FrostPlan& plan, std::size_t tile, Visit&& visit) {
  for (std::uint32_t i = plan.tile_begin[tile]; i < plan.tile_begin[tile + 1]; ++i) {
    const double xi = plan.x[i], yi = plan.y[i], zi = plan.z[i];
    for (std::uint32_t q = plan.neighbour_begin[tile]; q < plan.neighbour_begin[tile + 1]; ++q) {
      const std::uint32_t other = plan.neighbour[q];
      for (std::uint32_t j = plan.tile_begin[other]; j < plan.tile_begin[other + 1]; ++j)
        visit(i, j, kernel(plan, xi * plan.x[j] + yi * plan.y[j] + zi * plan.z[j]));
    }
  }
}

}  // namespace

bool frost_plan_matches(const FrostPlan& plan, int face_size, Vec3 outward, double frost_deg) {
  return plan.face_size == face_size && plan.frost_deg == frost_deg && length(outward) > 0 &&
         plan.outward == unit_outward(outward);
}

void make_frost_plan(int face_size, Vec3 outward, double frost_deg, FrostPlan& plan,
                     std::size_t max_stored_kernel) {
  if (face_size < 1) throw std::invalid_argument("frost: face size must be >= 1");
  if (!std::isfinite(frost_deg) || frost_deg < 0)
    throw std::invalid_argument("frost: frost_deg must be finite and >= 0");
  const Vec3 out = unit_outward(outward);
  const int n = face_size;
  plan.face_size = n;
  plan.outward = out;
  plan.frost_deg = frost_deg;
  plan.texel.clear();
  plan.x.clear();
  plan.y.clear();
  plan.z.clear();
  plan.weight.clear();
  plan.inv_z.clear();
  plan.tile_begin.assign(1, 0);
  plan.neighbour_begin.assign(1, 0);
  plan.neighbour.clear();
  if (frost_deg == 0) return;
  const double sigma = radians(frost_deg);
  plan.inv_sigma2 = 1.0 / (sigma * sigma);
  plan.min_dot = 1.0 - kCutoffExponent * sigma * sigma;  // may be < −1: no truncation
  // Front texels by tile, and each tile's bounding cone (axis, angular radius).
  const int tiles_per_side = (n + kTile - 1) / kTile;
  std::vector<Vec3> axis;
  std::vector<double> radius;
  for (int face = 0; face < 6; ++face)
    for (int tj = 0; tj < tiles_per_side; ++tj)
      for (int ti = 0; ti < tiles_per_side; ++ti) {
        const std::size_t first = plan.texel.size();
        Vec3 sum;
        for (int j = tj * kTile; j < std::min(n, (tj + 1) * kTile); ++j)
          for (int i = ti * kTile; i < std::min(n, (ti + 1) * kTile); ++i) {
            const Vec3 d = cubemap_texel_direction(n, {face, i, j});
            const double c = dot(d, out);
            if (!(c > 0)) continue;
            plan.texel.push_back(static_cast<std::uint32_t>(cubemap_texel_index(n, {face, i, j})));
            plan.x.push_back(d.x);
            plan.y.push_back(d.y);
            plan.z.push_back(d.z);
            plan.weight.push_back(c * cubemap_texel_solid_angle(n, i, j));
            sum += d;
          }
        if (plan.texel.size() == first) continue;
        const Vec3 a = normalize(sum);
        double r = 0;
        for (std::size_t k = first; k < plan.texel.size(); ++k) {
          const double d =
              std::clamp(a.x * plan.x[k] + a.y * plan.y[k] + a.z * plan.z[k], -1.0, 1.0);
          r = std::max(r, std::acos(d));
        }
        axis.push_back(a);
        radius.push_back(r);
        plan.tile_begin.push_back(static_cast<std::uint32_t>(plan.texel.size()));
      }
  // Tile pairs that may hold a pair of texels with ω·ω' ≥ min_dot.
  const double reach = plan.min_dot <= -1 ? kPi : std::acos(plan.min_dot);
  for (std::size_t p = 0; p < axis.size(); ++p) {
    for (std::size_t q = 0; q < axis.size(); ++q) {
      const double between = std::acos(std::clamp(dot(axis[p], axis[q]), -1.0, 1.0));
      if (between - radius[p] - radius[q] <= reach + 1e-9)
        plan.neighbour.push_back(static_cast<std::uint32_t>(q));
    }
    plan.neighbour_begin.push_back(static_cast<std::uint32_t>(plan.neighbour.size()));
  }
  // Where each tile's kernel rows start, if they fit the budget.
  const std::size_t tiles = axis.size();
  plan.kernel_begin.assign(tiles + 1, 0);
  for (std::size_t p = 0; p < tiles; ++p) {
    std::size_t row = 0;
    for (std::uint32_t q = plan.neighbour_begin[p]; q < plan.neighbour_begin[p + 1]; ++q)
      row += plan.tile_begin[plan.neighbour[q] + 1] - plan.tile_begin[plan.neighbour[q]];
    plan.kernel_begin[p + 1] =
        plan.kernel_begin[p] + row * (plan.tile_begin[p + 1] - plan.tile_begin[p]);
  }
  const bool store = plan.kernel_begin[tiles] <= max_stored_kernel;
  plan.kernel.assign(store ? plan.kernel_begin[tiles] : 0, 0.0f);
  // Z(ω) = Σ_ω' K·c·Ω, with the same truncated, float-rounded K as the blur.
  plan.inv_z.assign(plan.texel.size(), 0.0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles), [&](const auto& range) {
    for (std::size_t tile = range.begin(); tile != range.end(); ++tile) {
      for (std::uint32_t i = plan.tile_begin[tile]; i < plan.tile_begin[tile + 1]; ++i)
        plan.inv_z[i] = 0;
      std::size_t at = plan.kernel_begin[tile];
      for_each_pair_in_reach(plan, tile, [&](std::uint32_t i, std::uint32_t j, double k) {
        plan.inv_z[i] += k * plan.weight[j];
        if (store) plan.kernel[at++] = static_cast<float>(k);
      });
      for (std::uint32_t i = plan.tile_begin[tile]; i < plan.tile_begin[tile + 1]; ++i)
        plan.inv_z[i] = 1.0 / plan.inv_z[i];
    }
  });
}

void apply_frost(const FrostPlan& plan, std::span<Rgb> cubemap, std::vector<Rgb>& scratch) {
  if (plan.texel.empty()) return;
  if (cubemap.size() != cubemap_texel_count(plan.face_size))
    throw std::invalid_argument("frost: cubemap must hold 6·N² texels");
  const std::size_t m = plan.texel.size();
  // scratch[0, m): a(ω) = L·c·Ω/Z per front texel; scratch[m, 2m): the blurred L'.
  scratch.resize(2 * m);
  for (std::size_t i = 0; i < m; ++i)
    scratch[i] = cubemap[plan.texel[i]] * (plan.weight[i] * plan.inv_z[i]);
  const std::size_t tiles = plan.tile_begin.size() - 1;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles), [&](const auto& range) {
    for (std::size_t tile = range.begin(); tile != range.end(); ++tile) {
      for (std::uint32_t i = plan.tile_begin[tile]; i < plan.tile_begin[tile + 1]; ++i)
        scratch[m + i] = Rgb{};
      // K is symmetric: L'(ω_i) = Σ_j K(ω_j, ω_i)·a_j = Σ_j K(i, j)·a_j.
      if (plan.kernel.empty()) {
        for_each_pair_in_reach(plan, tile, [&](std::uint32_t i, std::uint32_t j, double k) {
          scratch[m + i] += scratch[j] * k;
        });
        continue;
      }
      const float* k = plan.kernel.data() + plan.kernel_begin[tile];
      for (std::uint32_t i = plan.tile_begin[tile]; i < plan.tile_begin[tile + 1]; ++i) {
        double r = 0, g = 0, b = 0;
        for (std::uint32_t q = plan.neighbour_begin[tile]; q < plan.neighbour_begin[tile + 1];
             ++q) {
          const std::uint32_t other = plan.neighbour[q];
          for (std::uint32_t j = plan.tile_begin[other]; j < plan.tile_begin[other + 1]; ++j) {
            const double w = *k++;
            r += w * scratch[j].r;
            g += w * scratch[j].g;
            b += w * scratch[j].b;
          }
        }
        scratch[m + i] = {r, g, b};
      }
    }
  });
  for (std::size_t i = 0; i < m; ++i) cubemap[plan.texel[i]] = scratch[m + i];
}

void frost_cubemap(int face_size, Vec3 outward, double frost_deg, std::span<Rgb> cubemap) {
  FrostPlan plan;
  make_frost_plan(face_size, outward, frost_deg, plan);
  std::vector<Rgb> scratch;
  apply_frost(plan, cubemap, scratch);
}

}  // namespace relight

#include "material/specular_lobe_sum.h"

#include <immintrin.h>

#include <algorithm>
#include <cmath>

#include "common/cpu_features.h"

namespace relight {

namespace {

// The smallest denominator S² (n·l Λ_v + n·v Λ_l): below it the lobe is a spike no node
// resolves, and the quotient would overflow.
constexpr float kTinyDenominator = 1e-30f;

// One light's lobe times its irradiance (the header's arithmetic), added to acc.
void add_portable(const SpecularLobeSum::Lobe& b, const MomentLightPlanes& p, std::size_t k,
                  float weight, std::array<std::array<float, 8>, 3>& acc) {
  const auto at = [&](std::size_t i) { return p.plane[i][k]; };
  const float lx = at(9), ly = at(10), lz = at(11);
  std::array<float, 3> e{};
  for (std::size_t c = 0; c < 3; ++c) {
    e[c] = b.nx * at(3 * c) + b.ny * at(3 * c + 1) + b.nz * at(3 * c + 2);
  }
  const float n_dot_l = b.nx * lx + b.ny * ly + b.nz * lz;
  if (!(n_dot_l > 0) || !(e[0] > 0 || e[1] > 0 || e[2] > 0)) return;
  const float c1 = 1 + (b.vx * lx + b.vy * ly + b.vz * lz);
  const float wx = lx + b.vx, wy = ly + b.vy, wz = lz + b.vz;
  const float cx = b.ny * wz - b.nz * wy, cy = b.nz * wx - b.nx * wz, cz = b.nx * wy - b.ny * wx;
  const float n_dot_w = n_dot_l + b.n_dot_v;
  const float s = cx * cx + cy * cy + cz * cz + n_dot_w * n_dot_w * b.alpha2;
  const float masking_l = std::sqrt(b.alpha2 + b.one_minus_alpha2 * n_dot_l * n_dot_l);
  const float smith = n_dot_l * b.masking_v + b.n_dot_v * masking_l;
  const float dv = b.scale * 4 * c1 * c1 / std::max(s * s * smith, kTinyDenominator);
  const float x = 1 - std::clamp(std::sqrt(std::max(0.5f * c1, 0.0f)), 0.0f, 1.0f);
  const float x5 = x * x * x * x * x;
  for (std::size_t c = 0; c < 3; ++c) {
    acc[c][0] += weight * e[c] * (b.f0[c] + (1 - b.f0[c]) * x5) * dv;
  }
}

__attribute__((target("avx2,fma"))) void add_avx2(const SpecularLobeSum::Lobe& b,
                                                  const MomentLightPlanes& p, std::size_t begin,
                                                  std::size_t end, float weight,
                                                  std::array<std::array<float, 8>, 3>& acc) {
  const __m256 nx = _mm256_set1_ps(b.nx), ny = _mm256_set1_ps(b.ny), nz = _mm256_set1_ps(b.nz);
  const __m256 vx = _mm256_set1_ps(b.vx), vy = _mm256_set1_ps(b.vy), vz = _mm256_set1_ps(b.vz);
  const __m256 n_dot_v = _mm256_set1_ps(b.n_dot_v), masking_v = _mm256_set1_ps(b.masking_v);
  const __m256 alpha2 = _mm256_set1_ps(b.alpha2), beta2 = _mm256_set1_ps(b.one_minus_alpha2);
  const __m256 scale = _mm256_set1_ps(4 * b.scale), zero = _mm256_setzero_ps();
  const __m256 one = _mm256_set1_ps(1), half = _mm256_set1_ps(0.5f);
  const __m256 tiny = _mm256_set1_ps(kTinyDenominator), w = _mm256_set1_ps(weight);
  __m256 f0[3], one_minus_f0[3], sum[3];
  for (std::size_t c = 0; c < 3; ++c) {
    f0[c] = _mm256_set1_ps(b.f0[c]);
    one_minus_f0[c] = _mm256_set1_ps(1 - b.f0[c]);
    sum[c] = _mm256_loadu_ps(acc[c].data());
  }
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  for (std::size_t k = begin; k < end; k += 8) {
    // The last group's lanes past `end` load nothing and count nothing.
    const auto left = static_cast<int>(std::min<std::size_t>(end - k, 8));
    const __m256i mask = _mm256_cmpgt_epi32(_mm256_set1_epi32(left), lane);
    __m256 in[12];
    for (std::size_t i = 0; i < 12; ++i) in[i] = _mm256_maskload_ps(p.plane[i] + k, mask);
    const __m256 lx = in[9], ly = in[10], lz = in[11];
    __m256 e[3];
    for (std::size_t c = 0; c < 3; ++c) {
      e[c] = _mm256_fmadd_ps(nx, in[3 * c],
                             _mm256_fmadd_ps(ny, in[3 * c + 1], _mm256_mul_ps(nz, in[3 * c + 2])));
    }
    const __m256 n_dot_l = _mm256_fmadd_ps(nx, lx, _mm256_fmadd_ps(ny, ly, _mm256_mul_ps(nz, lz)));
    const __m256 some_light = _mm256_or_ps(
        _mm256_or_ps(_mm256_cmp_ps(e[0], zero, _CMP_GT_OQ), _mm256_cmp_ps(e[1], zero, _CMP_GT_OQ)),
        _mm256_cmp_ps(e[2], zero, _CMP_GT_OQ));
    const __m256 counted =
        _mm256_and_ps(_mm256_and_ps(some_light, _mm256_cmp_ps(n_dot_l, zero, _CMP_GT_OQ)),
                      _mm256_castsi256_ps(mask));
    if (_mm256_movemask_ps(counted) == 0) continue;
    const __m256 c1 =
        _mm256_add_ps(one, _mm256_fmadd_ps(vx, lx, _mm256_fmadd_ps(vy, ly, _mm256_mul_ps(vz, lz))));
    const __m256 wx = _mm256_add_ps(lx, vx), wy = _mm256_add_ps(ly, vy), wz = _mm256_add_ps(lz, vz);
    const __m256 cx = _mm256_fmsub_ps(ny, wz, _mm256_mul_ps(nz, wy));
    const __m256 cy = _mm256_fmsub_ps(nz, wx, _mm256_mul_ps(nx, wz));
    const __m256 cz = _mm256_fmsub_ps(nx, wy, _mm256_mul_ps(ny, wx));
    const __m256 n_dot_w = _mm256_add_ps(n_dot_l, n_dot_v);
    const __m256 s =
        _mm256_fmadd_ps(_mm256_mul_ps(n_dot_w, n_dot_w), alpha2,
                        _mm256_fmadd_ps(cx, cx, _mm256_fmadd_ps(cy, cy, _mm256_mul_ps(cz, cz))));
    const __m256 masking_l =
        _mm256_sqrt_ps(_mm256_fmadd_ps(beta2, _mm256_mul_ps(n_dot_l, n_dot_l), alpha2));
    const __m256 smith = _mm256_fmadd_ps(n_dot_l, masking_v, _mm256_mul_ps(n_dot_v, masking_l));
    const __m256 denominator = _mm256_max_ps(_mm256_mul_ps(_mm256_mul_ps(s, s), smith), tiny);
    const __m256 dv = _mm256_div_ps(_mm256_mul_ps(scale, _mm256_mul_ps(c1, c1)), denominator);
    const __m256 v_dot_h =
        _mm256_min_ps(_mm256_sqrt_ps(_mm256_max_ps(_mm256_mul_ps(half, c1), zero)), one);
    const __m256 x = _mm256_sub_ps(one, v_dot_h);
    const __m256 x2 = _mm256_mul_ps(x, x);
    const __m256 x5 = _mm256_mul_ps(_mm256_mul_ps(x2, x2), x);
    const __m256 weighted = _mm256_and_ps(_mm256_mul_ps(dv, w), counted);
    for (std::size_t c = 0; c < 3; ++c) {
      const __m256 fresnel = _mm256_fmadd_ps(one_minus_f0[c], x5, f0[c]);
      sum[c] = _mm256_fmadd_ps(_mm256_mul_ps(e[c], fresnel), weighted, sum[c]);
    }
  }
  for (std::size_t c = 0; c < 3; ++c) _mm256_storeu_ps(acc[c].data(), sum[c]);
}

}  // namespace

void MomentLightBatch::push(const float* m, Vec3 l, float weight) {
  for (std::size_t i = 0; i < 9; ++i) plane_[i][size_] = m[i] * weight;
  plane_[9][size_] = static_cast<float>(l.x);
  plane_[10][size_] = static_cast<float>(l.y);
  plane_[11][size_] = static_cast<float>(l.z);
  ++size_;
}

MomentLightPlanes MomentLightBatch::planes() const {
  MomentLightPlanes p;
  for (std::size_t i = 0; i < 12; ++i) p.plane[i] = plane_[i].data();
  return p;
}

SpecularLobeSum::SpecularLobeSum(const MetallicRoughnessToward& brdf, Path path)
    : avx2_(path == Path::kFastest && has_avx2_fma()) {
  if (!(brdf.n_dot_v_ > 0)) return;
  lit_ = true;
  const double a2 = brdf.alpha_ * brdf.alpha_;
  lobe_ = {static_cast<float>(brdf.n_.x),
           static_cast<float>(brdf.n_.y),
           static_cast<float>(brdf.n_.z),
           static_cast<float>(brdf.v_.x),
           static_cast<float>(brdf.v_.y),
           static_cast<float>(brdf.v_.z),
           static_cast<float>(brdf.n_dot_v_),
           static_cast<float>(brdf.masking_v_),
           static_cast<float>(a2),
           static_cast<float>(1 - a2),
           static_cast<float>(a2 / (2 * kPi)),
           {static_cast<float>(brdf.f0_.r), static_cast<float>(brdf.f0_.g),
            static_cast<float>(brdf.f0_.b)}};
}

void SpecularLobeSum::add(const MomentLightPlanes& lights, std::size_t begin, std::size_t end,
                          float weight) {
  if (!lit_ || begin >= end) return;
  if (avx2_) {
    add_avx2(lobe_, lights, begin, end, weight, acc_);
    return;
  }
  for (std::size_t k = begin; k < end; ++k) add_portable(lobe_, lights, k, weight, acc_);
}

void SpecularLobeSum::flush_pending() {
  add(pending_, 1);
  pending_.clear();
}

Rgb SpecularLobeSum::total() {
  flush_pending();
  Rgb out;
  for (std::size_t lane = 0; lane < 8; ++lane) {
    out += Rgb{acc_[0][lane], acc_[1][lane], acc_[2][lane]};
  }
  return out;
}

}  // namespace relight

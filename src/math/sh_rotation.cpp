// Ivanic–Ruedenberg recursion (1996, with the 1998 erratum) for real SH rotation matrices;
// see sh_rotation.h. Notation follows the paper: M^l_{mn} = u U + v V + w W, with the helper
// P^l_{i,a,b} built from band 1 (R1) and band l−1.
#include "math/sh_rotation.h"

#include <cassert>
#include <cmath>
#include <cstdlib>

namespace relight {
namespace {

// Accessor for a band matrix stored at `base` with half-width l.
struct BandView {
  const double* base;
  int l;
  double operator()(int m, int n) const { return base[(m + l) * (2 * l + 1) + (n + l)]; }
};

// P^l_{i,a,b} of Ivanic & Ruedenberg Table 2 (i ∈ {−1, 0, 1}).
double p_term(int i, int l, int a, int b, const BandView& r1, const BandView& prev) {
  if (b == l) return r1(i, 1) * prev(a, l - 1) - r1(i, -1) * prev(a, -l + 1);
  if (b == -l) return r1(i, 1) * prev(a, -l + 1) + r1(i, -1) * prev(a, l - 1);
  return r1(i, 0) * prev(a, b);
}

double element(int l, int m, int n, const BandView& r1, const BandView& prev) {
  const double d_m0 = m == 0 ? 1.0 : 0.0;
  const double denom = std::abs(n) == l ? 2.0 * l * (2.0 * l - 1.0) : double(l + n) * (l - n);
  const int am = std::abs(m);
  const double u = std::sqrt(double(l + m) * (l - m) / denom);
  const double v =
      0.5 * std::sqrt((1.0 + d_m0) * (l + am - 1.0) * (l + am) / denom) * (1.0 - 2.0 * d_m0);
  const double w = -0.5 * std::sqrt((l - am - 1.0) * (l - am) / denom) * (1.0 - d_m0);

  double sum = 0.0;
  if (u != 0.0) sum += u * p_term(0, l, m, n, r1, prev);
  if (v != 0.0) {
    double vv;
    if (m == 0) {
      vv = p_term(1, l, 1, n, r1, prev) + p_term(-1, l, -1, n, r1, prev);
    } else if (m > 0) {
      const double d = m == 1 ? 1.0 : 0.0;
      vv = p_term(1, l, m - 1, n, r1, prev) * std::sqrt(1.0 + d) -
           p_term(-1, l, -m + 1, n, r1, prev) * (1.0 - d);
    } else {
      const double d = m == -1 ? 1.0 : 0.0;
      vv = p_term(1, l, m + 1, n, r1, prev) * (1.0 - d) +
           p_term(-1, l, -m - 1, n, r1, prev) * std::sqrt(1.0 + d);
    }
    sum += v * vv;
  }
  if (w != 0.0) {
    const double ww = m > 0 ? p_term(1, l, m + 1, n, r1, prev) + p_term(-1, l, -m - 1, n, r1, prev)
                            : p_term(1, l, m - 1, n, r1, prev) - p_term(-1, l, -m + 1, n, r1, prev);
    sum += w * ww;
  }
  return sum;
}

template <class T>
void rotate_one(const ShRotation& rot, int n_order, const T* in, T* out) {
  for (int l = 0; l < n_order; ++l) {
    const double* mat = rot.matrices.data() + ShRotation::band_offset(l);
    const int width = 2 * l + 1;
    const T* src = in + l * l;
    T* dst = out + l * l;
    for (int row = 0; row < width; ++row) {
      T acc{};
      const double* mrow = mat + static_cast<std::ptrdiff_t>(row) * width;
      for (int col = 0; col < width; ++col) acc += src[col] * mrow[col];
      dst[row] = acc;
    }
  }
}

}  // namespace

ShRotation make_sh_rotation(int order, const Mat3& r) {
  assert(order >= 0);
  ShRotation rot;
  rot.order = order;
  rot.matrices.assign(ShRotation::band_offset(order), 0.0);
  if (order == 0) return rot;
  rot.matrices[0] = 1.0;
  if (order == 1) return rot;

  // Band 1: the rotation matrix in the (y, z, x) order of (Y_1,−1, Y_10, Y_11).
  double* b1 = rot.matrices.data() + ShRotation::band_offset(1);
  constexpr int kAxis[3] = {1, 2, 0};  // m = −1, 0, 1 → y, z, x
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b1[i * 3 + j] = r(kAxis[i], kAxis[j]);

  const BandView r1{b1, 1};
  for (int l = 2; l < order; ++l) {
    const BandView prev{rot.matrices.data() + ShRotation::band_offset(l - 1), l - 1};
    double* band = rot.matrices.data() + ShRotation::band_offset(l);
    for (int m = -l; m <= l; ++m)
      for (int n = -l; n <= l; ++n)
        band[(m + l) * (2 * l + 1) + (n + l)] = element(l, m, n, r1, prev);
  }
  return rot;
}

ShRotation make_sh_rotation(int order, const Frame& local_to_world) {
  return make_sh_rotation(order, mat3_from_frame(local_to_world));
}

void sh_rotate(const ShRotation& rot, std::span<const double> in, std::span<double> out) {
  assert(in.size() == out.size());
  const int n = sh_order_from_count(in.size());
  assert(n <= rot.order);
  rotate_one(rot, n, in.data(), out.data());
}

void sh_rotate(const ShRotation& rot, std::span<const Rgb> in, std::span<Rgb> out) {
  assert(in.size() == out.size());
  const int n = sh_order_from_count(in.size());
  assert(n <= rot.order);
  rotate_one(rot, n, in.data(), out.data());
}

void sh_rotate_batch(const ShRotation& rot, std::span<const double> in, std::span<double> out) {
  assert(in.size() == out.size());
  const std::size_t stride = static_cast<std::size_t>(rot.order) * rot.order;
  if (stride == 0) return;
  assert(in.size() % stride == 0);
  for (std::size_t k = 0; k < in.size(); k += stride)
    rotate_one(rot, rot.order, in.data() + k, out.data() + k);
}

}  // namespace relight

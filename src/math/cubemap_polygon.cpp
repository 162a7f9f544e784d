// Texels a convex polygon covers, seen from a cubemap's centre; see cubemap_polygon.h.
#include "math/cubemap_polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "math/cubemap.h"

namespace relight {

namespace {

// How far (in texels) a row's or column's span is widened, so a direction on a texel's edge
// is never lost to rounding.
constexpr double kTexelMargin = 1e-7;

// out = the part of `in` where dot(plane, d) ≥ 0 (a plane through the centre).
void clip(const std::vector<Vec3>& in, Vec3 plane, std::vector<Vec3>& out) {
  out.clear();
  const std::size_t m = in.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3 p = in[k], q = in[(k + 1) % m];
    const double dp = dot(plane, p), dq = dot(plane, q);
    if (dp >= 0) out.push_back(p);
    if ((dp >= 0) != (dq >= 0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
  }
}

int clamp_cell(double x, int n) {
  return std::clamp(static_cast<int>(std::floor(x)), 0, n - 1);
}

// The texels of one face under the convex polygon with texel coordinates (x, y): per row, the
// x extent of the polygon within the row's strip (its vertices there and its edges' crossings
// of the strip's two lines).
void rasterise(int n, int face, const std::vector<double>& x, const std::vector<double>& y,
               std::vector<std::uint32_t>& texels) {
  const auto [y_min, y_max] = std::minmax_element(y.begin(), y.end());
  const int j0 = clamp_cell(*y_min - kTexelMargin, n), j1 = clamp_cell(*y_max + kTexelMargin, n);
  const std::size_t m = x.size();
  for (int j = j0; j <= j1; ++j) {
    const double lo = j - kTexelMargin, hi = j + 1 + kTexelMargin;
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
    const auto extend = [&](double v) {
      x_lo = std::min(x_lo, v);
      x_hi = std::max(x_hi, v);
    };
    for (std::size_t k = 0; k < m; ++k) {
      if (y[k] >= lo && y[k] <= hi) extend(x[k]);
      const std::size_t l = (k + 1) % m;
      for (const double line : {lo, hi}) {
        if ((y[k] - line) * (y[l] - line) < 0) {
          extend(x[k] + (x[l] - x[k]) * ((line - y[k]) / (y[l] - y[k])));
        }
      }
    }
    if (x_lo > x_hi) continue;
    const int i0 = clamp_cell(x_lo - kTexelMargin, n), i1 = clamp_cell(x_hi + kTexelMargin, n);
    for (int i = i0; i <= i1; ++i) {
      texels.push_back(
          static_cast<std::uint32_t>((static_cast<std::size_t>(face) * n + j) * n + i));
    }
  }
}

}  // namespace

void cubemap_polygon_texels(int n, std::span<const Vec3> polygon, Vec3 front,
                            CubemapPolygonScratch& scratch, std::vector<std::uint32_t>& texels) {
  std::vector<Vec3>& a = scratch.a;
  std::vector<Vec3>& b = scratch.b;
  std::vector<Vec3>& in_front = scratch.in_front;
  a.assign(polygon.begin(), polygon.end());
  clip(a, front, in_front);
  if (in_front.size() < 3) return;
  for (int face = 0; face < 6; ++face) {
    const Vec3 axis = cubemap_face_point(face, 0, 0);
    const Vec3 s_axis = cubemap_face_point(face, 1, 0) - axis;
    const Vec3 t_axis = cubemap_face_point(face, 0, 1) - axis;
    // The face's pyramid: |d·s| ≤ d·axis and |d·t| ≤ d·axis.
    clip(in_front, axis - s_axis, a);
    clip(a, axis + s_axis, b);
    clip(b, axis - t_axis, a);
    clip(a, axis + t_axis, b);
    if (b.size() < 3) continue;
    scratch.x.clear();
    scratch.y.clear();
    for (const Vec3 d : b) {
      const double w = dot(d, axis);
      if (!(w > 0)) continue;  // only the centre itself: the polygon's plane passes through it
      scratch.x.push_back((dot(d, s_axis) / w + 1) * 0.5 * n);
      scratch.y.push_back((dot(d, t_axis) / w + 1) * 0.5 * n);
    }
    if (scratch.x.size() < 3) continue;
    rasterise(n, face, scratch.x, scratch.y, texels);
  }
}

}  // namespace relight

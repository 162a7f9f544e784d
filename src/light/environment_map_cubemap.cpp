// Exact cubemap averages of an equirectangular map by Green's theorem in the equal-area
// (φ, cos θ) plane; see environment_map_cubemap.h.
#include "light/environment_map_cubemap.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "math/cubemap.h"

namespace relight {

namespace {

constexpr double kTwoPi = 2.0 * kPi;

// 3-point Gauss–Legendre on [−1, 1].
constexpr double kGaussNode = 0.77459666924148337704;  // sqrt(3/5)
constexpr double kGaussNodes[3] = {-kGaussNode, 0.0, kGaussNode};
constexpr double kGaussWeights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

struct Raster {
  int width = 0, height = 0;
  double d_phi = 0, d_theta = 0;
  double d_split = 0;  // Δφ / k, at most 1°: also split pieces there (coarse maps, near poles)
  double cos_rot = 1, sin_rot = 0;
  const std::vector<Rgb>* texels = nullptr;  // null: f ≡ 1
  double scale = 1;
  // prefix[j·(W+1) + i] = scale·Σ_{i' < i} f(i', j)·Δφ; the row total T_j at i = W.
  std::vector<Rgb> prefix;

  Rgb value(int i, int j) const {
    if (!texels) return {1, 1, 1};
    return (*texels)[static_cast<std::size_t>(j) * width + i] * scale;
  }
  Rgb prefix_at(int i, int j) const {
    if (!texels) {
      const double v = i * d_phi;
      return {v, v, v};
    }
    return prefix[static_cast<std::size_t>(j) * (width + 1) + i];
  }
  Rgb row_total(int j) const { return prefix_at(width, j); }
  // World → map frame (azimuth − rotate_deg, as Environment).
  Vec3 to_map(Vec3 d) const {
    return {d.x * cos_rot + d.z * sin_rot, d.y, d.z * cos_rot - d.x * sin_rot};
  }
  int row_of(double z) const {
    const double theta = std::acos(std::clamp(z, -1.0, 1.0));
    return std::clamp(static_cast<int>(std::floor(theta / d_theta)), 0, height - 1);
  }
  int column_of(double phi) const {
    return std::clamp(static_cast<int>(std::floor(phi / d_phi)), 0, width - 1);
  }
};

Raster make_raster(int width, int height, double rotate_deg, double scale,
                   const std::vector<Rgb>* texels) {
  Raster r;
  r.width = width;
  r.height = height;
  r.d_phi = kTwoPi / width;
  r.d_theta = kPi / height;
  r.d_split = r.d_phi / std::ceil(r.d_phi / radians(1.0));
  r.cos_rot = std::cos(radians(rotate_deg));
  r.sin_rot = std::sin(radians(rotate_deg));
  r.texels = texels;
  r.scale = scale;
  if (texels) {
    r.prefix.resize(static_cast<std::size_t>(height) * (width + 1));
    for (int j = 0; j < height; ++j) {
      Rgb sum;
      for (int i = 0; i < width; ++i) {
        r.prefix[static_cast<std::size_t>(j) * (width + 1) + i] = sum;
        sum += r.value(i, j) * r.d_phi;
      }
      r.prefix[static_cast<std::size_t>(j) * (width + 1) + width] = sum;
    }
  }
  return r;
}

double raw_phi(Vec3 q) {
  double phi = std::atan2(q.x, -q.z);
  if (phi < 0) phi += kTwoPi;
  return phi >= kTwoPi ? 0.0 : phi;
}

double z_of(Vec3 q) {
  return q.y / length(q);
}

// The unwrapped loop: φ is followed continuously from piece to piece.
struct Loop {
  bool started = false;
  double phi_ref = 0;  // unwrapped φ of the last piece's midpoint
  double first_raw = 0, first_unwrapped = 0;
  Rgb integral;                 // ∮ G dz
  double area = 0;              // ∮ φ dz (f ≡ 1)
  std::vector<double> scratch;  // split points of the current edge
};

// Adds ∫ G dz along the face segment q0 → q1 (map frame, not normalised).
void add_edge(const Raster& r, Vec3 q0, Vec3 q1, Loop& loop) {
  const Vec3 dq = q1 - q0;
  auto at = [&](double t) { return q0 + dq * t; };
  std::vector<double>& ts = loop.scratch;
  ts.assign({0.0, 1.0});

  // Column crossings (and the finer d_split meridians): φ is monotone along a great-circle arc that
  // misses the poles (an arc ending at a pole is a meridian: φ constant). Take φ at the ends, or
  // mid-arc at a pole.
  auto horizontal = [](Vec3 q) { return std::hypot(q.x, q.z); };
  const double phi_a = raw_phi(horizontal(q0) > 1e-12 * length(q0) ? q0 : at(0.5));
  const double phi_b = raw_phi(horizontal(q1) > 1e-12 * length(q1) ? q1 : at(0.5));
  const double delta = std::remainder(phi_b - phi_a, kTwoPi);
  const double lo = std::min(phi_a, phi_a + delta), hi = std::max(phi_a, phi_a + delta);
  for (long m = static_cast<long>(std::floor(lo / r.d_split)) + 1; m * r.d_split < hi; ++m) {
    const double phi = m * r.d_split;
    // Plane of the meridian φ: x cos φ + z sin φ = 0.
    const double c = std::cos(phi), s = std::sin(phi);
    const double den = dq.x * c + dq.z * s;
    if (den == 0) continue;
    const double t = -(q0.x * c + q0.z * s) / den;
    if (t > 0 && t < 1) ts.push_back(t);
  }

  // Row crossings z(t) = cos θ_j: (y0 + t Δy)² = c² |q0 + t Δq|² with y of the sign of c.
  double z_min = 2, z_max = -2;
  for (int k = 0; k <= 8; ++k) {
    const double z = z_of(at(k / 8.0));
    z_min = std::min(z_min, z);
    z_max = std::max(z_max, z);
  }
  const int j_lo = std::max(1, static_cast<int>(std::floor(std::acos(z_max) / r.d_theta)) - 1);
  const int j_hi =
      std::min(r.height - 1, static_cast<int>(std::ceil(std::acos(z_min) / r.d_theta)) + 1);
  for (int j = j_lo; j <= j_hi; ++j) {
    const double c = std::cos(j * r.d_theta);
    auto accept = [&](double t) {
      if (!(t > 0 && t < 1)) return;
      const double y = q0.y + t * dq.y;
      if ((y > 0) == (c > 0)) ts.push_back(t);
    };
    if (std::abs(c) < 1e-12) {  // the horizon: y(t) = 0
      if (dq.y != 0) {
        const double t = -q0.y / dq.y;
        if (t > 0 && t < 1) ts.push_back(t);
      }
      continue;
    }
    const double c2 = c * c;
    const double a = dq.y * dq.y - c2 * dot(dq, dq);
    const double b = 2.0 * (q0.y * dq.y - c2 * dot(q0, dq));
    const double cc = q0.y * q0.y - c2 * dot(q0, q0);
    if (std::abs(a) < 1e-14 * (dq.y * dq.y + c2 * dot(dq, dq)) || a == 0) {
      if (b != 0) accept(-cc / b);
      continue;
    }
    // A tangency may round to a slightly negative discriminant; an extra split is harmless.
    const double sq = std::sqrt(std::max(0.0, b * b - 4.0 * a * cc));
    const double qv = -0.5 * (b + (b >= 0 ? sq : -sq));
    if (qv != 0) {
      accept(qv / a);
      accept(cc / qv);
    } else {
      accept(0.0);
    }
  }
  // Pieces at most ~1° long, so that the 3-point rule is exact to ~1e-11 on coarse maps too.
  const double edge_angle = std::atan2(length(cross(q0, q1)), dot(q0, q1));
  const int min_pieces = static_cast<int>(std::ceil(edge_angle / radians(1.0)));
  for (int k = 1; k < min_pieces; ++k) ts.push_back(static_cast<double>(k) / min_pieces);
  std::sort(ts.begin(), ts.end());

  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const double ta = ts[k], tb = ts[k + 1];
    if (!(tb - ta > 1e-15)) continue;
    const Vec3 qm = at(0.5 * (ta + tb));
    const double phi_mid = raw_phi(qm);
    const int i = r.column_of(phi_mid), j = r.row_of(z_of(qm));
    double wraps = 0;  // unwrapped φ = raw φ + 2π·wraps
    if (!loop.started) {
      loop.started = true;
      loop.first_raw = phi_mid;
      loop.first_unwrapped = phi_mid;
    } else {
      wraps = std::round((loop.phi_ref - phi_mid) / kTwoPi);
    }
    loop.phi_ref = phi_mid + kTwoPi * wraps;
    const double phi_i = i * r.d_phi;
    // ∫ (φ − φ_i) dz on [ta, tb]: dz/dt = (Δy |q|² − y (q·Δq)) / |q|³.
    double moment = 0;
    const double half = 0.5 * (tb - ta), mid = 0.5 * (tb + ta);
    for (int g = 0; g < 3; ++g) {
      const Vec3 q = at(mid + half * kGaussNodes[g]);
      const double len2 = dot(q, q), len = std::sqrt(len2);
      const double dz = (dq.y * len2 - q.y * dot(q, dq)) / (len2 * len);
      // φ − φ_i taken near [0, Δφ] (the piece lies in column i).
      const double frac =
          std::remainder(raw_phi(q) - phi_i - 0.5 * r.d_phi, kTwoPi) + 0.5 * r.d_phi;
      moment += kGaussWeights[g] * frac * dz;
    }
    moment *= half;
    const double dz = z_of(at(tb)) - z_of(at(ta));
    loop.integral += (r.prefix_at(i, j) + r.row_total(j) * wraps) * dz + r.value(i, j) * moment;
    loop.area += (phi_i + kTwoPi * wraps) * dz + moment;
  }
}

// ∫ T(z) dz from z0 to z1 (either order), T = row totals; and the same for T ≡ 2π.
void add_row_integral(const Raster& r, double z0, double z1, double sign, Loop& loop) {
  const double lo = std::min(z0, z1), hi = std::max(z0, z1), dir = z1 >= z0 ? 1.0 : -1.0;
  for (int j = 0; j < r.height; ++j) {
    const double top = std::cos(j * r.d_theta), bottom = std::cos((j + 1) * r.d_theta);
    const double overlap = std::min(hi, top) - std::max(lo, bottom);
    if (overlap <= 0) continue;
    loop.integral += r.row_total(j) * (sign * dir * overlap);
    loop.area += kTwoPi * sign * dir * overlap;
  }
}

// Point of the face plane (not normalised) at face coordinates u, v ∈ [−1, 1].
Vec3 face_point(int face, double u, double v) {
  const Vec3 d = cubemap_direction({face, 0.5 * (u + 1.0), 0.5 * (v + 1.0)});
  return d / std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
}

Loop texel_loop(const Raster& r, int n, int face, int i, int j, std::vector<double> scratch = {}) {
  const double u0 = 2.0 * i / n - 1.0, u1 = 2.0 * (i + 1) / n - 1.0;
  const double v0 = 2.0 * j / n - 1.0, v1 = 2.0 * (j + 1) / n - 1.0;
  const Vec3 corners[4] = {r.to_map(face_point(face, u0, v0)), r.to_map(face_point(face, u1, v0)),
                           r.to_map(face_point(face, u1, v1)), r.to_map(face_point(face, u0, v1))};
  Loop loop;
  loop.scratch = std::move(scratch);
  for (int e = 0; e < 4; ++e) add_edge(r, corners[e], corners[(e + 1) % 4], loop);
  // Winding around a pole: close the loop along the pole line.
  const double back =
      loop.first_raw + kTwoPi * std::round((loop.phi_ref - loop.first_raw) / kTwoPi);
  const double winding = std::round((back - loop.first_unwrapped) / kTwoPi);
  if (winding != 0) {
    const double z_pole = corners[0].y > 0 ? 1.0 : -1.0;
    add_row_integral(r, z_of(corners[0]), z_pole, winding, loop);
  }
  return loop;
}

}  // namespace

std::vector<Rgb> equirect_map_to_cubemap(const EquirectMap& map, double rotate_deg, double scale,
                                         int face_size) {
  if (face_size < 1) throw std::invalid_argument("cubemap face size must be >= 1");
  if (map.width < 1 || map.height < 1 ||
      map.texels.size() != static_cast<std::size_t>(map.width) * map.height) {
    throw std::invalid_argument("environment map must hold width·height > 0 texels");
  }
  const int n = face_size;
  const Raster r = make_raster(map.width, map.height, rotate_deg, scale, &map.texels);
  const std::vector<double>& omega = cubemap_solid_angles(n);
  std::vector<Rgb> out(cubemap_texel_count(n));
  std::vector<double> scratch;
  for (int face = 0; face < 6; ++face) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        Loop loop = texel_loop(r, n, face, i, j, std::move(scratch));
        scratch = std::move(loop.scratch);
        const double sign = loop.area >= 0 ? 1.0 : -1.0;
        out[cubemap_texel_index(n, {face, i, j})] = loop.integral * (sign / omega[j * n + i]);
      }
    }
  }
  return out;
}

double equirect_raster_texel_solid_angle(int map_width, int map_height, int face_size, int face,
                                         int i, int j) {
  const Raster r = make_raster(map_width, map_height, 0.0, 1.0, nullptr);
  return std::abs(texel_loop(r, face_size, face, i, j).area);
}

}  // namespace relight

#include "material/metallic_roughness.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "math/frame.h"

namespace relight {

namespace {

constexpr double kDielectricF0 = 0.04;  // glTF 2.0 Appendix B: a dielectric's F0 (IOR 1.5)

double alpha_of(const MetallicRoughness& m) {
  // α below 1e-4 makes D overflow in double for n·h = 1; roughness 0.01 is a mirror already.
  return std::max(m.roughness * m.roughness, 1e-4);
}

Rgb f0_of(const MetallicRoughness& m) {
  const Rgb dielectric{kDielectricF0, kDielectricF0, kDielectricF0};
  return dielectric * (1 - m.metallic) + m.albedo * m.metallic;
}

Rgb schlick(Rgb f0, double v_dot_h) {
  const double x = 1 - std::clamp(std::abs(v_dot_h), 0.0, 1.0);
  const double x5 = x * x * x * x * x;
  return f0 + (Rgb{1, 1, 1} - f0) * x5;
}

double ggx_d(double alpha, double n_dot_h) {
  if (n_dot_h <= 0) return 0;
  const double a2 = alpha * alpha;
  const double t = n_dot_h * n_dot_h * (a2 - 1) + 1;
  return a2 / (kPi * t * t);
}

// Height-correlated Smith visibility V = G / (4 |n·l| |n·v|).
double smith_v(double alpha, double n_dot_l, double n_dot_v) {
  const double a2 = alpha * alpha;
  const double gv = n_dot_l * std::sqrt(a2 + (1 - a2) * n_dot_v * n_dot_v);
  const double gl = n_dot_v * std::sqrt(a2 + (1 - a2) * n_dot_l * n_dot_l);
  const double sum = gv + gl;
  return sum > 0 ? 0.5 / sum : 0;
}

// Smith's masking of one direction, G1 = 2 n·v / (n·v + √(α² + (1 − α²)(n·v)²)).
double smith_g1(double alpha, double n_dot_v) {
  const double a2 = alpha * alpha;
  return 2 * n_dot_v / (n_dot_v + std::sqrt(a2 + (1 - a2) * n_dot_v * n_dot_v));
}

// The chance of sampling the specular lobe.
double specular_share(const MetallicRoughness& m) {
  const double specular = luminance(f0_of(m));
  const double diffuse = luminance(m.albedo) * (1 - m.metallic) * (1 - kDielectricF0);
  const double total = specular + diffuse;
  return total > 0 ? std::clamp(specular / total, 0.1, 0.9) : 0.5;
}

// Density of l under the GGX visible-normal sampling for v (Heitz 2018 Eq. 17 over the
// reflection's Jacobian 1 / (4 v·h)): G1(v) D(h) / (4 n·v).
double specular_pdf(double alpha, double n_dot_v, double n_dot_h) {
  if (n_dot_v <= 0) return 0;
  return smith_g1(alpha, n_dot_v) * ggx_d(alpha, n_dot_h) / (4 * n_dot_v);
}

// acos x for 0 ≤ x ≤ 1 within 2e-8 (Abramowitz & Stegun 1964, eq. 4.4.46): √(1 − x) times a
// polynomial of degree 7. The view's shading looks the table up once a cut's node toward the
// eye, where libm's acos took a tenth of the frame.
double acos_unit(double x) {
  constexpr std::array<double, 8> a = {1.5707963050, -0.2145988016, 0.0889789874, -0.0501743046,
                                       0.0308918810, -0.0170881256, 0.0066700901, -0.0012624911};
  double p = a[7];
  for (int i = 6; i >= 0; --i) p = p * x + a[static_cast<std::size_t>(i)];
  return std::sqrt(1 - x) * p;
}

// The specular lobe's directional albedo E_s(μ) = ∫ F D V cos θ_l dω_l split by F0 (Schlick
// is linear in it): E_s = F0 · A(μ, r) + B(μ, r), tabulated over μ = n·v and roughness r by
// quadrature in half-vector space (dω_l = 4 (v·h) dω_h), θ_h broken at atan(kα) so that a
// narrow peak is resolved; bilinear between entries. The cosine-weighted means Ā, B̄ are those
// of the interpolated table, so that the coupled diffuse term below integrates exactly.
class SpecularAlbedoTable {
 public:
  static const SpecularAlbedoTable& get() {
    static const SpecularAlbedoTable table;
    return table;
  }
  // (A, B) at μ and roughness r.
  std::pair<double, double> at(double mu, double r) const {
    const double x = u_of(mu) * (kMu - 1), y = std::sqrt(std::clamp(r, 0.0, 1.0)) * (kR - 1);
    const int i = std::min(static_cast<int>(x), kMu - 2), j = std::min(static_cast<int>(y), kR - 2);
    const double fx = x - i, fy = y - j;
    const auto lerp = [&](const std::vector<double>& t) {
      const auto e = [&](int a, int b) { return t[index(a, b)]; };
      return (1 - fy) * ((1 - fx) * e(i, j) + fx * e(i + 1, j)) +
             fy * ((1 - fx) * e(i, j + 1) + fx * e(i + 1, j + 1));
    };
    return {lerp(a_), lerp(b_)};
  }
  // (Ā, B̄) = 2 ∫ (A, B) μ dμ of the interpolated table at roughness r (linear in √r between
  // the table's roughnesses, as the interpolant is).
  std::pair<double, double> mean(double r) const {
    const double y = std::sqrt(std::clamp(r, 0.0, 1.0)) * (kR - 1);
    const int j = std::min(static_cast<int>(y), kR - 2);
    const double fy = y - j;
    const auto u = static_cast<std::size_t>(j);
    return {(1 - fy) * a_mean_[u] + fy * a_mean_[u + 1],
            (1 - fy) * b_mean_[u] + fy * b_mean_[u + 1]};
  }

 private:
  static constexpr int kMu = 128, kR = 64, kMean = 1024;
  // Entries are spaced evenly in u, θ = π/2 (1 − (1 − u)²): finer toward grazing, where the
  // masking of a smooth surface changes within a degree.
  static double u_of(double mu) {
    const double theta = acos_unit(std::clamp(mu, 0.0, 1.0));
    return 1 - std::sqrt(std::max(0.0, 1 - theta / (kPi / 2)));
  }
  // Roughness entries are spaced evenly in √r, finer where α = r² is small.
  static double roughness_of(int j) {
    const double y = static_cast<double>(j) / (kR - 1);
    return y * y;
  }
  static double mu_of(double u) {
    const double w = 1 - u;
    return std::cos(kPi / 2 * (1 - w * w));
  }
  static std::size_t index(int i, int j) {
    return static_cast<std::size_t>(j) * kMu + static_cast<std::size_t>(i);
  }
  SpecularAlbedoTable() : a_(std::size_t{kMu} * kR), b_(std::size_t{kMu} * kR) {
    // Each entry on its own (the quadrature is deterministic): the table is the same whatever
    // the threads do.
    tbb::parallel_for(0, kMu * kR, [&](int e) {
      const int i = e % kMu, j = e / kMu;
      const double alpha = std::max(std::pow(roughness_of(j), 2), 1e-4);
      const double mu = std::max(mu_of(static_cast<double>(i) / (kMu - 1)), 1e-4);
      const Vec3 v{std::sqrt(1 - mu * mu), 0, mu};
      const auto [a, b] = integrate(alpha, v);
      a_[index(i, j)] = a;
      b_[index(i, j)] = b;
    });
    for (int j = 0; j < kR; ++j) {
      const double r = roughness_of(j);
      double a = 0, b = 0;
      for (int k = 0; k < kMean; ++k) {
        const double mu = (k + 0.5) / kMean;
        const auto [ak, bk] = at(mu, r);
        a += 2 * ak * mu / kMean;
        b += 2 * bk * mu / kMean;
      }
      a_mean_.push_back(a);
      b_mean_.push_back(b);
    }
  }
  static std::pair<double, double> integrate(double alpha, Vec3 v) {
    double a = 0, b = 0;
    for_each_reflection_node(v, alpha, 32, [&](Vec3 l, double w) {
      const Vec3 h = normalize(l + v);
      const double x = 1 - dot(v, h), x5 = x * x * x * x * x;
      const double lobe = ggx_d(alpha, h.z) * smith_v(alpha, l.z, v.z) * l.z * w;
      a += lobe * (1 - x5);
      b += lobe * x5;
    });
    return {a, b};
  }
  std::vector<double> a_, b_, a_mean_, b_mean_;
};

}  // namespace

void for_each_reflection_node(Vec3 v, double alpha, int points,
                              const std::function<void(Vec3 l, double weight)>& visit) {
  std::array<double, 8> breaks{0};
  const std::array<double, 6> k{0.1, 0.3, 1.0, 3.0, 10.0, 30.0};
  for (std::size_t i = 0; i < k.size(); ++i) breaks[i + 1] = std::atan(k[i] * alpha);
  breaks[7] = kPi / 2;
  for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
    const double dt = (breaks[piece + 1] - breaks[piece]) / points;
    for (int t = 0; t < points; ++t) {
      const double theta = breaks[piece] + (t + 0.5) * dt;
      // Symmetric about the plane of v: half the circle, counted twice.
      for (int p = 0; p < points; ++p) {
        const double phi = (p + 0.5) * kPi / points;
        const Vec3 h{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                     std::cos(theta)};
        const double v_dot_h = dot(v, h);
        if (v_dot_h <= 0) continue;
        const Vec3 l = h * (2 * v_dot_h) - v;
        if (l.z <= 0) continue;
        visit(l, 4 * v_dot_h * std::sin(theta) * dt * (2 * kPi / points));
      }
    }
  }
}

void prepare_metallic_roughness_tables() {
  (void)SpecularAlbedoTable::get();
}

std::pair<double, double> specular_albedo_split(double n_dot_v, double roughness) {
  return SpecularAlbedoTable::get().at(n_dot_v, roughness);
}

Rgb specular_directional_albedo(const MetallicRoughness& m, double n_dot_v) {
  const auto [a, b] = specular_albedo_split(n_dot_v, m.roughness);
  const Rgb f0 = f0_of(m);
  return f0 * a + Rgb{b, b, b};
}

Rgb hemispherical_albedo(const MetallicRoughness& m) {
  // Named copies, not a structured binding: clang 14 (the fuzz build) cannot capture those.
  const auto mean_albedo = SpecularAlbedoTable::get().mean(m.roughness);
  const double a = mean_albedo.first, b = mean_albedo.second;
  const Rgb f0 = f0_of(m);
  const auto channel = [&](double f0c, double albedo) {
    const double mean = f0c * a + b;
    return mean + (1 - mean) * (1 - m.metallic) * albedo;
  };
  return {channel(f0.r, m.albedo.r), channel(f0.g, m.albedo.g), channel(f0.b, m.albedo.b)};
}

MetallicRoughnessToward::MetallicRoughnessToward(const MetallicRoughness& m, Vec3 n, Vec3 v)
    : n_(n),
      v_(v),
      n_dot_v_(dot(n, v)),
      roughness_(m.roughness),
      alpha_(alpha_of(m)),
      f0_(f0_of(m)) {
  const double a2 = alpha_ * alpha_;
  masking_v_ = std::sqrt(a2 + (1 - a2) * n_dot_v_ * n_dot_v_);
  if (n_dot_v_ <= 0 || m.metallic >= 1) return;
  // The diffuse layer gets what the specular lobe leaves, coupled reciprocally (header):
  // (1 − E_s(v)) (1 − E_s(l)) / (1 − Ē_s) · (1 − metallic) ρ / π; all but 1 − E_s(l) here.
  const Rgb ev = specular_directional_albedo(m, n_dot_v_);
  const std::pair<double, double> means = SpecularAlbedoTable::get().mean(m.roughness);
  const auto channel = [&](double f0c, double evc, double albedo) {
    const double mean = f0c * means.first + means.second;
    return (1 - evc) / (1 - mean) * albedo * (1 - m.metallic) / kPi;
  };
  diffuse_ = {channel(f0_.r, ev.r, m.albedo.r), channel(f0_.g, ev.g, m.albedo.g),
              channel(f0_.b, ev.b, m.albedo.b)};
}

Rgb MetallicRoughnessToward::specular(Vec3 l) const {
  const double n_dot_l = dot(n_, l);
  if (n_dot_l <= 0 || n_dot_v_ <= 0) return {};
  const Vec3 h = normalize(l + v_);
  // Height-correlated Smith V = G / (4 |n·l| |n·v|), the viewer's half kept (smith_v).
  const double a2 = alpha_ * alpha_;
  const double sum = n_dot_l * masking_v_ + n_dot_v_ * std::sqrt(a2 + (1 - a2) * n_dot_l * n_dot_l);
  const double visibility = sum > 0 ? 0.5 / sum : 0;
  return schlick(f0_, dot(v_, h)) * (ggx_d(alpha_, dot(n_, h)) * visibility);
}

Rgb MetallicRoughnessToward::diffuse(Vec3 l) const {
  const double n_dot_l = dot(n_, l);
  if (n_dot_l <= 0 || n_dot_v_ <= 0 || diffuse_ == Rgb{}) return {};
  const auto [a, b] = specular_albedo_split(n_dot_l, roughness_);
  return diffuse_of_sums({1, 1, 1}, {a, a, a}, {b, b, b});
}

Rgb MetallicRoughnessToward::diffuse_of_sums(const Rgb& e, const Rgb& a, const Rgb& b) const {
  if (n_dot_v_ <= 0) return {};
  return {(e.r - f0_.r * a.r - b.r) * diffuse_.r, (e.g - f0_.g * a.g - b.g) * diffuse_.g,
          (e.b - f0_.b * a.b - b.b) * diffuse_.b};
}

Rgb metallic_roughness_specular(const MetallicRoughness& m, Vec3 n, Vec3 l, Vec3 v) {
  return MetallicRoughnessToward(m, n, v).specular(l);
}

Rgb metallic_roughness_diffuse(const MetallicRoughness& m, Vec3 n, Vec3 l, Vec3 v) {
  return MetallicRoughnessToward(m, n, v).diffuse(l);
}

Rgb metallic_roughness_brdf(const MetallicRoughness& m, Vec3 n, Vec3 l, Vec3 v) {
  return MetallicRoughnessToward(m, n, v)(l);
}

double metallic_roughness_pdf(const MetallicRoughness& m, Vec3 n, Vec3 l, Vec3 v) {
  const double n_dot_l = dot(n, l), n_dot_v = dot(n, v);
  if (n_dot_l <= 0 || n_dot_v <= 0) return 0;
  const double p = specular_share(m);
  const Vec3 h = normalize(l + v);
  return p * specular_pdf(alpha_of(m), n_dot_v, dot(n, h)) + (1 - p) * n_dot_l / kPi;
}

BrdfSample sample_metallic_roughness(const MetallicRoughness& m, Vec3 n, Vec3 v, double u0,
                                     double u1, double u2) {
  const Frame frame = frame_from_normal(n);
  const Vec3 vl = frame.to_local(v);
  if (vl.z <= 0) return {-n, 0};
  Vec3 l;
  if (u0 < specular_share(m)) {
    // Heitz 2018 §4: the visible normal from the hemisphere configuration of v stretched by α.
    const double alpha = alpha_of(m);
    const Vec3 vh = normalize(Vec3{alpha * vl.x, alpha * vl.y, vl.z});
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = lensq > 0 ? Vec3{-vh.y, vh.x, 0} / std::sqrt(lensq) : Vec3{1, 0, 0};
    const Vec3 t2 = cross(vh, t1);
    const double r = std::sqrt(u1), phi = 2 * kPi * u2;
    const double p1 = r * std::cos(phi);
    const double s = 0.5 * (1 + vh.z);
    const double p2 = (1 - s) * std::sqrt(std::max(0.0, 1 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0, 1 - p1 * p1 - p2 * p2));
    const Vec3 h = normalize(Vec3{alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)});
    l = frame.to_world(h * (2 * dot(vl, h)) - vl);
  } else {
    const double r = std::sqrt(u1), phi = 2 * kPi * u2;
    l = frame.to_world({r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u1))});
  }
  return {l, metallic_roughness_pdf(m, n, l, v)};
}

}  // namespace relight

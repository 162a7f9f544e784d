// The glTF metallic–roughness BRDF (material/metallic_roughness.h) against numerical
// integration: its tabulated specular albedo and its directional albedo estimated with its own
// importance sampling match a deterministic quadrature to 1e-3 over tables of roughness and
// viewing angle, a white surface never reflects more than 1 (the white furnace), and the BRDF
// is reciprocal to 1e-9.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>

#include <gtest/gtest.h>

#include "material/metallic_roughness.h"
#include "math/sampling.h"

namespace relight {
namespace {

const Vec3 kNormal{0, 0, 1};

Vec3 view_at(double theta_deg) {
  const double t = theta_deg * kPi / 180;
  return {std::sin(t), 0, std::cos(t)};
}

// ∫ g(l) dω_l over the hemisphere of l about the normal for viewer v, at 200 points per piece.
double quadrature(const std::function<double(Vec3)>& g, Vec3 v, double alpha) {
  double sum = 0;
  for_each_reflection_node(v, alpha, 200, [&](Vec3 l, double w) { sum += g(l) * w; });
  return sum;
}

// Red channel's directional albedo ∫ f cos θ_l dω_l.
double albedo_by_quadrature(const MetallicRoughness& m, Vec3 v) {
  return quadrature([&](Vec3 l) { return metallic_roughness_brdf(m, kNormal, l, v).r * l.z; }, v,
                    std::max(m.roughness * m.roughness, 1e-4));
}

// The same by the BRDF's own importance sampling, f cos / pdf averaged over 2^20 draws.
double albedo_by_sampling(const MetallicRoughness& m, Vec3 v) {
  Pcg32 rng(7, 11);
  constexpr int kSamples = 1 << 20;
  double sum = 0;
  for (int i = 0; i < kSamples; ++i) {
    const BrdfSample s = sample_metallic_roughness(m, kNormal, v, rng.next_double(),
                                                   rng.next_double(), rng.next_double());
    if (s.pdf <= 0 || s.l.z <= 0) continue;
    sum += metallic_roughness_brdf(m, kNormal, s.l, v).r * s.l.z / s.pdf;
  }
  return sum / kSamples;
}

const std::array<double, 4> kRoughness{0.05, 0.2, 0.5, 1.0};
const std::array<double, 4> kTheta{0, 30, 60, 80};

TEST(MetallicRoughness, ImportanceSampledDirectionalAlbedoMatchesQuadratureWithin1e3) {
  const std::array<MetallicRoughness, 3> materials{MetallicRoughness{{1, 1, 1}, 0, 0},
                                                   MetallicRoughness{{1, 1, 1}, 1, 0},
                                                   MetallicRoughness{{0.6, 0.3, 0.1}, 0.5, 0}};
  double worst = 0;
  for (MetallicRoughness m : materials) {
    for (const double r : kRoughness) {
      m.roughness = r;
      for (const double t : kTheta) {
        const double q = albedo_by_quadrature(m, view_at(t));
        const double s = albedo_by_sampling(m, view_at(t));
        worst = std::max(worst, std::abs(q - s));
        EXPECT_NEAR(s, q, 1e-3) << "metallic " << m.metallic << " roughness " << r << " at " << t
                                << "°";
      }
    }
  }
  std::printf("sampling vs quadrature: worst directional albedo difference %.2e\n", worst);
}

// The white furnace: a white surface reflects at most what it receives, within the
// quadrature's 1e-3; a white dielectric all of it (its diffuse layer takes what the specular
// lobe leaves); a white metal less (single scattering: light that would bounce between
// microfacets is lost).
TEST(MetallicRoughness, AWhiteSurfaceNeverReflectsMoreThanItReceives) {
  double highest = 0, lowest_dielectric = 1, lowest_metal = 1;
  for (const double metallic : {0.0, 0.5, 1.0}) {
    for (const double r : kRoughness) {
      for (const double t : kTheta) {
        const double a = albedo_by_quadrature({{1, 1, 1}, metallic, r}, view_at(t));
        highest = std::max(highest, a);
        EXPECT_LE(a, 1 + 1e-3) << "metallic " << metallic << " roughness " << r << " at " << t
                               << "°";
        if (metallic == 1) lowest_metal = std::min(lowest_metal, a);
        if (metallic == 0) {
          lowest_dielectric = std::min(lowest_dielectric, a);
          EXPECT_NEAR(a, 1, 1e-3) << "roughness " << r << " at " << t << "°";
        }
      }
    }
  }
  std::printf(
      "white furnace: highest directional albedo %.5f, lowest of a dielectric %.5f, of a metal "
      "%.5f\n",
      highest, lowest_dielectric, lowest_metal);
}

// The specular lobe's tabulated directional albedo against quadrature of the lobe itself (a
// metal reflects by its lobe alone), over roughness × viewing angle, two F0.
TEST(MetallicRoughness, TheTabulatedSpecularAlbedoMatchesQuadratureWithin1e3) {
  double worst = 0;
  for (const double f0 : {0.04, 0.9}) {
    for (const double r : {0.02, 0.05, 0.1, 0.2, 0.35, 0.5, 0.75, 1.0}) {
      for (const double t : {0.0, 15.0, 30.0, 45.0, 60.0, 70.0, 80.0, 85.0, 89.0}) {
        const MetallicRoughness metal{{f0, f0, f0}, 1, r};
        const double q = albedo_by_quadrature(metal, view_at(t));
        const double table = specular_directional_albedo(metal, view_at(t).z).r;
        worst = std::max(worst, std::abs(q - table));
        EXPECT_NEAR(table, q, 1e-3) << "F0 " << f0 << " roughness " << r << " at " << t << "°";
      }
    }
  }
  std::printf("specular albedo table vs quadrature: worst difference %.2e\n", worst);
}

TEST(MetallicRoughness, TheBrdfIsReciprocalWithin1e9) {
  Pcg32 rng(3, 5);
  for (int i = 0; i < 1000; ++i) {
    const MetallicRoughness m{{rng.next_double(), rng.next_double(), rng.next_double()},
                              rng.next_double(),
                              0.02 + rng.next_double()};
    const Vec3 a = sample_cosine_hemisphere(rng.next_double(), rng.next_double());
    const Vec3 b = sample_cosine_hemisphere(rng.next_double(), rng.next_double());
    const Rgb ab = metallic_roughness_brdf(m, kNormal, a, b);
    const Rgb ba = metallic_roughness_brdf(m, kNormal, b, a);
    EXPECT_NEAR(ab.r, ba.r, 1e-9 * std::max(1.0, ab.r));
    EXPECT_NEAR(ab.g, ba.g, 1e-9 * std::max(1.0, ab.g));
    EXPECT_NEAR(ab.b, ba.b, 1e-9 * std::max(1.0, ab.b));
  }
}

TEST(MetallicRoughness, ThePdfIntegratesToOneAndIsTheOneSamplesReport) {
  for (const double r : kRoughness) {
    const MetallicRoughness m{{0.8, 0.8, 0.8}, 0.3, r};
    for (const double t : kTheta) {
      const Vec3 v = view_at(t);
      const double total =
          quadrature([&](Vec3 l) { return metallic_roughness_pdf(m, kNormal, l, v); }, v,
                     std::max(r * r, 1e-4));
      // Visible-normal sampling also draws directions below the surface (lost samples): over
      // the hemisphere the pdf integrates to 1 less the share of them.
      Pcg32 draws(9, 9);
      int lost = 0;
      constexpr int kDraws = 1 << 20;
      for (int i = 0; i < kDraws; ++i) {
        const BrdfSample s = sample_metallic_roughness(m, kNormal, v, draws.next_double(),
                                                       draws.next_double(), draws.next_double());
        lost += s.l.z <= 0 ? 1 : 0;
      }
      EXPECT_NEAR(total, 1 - static_cast<double>(lost) / kDraws, 2e-3)
          << "roughness " << r << " at " << t << "°";
      Pcg32 rng(1, 2);
      for (int i = 0; i < 100; ++i) {
        const BrdfSample s = sample_metallic_roughness(m, kNormal, v, rng.next_double(),
                                                       rng.next_double(), rng.next_double());
        if (s.l.z <= 0) continue;
        EXPECT_NEAR(s.pdf, metallic_roughness_pdf(m, kNormal, s.l, v), 1e-9 * s.pdf);
      }
    }
  }
}

}  // namespace
}  // namespace relight

// The glTF 2.0 metallic–roughness BRDF (Khronos, glTF 2.0 specification, 2021, Appendix B "BRDF
// Implementation"), the surface model of a material with a `metallic` or `roughness` key (a
// material with neither stays Lambertian: lambert.h):
//
//   f = F · D · V  +  diffuse,
//   D = α² / (π ((n·h)² (α² − 1) + 1)²)                        (Trowbridge–Reitz / GGX, α =
//   roughness²) V = 1 / (|n·l| √(α² + (1 − α²)(n·v)²) + |n·v| √(α² + (1 − α²)(n·l)²))
//                                                              (height-correlated Smith, G /
//                                                              4|n·l||n·v|)
//   F = F0 + (1 − F0)(1 − |v·h|)⁵,  F0 = mix(0.04, albedo, metallic)   (Schlick),
//
// with l and v on the normal's side (0 otherwise: light reaches a surface's front only).
//
// The diffuse layer: the specification's (1 − F(v·h)) · (1 − metallic) · albedo / π reflects
// more than it receives at grazing view (a white dielectric: 1.35 at 80° for roughness 0.05,
// 1.08 for 0.5, measured by quadrature), so the diffuse layer here gets what the specular lobe
// leaves, coupled reciprocally (Kelemen and Szirmay-Kalos 2001, "A microfacet based coupled
// specular-matte BRDF model with importance sampling"):
//   diffuse = (1 − E_s(v)) (1 − E_s(l)) / (1 − Ē_s) · (1 − metallic) · albedo / π,
// E_s the specular lobe's directional albedo (tabulated, specular_directional_albedo) and Ē_s
// its cosine-weighted mean: a white dielectric then reflects exactly 1 at every angle, and
// the layer is the specification's where the lobe's Fresnel is the same in all directions. It
// is reciprocal (f(l, v) = f(v, l): h, |v·h| = |l·h|, V and the coupling are symmetric).
//
// Sampling for Monte Carlo (the reference tracer): with probability p_s (the specular lobe's
// share of the albedo at normal incidence, clamped to [0.1, 0.9]) a GGX visible normal (Heitz
// 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4), §4) reflected about
// it, else a cosine-distributed direction; the pdf is the mixture's, so either choice weights
// every direction alike. Pinned by tests/material/metallic_roughness_test.cpp: directional
// albedo against numerical integration, the white furnace, reciprocity, the pdf.
#pragma once

#include <functional>
#include <utility>

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

struct MetallicRoughness {
  Rgb albedo;  // glTF baseColor: the diffuse colour of a dielectric, F0 of a metal
  double metallic = 0, roughness = 1;
};

// f(·, v) of one material at one normal for one viewer, for many l (a vertex's cut or BRDF
// samples toward the eye): what depends on v alone — F0, α, the masking of v, the diffuse
// layer's 1 − E_s(v) — is computed once. It owns the formulas above: metallic_roughness_brdf
// and its layers below are one of these for one l.
class MetallicRoughnessToward {
 public:
  MetallicRoughnessToward(const MetallicRoughness& m, Vec3 n, Vec3 v);
  Rgb operator()(Vec3 l) const { return specular(l) + diffuse(l); }
  Rgb specular(Vec3 l) const;
  Rgb diffuse(Vec3 l) const;
  // The diffuse layer summed over lights e_j from directions l_j above the surface, from sums
  // that do not depend on v: Σ_j e_j diffuse(l_j) = diffuse_of_sums(Σ e_j, Σ e_j A_j, Σ e_j B_j)
  // with (A_j, B_j) = specular_albedo_split(n·l_j, the BRDF's roughness), as the layer's factor
  // 1 − E_s(l) = 1 − F0·A − B is linear in them (so a view can keep the sums while the light
  // stays, sources/environment/environment_lighting.h).
  Rgb diffuse_of_sums(const Rgb& e, const Rgb& a, const Rgb& b) const;

 private:
  friend class SpecularLobeSum;  // the same lobe over many lights (material/specular_lobe_sum.h)
  Vec3 n_, v_;
  double n_dot_v_ = 0, roughness_ = 0, alpha_ = 0, masking_v_ = 0;
  Rgb f0_;
  Rgb diffuse_;  // (1 − E_s(v)) (1 − metallic) ρ / (π (1 − Ē_s)); 0 for a metal
};

// f(l, v) per channel (1/sr) at a surface of unit normal n; l toward the light, v toward the
// viewer, both unit.
Rgb metallic_roughness_brdf(const MetallicRoughness& m, Vec3 n, Vec3 l, Vec3 v);
// Its two layers, f = specular + diffuse: F D V, and the coupled diffuse layer.
Rgb metallic_roughness_specular(const MetallicRoughness& m, Vec3 n, Vec3 l, Vec3 v);
Rgb metallic_roughness_diffuse(const MetallicRoughness& m, Vec3 n, Vec3 l, Vec3 v);

// The specular lobe's directional albedo ∫ F D V cos θ_l dω_l per channel at n·v = `n_dot_v`
// (a table over n·v and roughness, bilinear; within 1e-3 of quadrature).
Rgb specular_directional_albedo(const MetallicRoughness& m, double n_dot_v);
// Its split by F0 (Schlick is linear in it): E_s = F0·A + B, the pair (A, B) at n·v = `n_dot_v`
// and `roughness`.
std::pair<double, double> specular_albedo_split(double n_dot_v, double roughness);

// Builds the table behind specular_directional_albedo and hemispherical_albedo now, once per
// process, so that its cost (measured: docs/decisions.md) falls outside a frame; otherwise it is
// built on first use, e.g. the first glossy material edit.
void prepare_metallic_roughness_tables();

// The hemispherical–hemispherical albedo per channel: the cosine-weighted mean over incident
// directions of the directional albedo, Ē_s + (1 − Ē_s)(1 − metallic) ρ (the coupled diffuse
// layer reflects (1 − E_s(v))(1 − metallic) ρ of light from v). What a Lambertian surface of
// the same flux budget would reflect.
Rgb hemispherical_albedo(const MetallicRoughness& m);

// Quadrature nodes over the hemisphere of l about the normal (0, 0, 1), for a viewer v in the
// xz-plane and integrands symmetric about that plane (as f, its pdf and cos θ_l are):
// visit(l, w) per node, Σ w g(l) ≈ ∫ g(l) dω_l. Nodes are laid in half-vector space
// (dω_l = 4 (v·h) dω_h), θ_h in pieces broken at atan(kα), k = 0.1 … 30, so that a narrow GGX
// peak and the broad diffuse lobe are both resolved; `points` midpoints per piece in θ_h and
// over the half circle in φ. The specular albedo table is built with it (32 points); the
// tests integrate with it as their oracle (200), checked in turn against sampling.
void for_each_reflection_node(Vec3 v, double alpha, int points,
                              const std::function<void(Vec3 l, double weight)>& visit);

struct BrdfSample {
  Vec3 l;          // unit; below the surface when the sample is lost (weight 0)
  double pdf = 0;  // per steradian
};

// A direction l for viewer direction v from three uniform numbers in [0, 1).
BrdfSample sample_metallic_roughness(const MetallicRoughness& m, Vec3 n, Vec3 v, double u0,
                                     double u1, double u2);

// The density sample_metallic_roughness draws l with.
double metallic_roughness_pdf(const MetallicRoughness& m, Vec3 n, Vec3 l, Vec3 v);

}  // namespace relight

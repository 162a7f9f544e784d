// The first reflection of a point light's (or the sun's) direct light off glossy surfaces: what a
// polished floor throws onto the ceiling from a downlight or a sun patch — exactly in direction, at
// run time, through the stored gather operator G. Used by the luminaires' term (per luminaire,
// sources/luminaires/luminaire_lighting.h) and the suns traced behind clear glass
// (sources/portals/portal_lighting.h).
//
// The diffuse transfer bounces a glossy vertex j's light as a Lambertian surface of its
// hemispherical albedo ρh_j (material/material_reflectance.h): receiver r gathers G_rj ρh_j E_j.
// For the direct light D_j of a point luminaire the incident direction l_j at j is known, so
// the light j sends toward r is the BRDF's, π f_j(l_j, ω_jr) D_j, with ω_jr the direction from
// vertex j to receiver r (Iwasaki et al. 2007 §4.1, Eq. 5–9, approximate a glossy object's
// outgoing light with a separable BRDF, Yue et al. 2009 keep glossy vertices' light in
// orthonormal bases, their Appendix — here the luminaire's direction makes the exact value
// cheap). The correction of receiver r,
//     c_r = Σ_{j glossy} G_rj (π f_j(l_j, ω_jr) D_j − ρh_j D'_j)      (per colour channel),
// D'_j the light the diffuse transfer reflected at j: D_j for light bounced at run time (the
// suns), and for a luminaire its distribution as the stored transfer holds it — the windowed
// SH series Σ_k w_k Y_k(ω_j) times the same geometry — so that the transfer's diffuse first
// reflection at glossy vertices is taken out exactly, not with the SH series' error (a cos⁶
// downlight at SH order 8 over a mirror floor: the ceiling 6.5 % low against the image
// source with D' = D, tests/cli/mirror_limit_test.cpp),
// then bounces diffusely like any light (X = G ρ (c + X), engine/bounce_solver.h), and the
// response Γ = c + X (3 per receiver) is what one luminaire adds for unit colour and dimmer.
// Near-mirror vertices (engine/mirror_reflection.h): with the light's mirror paths, a vertex on
// a mirror plane contributes only its diffuse layer per entry, π f_d(l_j, ω_jr) D_j − ρh_j D'_j,
// and the specular lobe reaches the receivers as the light's image instead,
//     c_r += Σ_paths I_k · factor_k · E_s,k(cos θ_y)     (the paths of receiver r; for the sun
//     I_k is the normal illuminance at the mirror, engine/mirror_reflection.h);
// without them (the sun's light) such a vertex reflects by its whole BRDF as any other.
// Light arriving at a glossy vertex from elsewhere (interreflections, windows) still leaves
// it as from a diffuse surface of albedo ρh. Pinned by tests/engine/glossy_first_bounce_test.cpp
// (one glossy patch, against the sum done by hand) and tests/cli/glossy_probe_test.cpp
// (probe against relight reference).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/bounce_solver.h"
#include "engine/gather_operator.h"
#include "engine/mirror_reflection.h"
#include "material/metallic_roughness.h"
#include "math/vec3.h"

namespace relight {

// A light's paths through the near-mirror planes and, along each, its intensity (cd) for a
// point light or its normal illuminance at y (lx) for the sun: `channels` (1, or 3 for RGB)
// values per path.
struct MirrorLight {
  std::span<const MirrorPath> paths;
  std::span<const float> intensity;
  std::size_t channels = 1;
};

class GlossyFirstBounce {
 public:
  // `gather` (receivers × vertices, kept alive by the caller); `positions` and `normals`: the
  // receivers' (vertices, then sensors); per vertex `glossy_of` an index into `glossy` or −1;
  // `albedo`: 3 per vertex, what the diffuse transfer bounces with (ρh at glossy vertices).
  // `mirrors` (may be null; kept alive by the caller): the near-mirror planes of these
  // materials.
  GlossyFirstBounce(const GatherOperator& gather, std::span<const Vec3> positions,
                    std::span<const Vec3> normals, std::vector<std::int32_t> glossy_of,
                    std::vector<MetallicRoughness> glossy, std::span<const float> albedo,
                    BounceSettings settings, const MirrorReflection* mirrors = nullptr);

  bool empty() const { return entries_.empty(); }
  // Whether vertex v is glossy (its entries are corrected).
  bool glossy(std::size_t v) const { return v < glossy_of_.size() && glossy_of_[v] >= 0; }
  // The near-mirror planes, or null when there are none.
  const MirrorReflection* mirrors() const { return mirrors_; }

  // Γ (3 per receiver) for light from a point (or the sun) whose direction toward each receiver
  // is (dir_x, dir_y, dir_z)[r] (unit, from the light) with irradiance `direct`: 1 value per
  // receiver (no colour: a luminaire's) or 3 (RGB: the sun through tinted glass). With
  // `mirror` (a point light's paths through mirrors()), the near-mirror vertices' specular
  // lobe is that light's image. `reflected` (as `direct`, or empty for `direct` itself): D',
  // what the diffuse transfer reflected at the glossy vertices.
  void respond(std::span<const float> dir_x, std::span<const float> dir_y,
               std::span<const float> dir_z, std::span<const float> direct,
               std::span<float> response, const MirrorLight* mirror = nullptr,
               std::span<const float> reflected = {}) const;

 private:
  struct Entry {  // one entry of G whose vertex is glossy
    std::uint32_t row, vertex;
    float weight;
  };
  const GatherOperator& gather_;
  std::vector<Vec3> positions_, normals_;
  std::vector<std::int32_t> glossy_of_;
  std::vector<MetallicRoughness> glossy_;
  std::vector<float> albedo_;
  BounceSettings settings_;
  const MirrorReflection* mirrors_ = nullptr;
  std::vector<Entry> entries_;          // row by row
  std::vector<std::size_t> row_first_;  // per row: its first entry, then the total
};

}  // namespace relight

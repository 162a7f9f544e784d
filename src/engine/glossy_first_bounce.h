// The first reflection of a point light's (or the sun's) direct light off glossy surfaces
// (issue 13): what a polished floor throws onto the ceiling from a downlight or a sun patch —
// exactly in direction, at run time, through the stored gather operator G. Used by the
// luminaires' term (per luminaire, sources/luminaire/luminaire_lighting.h) and the suns traced
// behind clear glass (sources/portal/portal_lighting.h).
//
// The diffuse transfer bounces a glossy vertex j's light as a Lambertian surface of its
// hemispherical albedo ρh_j (engine/material_reflectance.h): receiver r gathers G_rj ρh_j E_j.
// For the direct light D_j of a point luminaire the incident direction l_j at j is known, so
// the light j sends toward r is the BRDF's, π f_j(l_j, ω_jr) D_j, with ω_jr the direction from
// vertex j to receiver r (Iwasaki et al. 2007 §4.1, Eq. 5–9, approximate a glossy object's
// outgoing light with a separable BRDF, Yue et al. 2009 keep glossy vertices' light in
// orthonormal bases, their Appendix — here the luminaire's direction makes the exact value
// cheap). The correction of receiver r,
//     c_r = Σ_{j glossy} G_rj (π f_j(l_j, ω_jr) − ρh_j) D_j      (per colour channel),
// then bounces diffusely like any light (X = G ρ (c + X), engine/bounce_solver.h), and the
// response Γ = c + X (3 per receiver) is what one luminaire adds for unit colour and dimmer.
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
#include "material/metallic_roughness.h"
#include "math/vec3.h"

namespace relight {

class GlossyFirstBounce {
 public:
  // `gather` (receivers × vertices, kept alive by the caller); `positions` and `normals`: the
  // receivers' (vertices, then sensors); per vertex `glossy_of` an index into `glossy` or −1;
  // `albedo`: 3 per vertex, what the diffuse transfer bounces with (ρh at glossy vertices).
  GlossyFirstBounce(const GatherOperator& gather, std::span<const Vec3> positions,
                    std::span<const Vec3> normals, std::vector<std::int32_t> glossy_of,
                    std::vector<MetallicRoughness> glossy, std::span<const float> albedo,
                    BounceSettings settings);

  bool empty() const { return entries_.empty(); }

  // Γ (3 per receiver) for light from a point (or the sun) whose direction toward each receiver
  // is (dir_x, dir_y, dir_z)[r] (unit, from the light) with irradiance `direct`: 1 value per
  // receiver (no colour: a luminaire's) or 3 (RGB: the sun through tinted glass).
  void respond(std::span<const float> dir_x, std::span<const float> dir_y,
               std::span<const float> dir_z, std::span<const float> direct,
               std::span<float> response) const;

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
  std::vector<Entry> entries_;          // row by row
  std::vector<std::size_t> row_first_;  // per row: its first entry, then the total
};

}  // namespace relight

// The incident radiance at a sample point x (Sun 2005 §3.3.4): the emitters are
// rendered into a small cubemap seen from x, with occlusion by the scene, and projected onto
// SH with per-texel solid angles, l_k = Σ_texels L(c) Y_k(ω_c) ω(c); the distances to the
// emitters seen give their harmonic mean H_d = N / Σ 1/d_i (the oracle's, Eq. 3.3).
//
// Sun 2005 rasterises on the GPU; here each texel is ray-cast: 2×2 sub-rays, and 8×8 where
// those or its 8 neighbours' disagree (an emitter's outline, an occluder's edge), so a small
// emitter's solid angle is caught to a fraction of a texel. An emitter narrower than half a
// texel can slip between the sub-rays and be missed. Each sub-ray carries its own direction into
// Y_k and an equal share of its texel's exact solid angle; the harmonic mean weights distances the
// same way. A sub-ray sees an emitter when the emitter is hit before any occluder.
#pragma once

#include <limits>
#include <span>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

struct IncidentRadianceSettings {
  int face_size = 16;  // texels per cubemap face side
  int order = 4;       // SH bands l < order
};

struct IncidentRadiance {
  std::vector<Rgb> sh;  // order² coefficients
  // Harmonic mean distance to the emitters seen (infinity when none is seen).
  double harmonic_mean_distance = std::numeric_limits<double>::infinity();
  double emitter_solid_angle = 0;  // sr of the cubemap the emitters cover
};

// `emitters` reports, per hit, an id into `emitter_radiance` (cd/m² per channel) and, when
// given, into `emitter_normals`: a triangle seen from behind (its back, dot(ω, n) ≥ 0) emits
// nothing but still hides what is behind it; without normals both sides emit.
// `occluders` is the static scene (may be null: no occlusion).
IncidentRadiance sample_incident_radiance(Vec3 x, const RayTracer& emitters,
                                          std::span<const Rgb> emitter_radiance,
                                          std::span<const Vec3> emitter_normals,
                                          const RayTracer* occluders,
                                          const IncidentRadianceSettings& settings);

// |l| of the oracle (Eq. 3.3): the Euclidean norm of the coefficient vector, of each coefficient's
// luminance (Y of linear Rec.709).
double sh_luminance_norm(std::span<const Rgb> sh);

}  // namespace relight

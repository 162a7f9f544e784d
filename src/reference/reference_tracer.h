// `relight reference`: an independent Monte Carlo path tracer.
// Diffuse surfaces that reflect on their front side (back sides absorb), point
// luminaires with their full intensity distribution reached by next-event estimation,
// cosine-weighted continuation and Russian roulette on the albedo, deterministic
// per-sample random streams. It shares only the scene loader and the ray tracer with the
// transfer code, so accuracy tests can catch transfer bugs.
//
// Estimators: at a surface point x of albedo ρ, outgoing luminance
//   L(x) = ρ/π · E(x),  E(x) = E_direct(x) + π · E_ω~cos[L_in(x, ω)],
// with E_direct = Σ_lights V · I(−ω) · cos θ / d². Sensors report E; pixels report L (and
// E for false-colour illuminance views). A luminaire with a luminous opening (IES/LDT
// dimensions or a scene size) is seen through a random point of the opening per sample,
// so V averages to its visible fraction and shadows get their penumbrae; ω, I and d stay
// those of the photometric centre.
// Daylight (reference/reference_portals.h): E(x) also gets, per sample, next-event estimates
// of each portal's environment (an area sample of the window with backward occlusion, and
// a sun-cone sample for a sky with a sun); continuation rays that leave through a portal
// add nothing, so no light is counted twice. Camera rays that look out through a portal
// see the environment (sun included) in the luminance image.
// Near-field emitters (reference/reference_emitters.h): one next-event estimate per sample
// wherever the luminaires get one; camera rays do not see the emitters themselves.
// Glossy surfaces (the glTF metallic–roughness BRDF of material/metallic_roughness.h):
// outgoing luminance toward v is estimated directly,
//   L(x, v) = Σ_lights f(l, v) L_l cos θ_l / p_l · w_l  +  f(l', v) cos θ_l' / p(l') · L_in(l'),
// next-event samples of every light weighted against the BRDF sample l' (visible-normal and
// cosine mixture, sample_metallic_roughness) by the power heuristic, and the continuation l'
// adding what it finds through a window with the complementary weight
// (reference/reference_weight.h); Russian roulette on f cos / p. Sensors still report E, and the
// illuminance image E at the surface seen.
// Near-mirrors (reference/reference_mirror.h): wherever E is estimated, each luminaire's light
// reflected by each near-mirror plane is also sampled about the luminaire's image, weighted by
// the power heuristic against the cosine sampling that otherwise finds it.
// A top-level environment: wherever the luminaires get a next-event estimate, one
// direction drawn from the environment's sampler (and one from a sky's sun cone) that must
// leave the scene, weighted by the power heuristic against the continuation (cosine at a
// Lambertian point, the BRDF at a glossy one), which adds what it finds outside with the
// complementary weight; camera rays that leave the scene see it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "image/image.h"
#include "light/environment_sampling.h"
#include "light/luminaire_frame.h"
#include "material/metallic_roughness.h"
#include "material/mirror_planes.h"
#include "math/rgb.h"
#include "reference/reference_emitters.h"
#include "reference/reference_portals.h"
#include "scene/camera.h"
#include "scene/mesh_preparation.h"
#include "scene/scene.h"
#include "trace/traced_scene.h"

namespace relight {

struct ReferenceSettings {
  int spp = 64;  // samples per sensor / per pixel
  std::uint64_t seed = 1;
  int max_depth = 1000;  // safety bound; Russian roulette ends paths long before
  bool progress = true;
  // The longest path counted, in reflections plus one: 1 = direct light only (at a
  // sensor light straight from its sources, at a pixel the surface seen lit directly), 2 =
  // one more reflection, …; 0 = no limit.
  int max_bounces = 0;
};

// Everything the tracer reads; built once per scene.
// A luminaire's luminous opening as the reference samples it for visibility: extents
// along C0 (length), C90 (width) and the aim (height), elliptical in plan when round;
// all zero for a point source. Intensity is always taken from the photometric centre.
struct ReferenceOpening {
  double length = 0, width = 0, height = 0;
  bool round = false;
  bool is_point() const { return length <= 0 && width <= 0 && height <= 0; }
};

struct ReferenceScene {
  const PreparedMesh& mesh;
  const TracedScene& traced;
  const std::vector<PlacedLuminaire>& luminaires;
  std::vector<Rgb> triangle_albedo;
  std::vector<ReferenceOpening> openings;  // one per luminaire
  ReferencePortals portals;
  ReferenceEmitters emitters;  // near-field emitters as placed (reference/reference_emitters.h)
  // Glossy materials: per triangle an index into `glossy`, or −1 (Lambertian).
  std::vector<std::int32_t> triangle_glossy;
  std::vector<MetallicRoughness> glossy;
  // Near-mirror planes (material/mirror_planes.h, grouped by glossy material) and per triangle
  // the index of its plane, or −1: light reflected by them is also sampled about each
  // luminaire's image (reference/reference_mirror.h).
  std::vector<MirrorPlane> mirror_planes;
  std::vector<std::int32_t> triangle_mirror;
  // A top-level environment and its sampler (light/environment_sampling.h): seen by
  // every ray that leaves the scene without meeting a surface or portal glass; none: light
  // comes from outside only through portals.
  std::optional<Environment> open_environment;
  std::optional<EnvironmentSampler> open_sampler;
};

// Lights `ref` with a top-level environment from now on.
void light_with_environment(ReferenceScene& ref, Environment environment);

// `environments`: one per scene portal, in order (see make_reference_portals); may stay
// empty only for a scene without portals.
ReferenceScene make_reference_scene(const Scene& scene, const PreparedMesh& mesh,
                                    const TracedScene& traced,
                                    const std::vector<PlacedLuminaire>& luminaires,
                                    std::vector<Environment> environments = {},
                                    PlacedEmitters emitters = {},
                                    const std::vector<std::vector<ExteriorObject>>& exterior = {});

// Rays cast (closest-hit and shadow) and wall time of one estimate.
struct ReferenceStats {
  std::uint64_t rays = 0;
  double seconds = 0;
};

// Illuminance (lux per channel) at every sensor point, in scene order (set by set).
std::vector<Rgb> reference_sensor_illuminance(const Scene& scene, const ReferenceScene& ref,
                                              const ReferenceSettings& settings,
                                              ReferenceStats* stats = nullptr);

struct ReferenceImages {
  Image luminance;    // cd/m² per channel (the environment through portals); black where only
                      // the back of surfaces is seen, NaN where nothing is
  Image illuminance;  // lux per channel at the seen surface; NaN where none is seen
  std::size_t back_side_pixels = 0;  // pixels every sample of which met the back of a surface
};

ReferenceImages reference_render(const PinholeCamera& camera, const ReferenceScene& ref,
                                 const ReferenceSettings& settings,
                                 ReferenceStats* stats = nullptr);

}  // namespace relight

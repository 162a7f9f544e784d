// The image of a point light in the near-mirror planes (material/mirror_planes.h) at every
// receiver, at run time (the mirror limit: roughness near 0). For a light at p and a plane in front
// of which both p and receiver x lie, the light's image p' reaches x along the segment x–p' where
// it first meets the plane, at y, when nothing blocks x–y or y–p:
//     E_x = I(p → y) · cos θ_x / |x − p'|² · E_s(cos θ_y),
// (for the sun, parallel light of normal illuminance E_⊥: E_x = E_⊥(y) · cos θ_x · E_s(cos θ_y)),
// I the light's intensity toward y, θ_x the angle of the arrival at x, |x − p'| the unfolded
// path, E_s the mirror's specular directional albedo at the incidence θ_y (for a perfect
// mirror the Fresnel factor F(θ_y); material/metallic_roughness.h) — the image-source form
// I(γ) cos θ / d² · F that tests/cli/mirror_limit_test.cpp checks. The diffuse layer of such a
// mirror still reflects through the gather operator (engine/glossy_first_bounce.h).
//
// A path is traced once per light position and material state (a ray x → p' that must hit the
// plane's own triangles, and a shadow ray y → p) and kept as a record; the light's aim and
// photometry only change I, evaluated per record. Moved objects do not block a traced path (movable
// objects shadow the room's own light only). Pinned by tests/engine/mirror_reflection_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "material/mirror_planes.h"
#include "engine/runtime_scene.h"
#include "material/metallic_roughness.h"
#include "math/vec3.h"

namespace relight {

// One receiver ← mirror ← light path.
struct MirrorPath {
  std::uint32_t receiver = 0;
  std::uint32_t vertex = 0;   // the mirror's vertex nearest y: whose BRDF reflects
  float emit[3] = {0, 0, 0};  // a point light's unit direction toward y (world)
  float at[3] = {0, 0, 0};    // y, where the path meets the mirror
  float factor = 0;  // cos θ_x / |x − p'|² (1/m²) for a point light, cos θ_x for the sun
  float cos_in = 0;  // cos θ_y, the light's incidence on the mirror
};

class MirrorReflection {
 public:
  // The near-mirror planes of the scene's opaque triangles: a triangle reflects as a mirror
  // when its first corner's material (glossy_of per vertex: an index into `glossy`, or −1)
  // does. `scene` must outlive this.
  MirrorReflection(const RuntimeScene& scene, std::span<const std::int32_t> glossy_of,
                   std::span<const MetallicRoughness> glossy);

  bool empty() const { return planes_.empty(); }
  const std::vector<MirrorPlane>& planes() const { return planes_; }
  // Whether vertex v lies on a triangle of a plane here (its specular lobe is the image's).
  bool reflects(std::size_t v) const { return v < vertex_.size() && vertex_[v] != 0; }

  // The paths from a light at `light` to every receiver, receiver by receiver.
  std::vector<MirrorPath> trace(Vec3 light) const;
  // The paths of parallel light arriving from unit direction `toward` (from the surfaces to
  // the light: the sun), receiver by receiver. Whether the light reaches y (the window, what
  // shades it) is the caller's: E_x = E_⊥(y) cos θ_x E_s(cos θ_y), E_⊥ the light's normal
  // illuminance at y.
  std::vector<MirrorPath> trace_parallel(Vec3 toward) const;

 private:
  const RuntimeScene* scene_;
  std::vector<MirrorPlane> planes_;
  std::vector<std::int32_t> plane_of_;  // per mesh triangle id
  std::vector<std::uint8_t> vertex_;    // per vertex: on a plane's triangle

  // Where paths to receiver r start.
  Vec3 origin(std::size_t r) const;
  // The path to receiver r through plane p along w (unit, from r toward the image) within
  // `span` (m), if its first hit is the plane's: fills receiver, vertex, at.
  bool reaches_plane(std::size_t r, std::size_t p, Vec3 w, double span, MirrorPath& out) const;
};

}  // namespace relight

// An image of a relit scene through a camera: per-vertex radiance interpolated over the
// triangles (Gouraud-equivalent), or with `pixel_direct` the direct light of every kind
// evaluated exactly at each pixel's surface point (runtime/direct_light.h; near-field emitters
// as area lights) and only the interreflected light interpolated. Windows show
// the current shell of their portal.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "render/vertex_shading.h"
#include "runtime/relit_scene.h"
#include "scene/camera.h"

namespace relight {

ShadedImages render_relit_scene(RelitScene& scene, const Camera& camera, int width, int height,
                                bool pixel_direct = false);

// The luminance (cd/m², RGB) seen along each ray, shaded as render_relit_scene without
// pixel_direct (vertex light interpolated; a window shows its shell, and the suns' discs and a
// top-level environment's compact sources only `with_suns`); 0 where nothing is seen. For views
// that are no pinhole camera (render/glare.h).
std::vector<Rgb> relit_scene_luminance(RelitScene& scene, std::span<const Ray> rays,
                                       bool with_suns);

// The luminance (cd/m², 3 per vertex: the room's, then the movable objects' in their order)
// each glossy vertex sends toward `eye` under the state's materials — its luminaires' and suns'
// highlights exact, the room's reflection by `samples` BRDF samples of the relit vertices
// (render/glossy_pixels.h) — and NaN at the other vertices (and at glossy ones seen from
// behind or of hidden objects): what render_relit_scene interpolates without pixel_direct, and
// the studio's view-dependent shading (RLGV).
// With `needed` (1 per vertex), only those vertices are shaded; the others are NaN.
std::vector<float> glossy_vertex_luminance(RelitScene& scene, Vec3 eye, int samples,
                                           std::span<const std::uint8_t> needed = {});

// The vertices (of the shown scene, as above) of the triangles render_relit_scene's rays meet
// without pixel_direct at this camera and size: the ones it shades toward the eye (the capture
// paper's §V.B visible vertices).
std::vector<std::uint8_t> vertices_in_view(RelitScene& scene, const Camera& camera, int width,
                                           int height);

}  // namespace relight

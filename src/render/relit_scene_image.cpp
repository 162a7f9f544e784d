#include "render/relit_scene_image.h"

#include <optional>

#include "math/cubemap.h"
#include "render/pixel_direct.h"
#include "sources/nearfield/emitter_direct.h"

namespace relight {

ShadedImages render_relit_scene(RelitScene& scene, const Camera& camera, int width, int height,
                                bool pixel_direct) {
  const TransferFile& t = scene.transfer();
  const RayTracer& occluders = scene.opaque_tracer();
  const RayTracer& windows = scene.portal_tracer();
  const PinholeCamera pinhole = make_pinhole_camera(camera, width, height);
  const Relighter& lit = scene.relighter();
  const auto background = [&](Vec3 origin, Vec3 dir) {
    const RayHit hit = windows.intersect({origin, dir});
    if (!hit.hit()) return Rgb{};
    const Shell& shell = lit.shell(hit.triangle);
    Rgb l =
        shell.cubemap[cubemap_texel_index(shell.face_size, cubemap_texel(shell.face_size, dir))];
    for (const PortalSun& sun : lit.suns()) {  // traced exactly, so not in the shell
      if (sun.portal == hit.triangle && sun_disc_luminance(sun.disc, normalize(dir)) > 0) {
        l += sun.illuminance * (sun.disc.luminance / sun.disc.normal_illuminance);
      }
    }
    return l;
  };
  if (!pixel_direct) {
    return shade_vertices(
        pinhole,
        {occluders, t.positions, t.triangles, t.vertex_albedo, scene.irradiance(), {}, background});
  }
  const std::vector<float> indirect = scene.indirect_irradiance();
  const std::vector<LuminaireLight> lights = pixel_lights(t.scene, lit);
  // A scene without windows has no suns and no sun geometry.
  const std::optional<SunGeometry> sun_geometry =
      lit.suns().empty() ? std::nullopt : std::optional<SunGeometry>(lit.sun_geometry());
  const EmitterLighting* emitters = lit.emitters();
  return shade_vertices(
      pinhole, {occluders, t.positions, t.triangles, t.vertex_albedo, indirect,
                [&](Vec3 p, Vec3 n) {
                  Rgb e = luminaire_direct_irradiance(occluders, lights, p, n) +
                          (sun_geometry ? sun_irradiance(*sun_geometry, lit.suns(), p, n) : Rgb{});
                  if (emitters != nullptr) {
                    const Occluders room(occluders);
                    e += emitter_direct_irradiance(emitters->placed(), &room, p, n);
                  }
                  return e;
                },
                background});
}

}  // namespace relight

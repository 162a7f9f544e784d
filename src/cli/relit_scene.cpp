#include "cli/relit_scene.h"

#include "math/cubemap.h"
#include "render/environment_map_io.h"
#include "render/pixel_direct.h"

namespace relight {

RelitScene relight_transfer_file(const std::filesystem::path& rlt,
                                 const std::optional<std::filesystem::path>& state_file) {
  RelitScene r;
  r.transfer = std::make_unique<TransferFile>(open_transfer_file(rlt));
  RelighterSettings settings;
  settings.load_environment = load_environment;
  r.relighter = std::make_unique<Relighter>(r.transfer->view, r.transfer->scene, settings);
  r.irradiance.resize(3 * r.relighter->receivers());
  r.apply(state_file ? load_lighting_state(r.transfer->scene, *state_file)
                     : default_lighting_state(r.transfer->scene));
  return r;
}

void RelitScene::apply(const LightingState& state) {
  relighter->set_state(state);
  relighter->relight(irradiance);
}

std::vector<Rgb> RelitScene::sensor_irradiance() const {
  std::vector<Rgb> out;
  for (std::size_t s = 0; s < transfer->sensor_count; ++s) {
    const std::size_t r = 3 * (transfer->vertex_count + s);
    out.push_back({irradiance[r], irradiance[r + 1], irradiance[r + 2]});
  }
  return out;
}

ShadedImages RelitScene::render(const Camera& camera, int width, int height, bool pixel_direct) {
  const TransferFile& t = *transfer;
  if (!tracer) {
    std::vector<Triangle> opaque;
    opaque.reserve(t.opaque_triangles.size());
    for (std::uint32_t i : t.opaque_triangles) opaque.push_back(t.triangles[i]);
    tracer = std::make_unique<RayTracer>(t.positions, opaque, t.opaque_triangles);
    // Portal triangles, ids their portal's index: the view out of each window.
    std::vector<Triangle> glass;
    for (std::uint32_t i : t.portal_triangles) glass.push_back(t.triangles[i]);
    portal_tracer = std::make_unique<RayTracer>(t.positions, glass, t.portal_of_triangle);
  }
  const PinholeCamera pinhole = make_pinhole_camera(camera, width, height);
  const Relighter& lit = *relighter;
  const RayTracer& windows = *portal_tracer;
  const auto background = [&](Vec3 origin, Vec3 dir) {
    const RayHit hit = windows.intersect({origin, dir});
    if (!hit.hit()) return Rgb{};
    const Shell& shell = lit.shell(hit.triangle);
    return shell.cubemap[cubemap_texel_index(shell.face_size, cubemap_texel(shell.face_size, dir))];
  };
  if (!pixel_direct) {
    return shade_vertices(
        pinhole, {*tracer, t.positions, t.triangles, t.vertex_albedo, irradiance, {}, background});
  }
  std::vector<float> indirect(irradiance.size());
  relighter->relight(indirect, false);
  const std::vector<PixelLight> lights = pixel_lights(t.scene, *relighter);
  const std::vector<PixelSun> suns = pixel_suns(*relighter, t.scene.portals.size());
  const RayTracer& occluders = *tracer;
  return shade_vertices(pinhole, {*tracer, t.positions, t.triangles, t.vertex_albedo, indirect,
                                  [&](Vec3 p, Vec3 n) {
                                    return exact_direct_irradiance(occluders, lights, p, n) +
                                           sun_irradiance(occluders, windows, suns, p, n);
                                  },
                                  background});
}

}  // namespace relight

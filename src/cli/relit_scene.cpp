#include "cli/relit_scene.h"

#include "render/pixel_direct.h"

namespace relight {

RelitScene relight_transfer_file(const std::filesystem::path& rlt,
                                 const std::optional<std::filesystem::path>& state_file) {
  RelitScene r;
  r.transfer = std::make_unique<TransferFile>(open_transfer_file(rlt));
  r.relighter = std::make_unique<Relighter>(r.transfer->view, r.transfer->scene);
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
  }
  const PinholeCamera pinhole = make_pinhole_camera(camera, width, height);
  if (!pixel_direct) {
    return shade_vertices(pinhole,
                          {*tracer, t.positions, t.triangles, t.vertex_albedo, irradiance, {}});
  }
  std::vector<float> indirect(irradiance.size());
  relighter->relight(indirect, false);
  const std::vector<PixelLight> lights = pixel_lights(t.scene, *relighter);
  const RayTracer& occluders = *tracer;
  return shade_vertices(
      pinhole, {*tracer, t.positions, t.triangles, t.vertex_albedo, indirect,
                [&](Vec3 p, Vec3 n) { return exact_direct_irradiance(occluders, lights, p, n); }});
}

}  // namespace relight

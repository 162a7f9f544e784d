#include "runtime/relit_scene.h"

#include "engine/receivers.h"
#include "material/lambert.h"

namespace relight {

RelitScene::RelitScene(const std::filesystem::path& rlt,
                       const std::optional<std::filesystem::path>& state_file)
    : transfer_(std::make_unique<TransferFile>(open_transfer_file(rlt))) {
  relighter_ = std::make_unique<Relighter>(transfer_->view, transfer_->scene);
  irradiance_.resize(3 * relighter_->receivers());
  apply(state_file ? load_lighting_state(transfer_->scene, *state_file)
                   : default_lighting_state(transfer_->scene));
}

void RelitScene::apply(const LightingState& state) {
  relighter_->set_state(state);
  relighter_->relight(irradiance_);
}

std::vector<float> RelitScene::indirect_irradiance() {
  std::vector<float> out(irradiance_.size());
  relighter_->relight(out, false);
  return out;
}

std::vector<Rgb> RelitScene::sensor_irradiance() const {
  std::vector<Rgb> out;
  out.reserve(transfer_->sensor_count);
  for (std::size_t s = 0; s < transfer_->sensor_count; ++s) {
    const std::size_t r = 3 * sensor_receiver(transfer_->vertex_count, s);
    out.push_back({irradiance_[r], irradiance_[r + 1], irradiance_[r + 2]});
  }
  return out;
}

std::vector<float> RelitScene::vertex_radiance(std::span<const float> irradiance) const {
  std::vector<float> l(3 * transfer_->vertex_count);
  for (std::size_t i = 0; i < l.size(); ++i) {
    l[i] = static_cast<float>(lambertian_radiance(transfer_->vertex_albedo[i], irradiance[i]));
  }
  return l;
}

const RayTracer& RelitScene::opaque_tracer() {
  if (!opaque_tracer_) {
    const TransferFile& t = *transfer_;
    std::vector<Triangle> opaque;
    opaque.reserve(t.opaque_triangles.size());
    for (std::uint32_t i : t.opaque_triangles) opaque.push_back(t.triangles[i]);
    opaque_tracer_ = std::make_unique<RayTracer>(t.positions, opaque, t.opaque_triangles);
  }
  return *opaque_tracer_;
}

const RayTracer& RelitScene::portal_tracer() {
  if (!portal_tracer_) {
    const TransferFile& t = *transfer_;
    std::vector<Triangle> glass;
    glass.reserve(t.portal_triangles.size());
    for (std::uint32_t i : t.portal_triangles) glass.push_back(t.triangles[i]);
    portal_tracer_ = std::make_unique<RayTracer>(t.positions, glass, t.portal_of_triangle);
  }
  return *portal_tracer_;
}

const RayTracer& RelitScene::mesh_tracer() {
  if (!mesh_tracer_) {
    const TransferFile& t = *transfer_;
    mesh_tracer_ =
        std::make_unique<RayTracer>(t.positions, t.triangles, sequential_ids(t.triangles.size()));
  }
  return *mesh_tracer_;
}

}  // namespace relight

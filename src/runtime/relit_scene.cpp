#include "runtime/relit_scene.h"

#include <cstdio>

#include "engine/receivers.h"
#include "material/lambert.h"
#include "runtime/window_view.h"

namespace relight {

RelitScene::RelitScene(const std::filesystem::path& rlt,
                       const std::optional<std::filesystem::path>& state_file,
                       const RelighterSettings& settings)
    : transfer_(std::make_shared<const TransferFile>(open_transfer_file(rlt))),
      settings_(settings) {
  relighter_ = std::make_unique<Relighter>(transfer_->view, transfer_->scene, settings_);
  irradiance_.resize(3 * relighter_->receivers());
  apply(state_file ? load_lighting_state(transfer_->scene, *state_file)
                   : default_lighting_state(transfer_->scene));
}

RelitScene::RelitScene(TwinKey /*key*/, std::shared_ptr<const TransferFile> transfer,
                       const RelighterSettings& settings, const LightingState& state)
    : transfer_(std::move(transfer)), settings_(settings) {
  relighter_ = std::make_unique<Relighter>(transfer_->view, transfer_->scene, settings_);
  irradiance_.resize(3 * relighter_->receivers());
  apply(state);
}

std::unique_ptr<RelitScene> RelitScene::twin() const {
  RelighterSettings settings = settings_;
  settings.sensor_importance = relighter_->sensor_importance();
  return std::make_unique<RelitScene>(TwinKey{}, transfer_, settings, relighter_->state());
}

void RelitScene::apply(const LightingState& state) {
  relighter_->set_state(state);
  relighter_->relight(irradiance_);
  if (relighter_->objects() != nullptr) {
    for (const std::string& name : relighter_->take_object_warnings()) {
      std::fprintf(stderr, "warning: movable object \"%s\" is placed through the room's surfaces\n",
                   name.c_str());
    }
  }
}

std::vector<float> RelitScene::indirect_irradiance() {
  std::vector<float> out(irradiance_.size());
  relighter_->relight(out, false);
  return out;
}

std::vector<Rgb> RelitScene::sensor_rows(std::span<const float> per_receiver) const {
  std::vector<Rgb> out;
  if (per_receiver.empty()) return out;
  out.reserve(transfer_->sensor_count);
  for (std::size_t s = 0; s < transfer_->sensor_count; ++s) {
    const std::size_t r = 3 * sensor_receiver(transfer_->vertex_count, s);
    out.push_back({per_receiver[r], per_receiver[r + 1], per_receiver[r + 2]});
  }
  return out;
}

std::vector<Rgb> RelitScene::window_radiance() const {
  std::vector<Rgb> out;
  out.reserve(transfer_->view.portals.size());
  for (std::size_t p = 0; p < transfer_->view.portals.size(); ++p) {
    out.push_back(window_view_radiance(relighter_->shell(p), transfer_->view.portals[p].outward));
  }
  return out;
}

std::span<const float> RelitScene::object_albedo() const {
  const ObjectLighting* objects = relighter_->objects();
  return objects ? std::span<const float>(objects->placed().albedo) : std::span<const float>{};
}

std::span<const float> RelitScene::object_irradiance() const {
  const ObjectLighting* objects = relighter_->objects();
  return objects ? objects->irradiance(true) : std::span<const float>{};
}

std::vector<Rgb> RelitScene::sensor_irradiance() const {
  return sensor_rows(irradiance_);
}

std::vector<Rgb> RelitScene::sensor_sun_irradiance() const {
  return sensor_rows(relighter_->portals().sun_direct());
}

std::vector<float> RelitScene::vertex_radiance(std::span<const float> irradiance) const {
  std::vector<float> l(3 * transfer_->vertex_count);
  for (std::size_t i = 0; i < l.size(); ++i) {
    l[i] = static_cast<float>(lambertian_radiance(relighter_->vertex_albedo()[i], irradiance[i]));
  }
  return l;
}

namespace {

// A tracer over the stored triangles `which`, hits reporting `ids` (one per triangle).
std::unique_ptr<RayTracer> tracer_of(const TransferFile& t, std::span<const std::uint32_t> which,
                                     const std::vector<std::uint32_t>& ids) {
  std::vector<Triangle> triangles;
  triangles.reserve(which.size());
  for (const std::uint32_t i : which) triangles.push_back(t.triangles[i]);
  return std::make_unique<RayTracer>(t.positions, triangles, ids);
}

}  // namespace

const RayTracer& RelitScene::opaque_tracer() {
  if (const RuntimeScene* runtime = relighter_->runtime_scene()) return runtime->occluders();
  if (!opaque_tracer_) {
    opaque_tracer_ =
        tracer_of(*transfer_, transfer_->opaque_triangles, transfer_->opaque_triangles);
  }
  return *opaque_tracer_;
}

const RayTracer& RelitScene::shown_tracer() {
  const ObjectLighting* objects = relighter_->objects();
  if (objects == nullptr) return opaque_tracer();
  const PlacedObjects& placed = objects->placed();
  if (shown_tracer_ && shown_positions_ == placed.positions &&
      shown_triangles_ == placed.triangles) {
    return *shown_tracer_;
  }
  const TransferFile& t = *transfer_;
  std::vector<Vec3> positions = t.positions;
  positions.insert(positions.end(), placed.positions.begin(), placed.positions.end());
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> ids;
  for (const std::uint32_t i : t.opaque_triangles) {
    triangles.push_back(t.triangles[i]);
    ids.push_back(i);
  }
  const auto base = static_cast<std::uint32_t>(t.positions.size());
  for (std::size_t k = 0; k < placed.triangles.size(); ++k) {
    const Triangle& tri = placed.triangles[k];
    triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    ids.push_back(static_cast<std::uint32_t>(t.triangles.size() + k));
  }
  shown_tracer_ = std::make_unique<RayTracer>(positions, triangles, ids);
  shown_positions_ = placed.positions;
  shown_triangles_ = placed.triangles;
  return *shown_tracer_;
}

const RayTracer& RelitScene::portal_tracer() {
  if (const RuntimeScene* runtime = relighter_->runtime_scene()) return runtime->glass();
  if (!portal_tracer_) {
    portal_tracer_ =
        tracer_of(*transfer_, transfer_->portal_triangles, transfer_->portal_of_triangle);
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

// The one owner of "a lighting state applied to a precomputed scene" (docs/architecture.md,
// "runtime"): the opened .rlt, the Relighter over its sources, the current irradiance per
// receiver, the sensors' readings, per-vertex radiance, and the ray tracers over the stored
// mesh that renderers, pickers and exact direct light need. `render`, `probe`, `bench`,
// `nearfield`, `serve` and the demo all go through it.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "math/rgb.h"
#include "runtime/lighting_state.h"
#include "runtime/relighter.h"
#include "sources/transfer_file.h"
#include "trace/ray_tracer.h"

namespace relight {

class RelitScene {
 public:
  // Opens `rlt` and lights it with the state in `state_file`, or the scene's own state.
  RelitScene(const std::filesystem::path& rlt,
             const std::optional<std::filesystem::path>& state_file,
             const RelighterSettings& settings = {});

  // A second RelitScene of the same opened file (shared, read-only) with the same settings
  // and the sensors' importance shared (not solved again), lit by this one's state. A
  // relighter is not thread-safe: a caller that relights in parallel (`relight annual`'s
  // streams of hours) gives each thread its own. It holds its own relighter and runtime scene
  // (the gather operator copied: 29 MB for the demo room).
  std::unique_ptr<RelitScene> twin() const;
  // twin()'s constructor (the key can only be made here).
  class TwinKey {
    friend class RelitScene;
    TwinKey() = default;
  };
  RelitScene(TwinKey, std::shared_ptr<const TransferFile> transfer,
             const RelighterSettings& settings, const LightingState& state);

  const TransferFile& transfer() const { return *transfer_; }
  const Scene& scene() const { return transfer_->scene; }
  Relighter& relighter() { return *relighter_; }
  const Relighter& relighter() const { return *relighter_; }
  const LightingState& state() const { return relighter_->state(); }

  // Applies a state and relights.
  void apply(const LightingState& state);

  // Irradiance per receiver, RGB interleaved (3 per receiver: vertices, then sensors).
  std::span<const float> irradiance() const { return irradiance_; }
  // What renderers that evaluate direct light per pixel add it to: the same without the
  // luminaires' direct light and the portals' exact suns (Relighter::relight).
  std::vector<float> indirect_irradiance();
  // Sensor illuminance (lx, RGB) in scene order, sensor sets back to back.
  std::vector<Rgb> sensor_irradiance() const;
  // The portals' exact suns alone at every sensor (PortalSetLighting::sun_direct: no movable
  // object's shadow), as the last apply() traced them; empty when there is no sun.
  std::vector<Rgb> sensor_sun_irradiance() const;
  // Per-vertex luminance L = ρE/π (cd/m², RGB), 3 per vertex, from `irradiance` (3 per
  // receiver or per vertex).
  std::vector<float> vertex_radiance(std::span<const float> irradiance) const;

  // What a viewer of the lit scene shows besides the irradiance: what each portal's glass
  // shows looking out (runtime/window_view.h), in scene order; what the vertices reflect under
  // the state's materials (3 per vertex); the movable objects' vertices' albedo and
  // irradiance with direct light (3 per object vertex each, every object back to back in scene
  // order; empty without objects).
  std::vector<Rgb> window_radiance() const;
  std::span<const float> vertex_albedo() const { return relighter_->vertex_albedo(); }
  std::span<const float> object_albedo() const;
  std::span<const float> object_irradiance() const;
  // A material edit's approximate frame: n bounces of the edit's light until set back to −1
  // (converged; Relighter::set_material_bounces).
  void set_material_bounces(int bounces) { relighter_->set_material_bounces(bounces); }
  // How many luminaire distributions the relighter has projected incrementally.
  std::size_t incremental_curve_updates() const { return relighter_->incremental_curve_updates(); }

  // Ray tracers over the stored mesh, built on first use: the opaque triangles (ids: the
  // triangle's index in the mesh), the portals' glass (ids: the portal's index), and every
  // triangle (ids: its index; for picking).
  const RayTracer& opaque_tracer();
  const RayTracer& portal_tracer();
  const RayTracer& mesh_tracer();
  // The opaque triangles and the movable objects as the state places them (ids: the mesh's
  // triangle indices, then the placed objects' triangles numbered on from the mesh's count):
  // what a camera sees. Built again only when a placement moved, hid or showed a triangle, so
  // frames that move only the eye (the glossy view, `relight bench`'s view_ms) reuse it. The
  // opaque tracer without objects.
  const RayTracer& shown_tracer();

 private:
  // The sensors' rows of a per-receiver RGB array (3 per receiver), in scene order; empty for
  // an empty array.
  std::vector<Rgb> sensor_rows(std::span<const float> per_receiver) const;

  std::shared_ptr<const TransferFile> transfer_;  // stable address: the Relighter refers to it
  RelighterSettings settings_;
  std::unique_ptr<Relighter> relighter_;
  std::vector<float> irradiance_;
  std::unique_ptr<RayTracer> opaque_tracer_, portal_tracer_, mesh_tracer_, shown_tracer_;
  // The placed objects' vertices and triangles the shown tracer was built for.
  std::vector<Vec3> shown_positions_;
  std::vector<Triangle> shown_triangles_;
};

}  // namespace relight

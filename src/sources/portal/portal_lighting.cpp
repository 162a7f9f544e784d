#include "sources/portal/portal_lighting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "common/input_error.h"
#include "light/environment_map_io.h"
#include "math/placement.h"
#include "math/sh.h"

namespace relight {

std::vector<ExteriorObject> placed_exterior(const Scene& scene,
                                            const std::vector<ExteriorPlacement>& placements) {
  std::vector<ExteriorObject> objects;
  for (std::size_t i = 0; i < scene.exterior.size(); ++i) {
    const ExteriorGeometry& g = scene.exterior[i];
    const ExteriorPlacement p = i < placements.size() ? placements[i] : ExteriorPlacement{};
    if (!p.visible) continue;
    std::vector<Vec3> positions;
    positions.reserve(g.geometry.positions.size());
    for (const Vec3& x : g.geometry.positions) {
      positions.push_back(placed_point(x, g.pivot, p));
    }
    std::map<std::uint32_t, std::size_t> by_material;
    for (std::size_t t = 0; t < g.geometry.triangles.size(); ++t) {
      const std::uint32_t m = g.geometry.triangle_material[t];
      auto it = by_material.find(m);
      if (it == by_material.end()) {
        it = by_material.emplace(m, objects.size()).first;
        objects.push_back({positions, {}, scene.materials.at(m).albedo});
      }
      objects[it->second].triangles.push_back(g.geometry.triangles[t]);
    }
  }
  return objects;
}

void update_portal_lighting(PortalLighting& lighting, const PortalTransferView& portal,
                            int sh_order, const PortalState& state, const Scene& scene) {
  const auto start = std::chrono::steady_clock::now();
  const Environment environment = [&] {
    try {
      return load_environment(state.environment);
    } catch (const InputError& e) {  // e.g. a map file moved since the precompute
      fail_input(state.environment.where, e.what());
    }
  }();
  const std::vector<ExteriorObject> exterior = placed_exterior(scene, state.exterior);
  ShellInputs inputs;
  inputs.environment = &environment;
  inputs.tint = state.tint;
  inputs.frost_deg = state.frost_deg;
  inputs.exterior = exterior;
  // The indirect weights are the SH of the shell's outward half: no light from behind the
  // portal's plane can pass it (its direct transfer is zero), but in a band-limited projection
  // of the whole shell a bright feature there — a sun behind the building, a bright map
  // region — rings into the directions that do pass and lights the room through the indirect
  // transfer (a map of high contrast through a window: floor error against the reference
  // 4.4 % mean, 16 % worst unmasked; see docs/design-notes.md).
  inputs.sh_outward_half = true;
  const Shell& shell = lighting.shell;
  render_shell(inputs, {portal.centre, portal.outward}, portal.face_size, sh_order, lighting.shell,
               lighting.workspace);
  prepare_shell_cubemap(portal.face_size, shell.cubemap, lighting.cubemap);
  lighting.sharp_sun.reset();
  if (shell.sun_in_shell && state.frost_deg == 0) {
    // The same shell without the sun's deposit, for renderers that trace the sun per pixel.
    lighting.sky_cells = shell.cubemap;
    Rgb& value = lighting.sky_cells[shell.sun_texel];
    value = Rgb{std::max(0.0, value.r - shell.sun_radiance.r),
                std::max(0.0, value.g - shell.sun_radiance.g),
                std::max(0.0, value.b - shell.sun_radiance.b)};
    prepare_shell_cubemap(portal.face_size, lighting.sky_cells, lighting.sky_cubemap);
    const SunDisc& sun = *environment.sun();
    lighting.sharp_sun = PortalSun{sun.direction, state.tint * sun.normal_illuminance};
  }
  const auto k = static_cast<std::size_t>(sh_count(sh_order));
  lighting.weights.resize(3 * k);
  lighting.active = false;
  for (std::size_t b = 0; b < k; ++b) {
    const Rgb c = shell.sh[b];
    lighting.weights[3 * b] = static_cast<float>(c.r);
    lighting.weights[3 * b + 1] = static_cast<float>(c.g);
    lighting.weights[3 * b + 2] = static_cast<float>(c.b);
    lighting.active = lighting.active || c.r != 0 || c.g != 0 || c.b != 0;
  }
  lighting.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

PortalSetLighting::PortalSetLighting(PortalTransferSet transfer, const Scene& scene)
    : transfer_(transfer), scene_(&scene) {
  if (transfer_.portals.size() != scene.portals.size()) {
    throw std::invalid_argument("PortalSetLighting: transfer and scene disagree on portals");
  }
  for (const Portal& p : scene.portals) states_.push_back(portal_state(p, scene.exterior.size()));
  portals_.resize(scene.portals.size());
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    update_portal_lighting(portals_[p], transfer_.portals[p], transfer_.sh_order, states_[p],
                           scene);
  }
}

bool PortalSetLighting::set_state(std::span<const PortalState> states) {
  if (states.size() != portals_.size()) {
    throw std::invalid_argument("PortalSetLighting: one state per portal");
  }
  bool changed = false;
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    if (states[p] == states_[p]) continue;
    update_portal_lighting(portals_[p], transfer_.portals[p], transfer_.sh_order, states[p],
                           *scene_);
    states_[p] = states[p];
    changed = true;
  }
  return changed;
}

void PortalSetLighting::add_block(std::size_t b, bool include_direct,
                                  float (&acc)[3][kBlock]) const {
  const std::size_t n = transfer_.receivers;
  const auto kp = static_cast<std::size_t>(sh_count(transfer_.sh_order));
  const std::size_t base = b * kBlock;
  const std::size_t count = std::min(kBlock, n - base);
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    const PortalLighting& l = portals_[p];
    if (!l.active) continue;
    const PortalTransferView& v = transfer_.portals[p];
    const ShellCubemap& shell = include_direct || !l.sharp_sun ? l.cubemap : l.sky_cubemap;
    for (std::size_t i = 0; i < count; ++i) {
      const std::uint64_t at = v.offsets[base + i];
      const Rgb e =
          dot_receiver_cubemap(v.records.subspan(at, v.offsets[base + i + 1] - at), shell);
      acc[0][i] += static_cast<float>(e.r);
      acc[1][i] += static_cast<float>(e.g);
      acc[2][i] += static_cast<float>(e.b);
    }
    add_weighted_block(v.indirect.data() + b * kp * 3 * kBlock, kp, l.weights.data(), acc);
  }
}

std::size_t PortalSetLighting::transfer_bytes() const {
  std::size_t bytes = 0;
  for (std::size_t p = 0; p < portals_.size(); ++p) {
    if (!portals_[p].active) continue;
    const PortalTransferView& v = transfer_.portals[p];
    bytes += v.indirect.size_bytes() + v.records.size_bytes() + v.offsets.size_bytes();
  }
  return bytes;
}

}  // namespace relight

#include "runtime/portal_lighting.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "common/input_error.h"
#include "math/placement.h"
#include "math/sh.h"
#include "runtime/relighter.h"

namespace relight {

Environment environment_without_images(const EnvironmentSpec& spec) {
  if (spec.type == EnvironmentType::kMap) {
    fail_input(spec.where, "map environments need their image loaded (not available here)");
  }
  return make_environment(spec);
}

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
      positions.push_back(placed_point(x, g.pivot, p.rotate_deg, p.translate));
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
                            int sh_order, const PortalState& state, const Scene& scene,
                            const EnvironmentLoader& load) {
  const auto start = std::chrono::steady_clock::now();
  const Environment environment = [&] {
    try {
      return load(state.environment);
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

}  // namespace relight

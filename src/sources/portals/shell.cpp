// The run-time shell of a portal: environment, exterior, frost, tint, SH; see
// sources/portals/shell.h.
#include "sources/portals/shell.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "light/environment_irradiance.h"
#include "math/cubemap.h"
#include "math/sh.h"

namespace relight {

namespace {

bool finite_non_negative(Rgb c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && c.r >= 0 && c.g >= 0 &&
         c.b >= 0;
}

bool has_triangles(std::span<const ExteriorObject> exterior) {
  for (const ExteriorObject& o : exterior)
    if (!o.triangles.empty()) return true;
  return false;
}

// Diffusing glass: what passes, (1/π)·Σ L·cos·Ω over the texels in front, shown evenly in every
// direction in front of the glass.
void diffuse_through_glass(int face_size, Vec3 outward, Shell& shell) {
  const std::vector<Vec3>& directions = cubemap_texel_directions(face_size);
  const std::vector<double>& omega = cubemap_solid_angles(face_size);
  const auto face_texels = static_cast<std::size_t>(face_size) * face_size;
  Rgb flux;
  for (std::size_t t = 0; t < shell.cubemap.size(); ++t) {
    const double c = dot(directions[t], outward);
    if (c > 0) flux += shell.cubemap[t] * (c * omega[t % face_texels]);
  }
  const Rgb diffuse = flux * (1 / kPi);
  for (std::size_t t = 0; t < shell.cubemap.size(); ++t) {
    shell.cubemap[t] = dot(directions[t], outward) > 0 ? diffuse : Rgb{};
  }
}

}  // namespace

void render_shell(const ShellInputs& inputs, const PortalFrame& portal, int face_size, int sh_order,
                  Shell& shell, ShellWorkspace& workspace) {
  if (!inputs.environment) throw std::invalid_argument("shell: no environment");
  if (face_size < 1 || sh_order < 1)
    throw std::invalid_argument("shell: face size and SH order must be >= 1");
  if (!finite_non_negative(inputs.tint))
    throw std::invalid_argument("shell: tint must be finite and >= 0");
  if (!std::isfinite(inputs.frost_deg) || inputs.frost_deg < 0)
    throw std::invalid_argument("shell: frost_deg must be finite and >= 0");
  if (inputs.exterior_subrays < 1)
    throw std::invalid_argument("shell: exterior sub-rays per axis must be >= 1");
  if (!is_finite(portal.centre) || !is_finite(portal.outward) || !(length(portal.outward) > 0))
    throw std::invalid_argument(
        "shell: portal centre and outward normal must be finite, "
        "the normal non-zero");
  const Environment& env = *inputs.environment;
  const Environment continuous = environment_without_sun(env);
  const std::optional<SunDisc>& sun = env.sun();

  // 1. The environment's continuous part.
  shell.face_size = face_size;
  shell.cubemap = environment_cubemap(continuous, face_size);
  shell.exterior_texels = 0;

  // 2. Exterior objects, and whether the sun is seen past them.
  bool sun_seen = sun.has_value();
  if (has_triangles(inputs.exterior)) {
    const ExteriorScene scene = build_exterior_scene(inputs.exterior);
    const IrradianceSh sky = irradiance_sh(continuous);
    shell.exterior_texels =
        composite_exterior(scene, portal.centre, face_size, inputs.exterior_subrays, sky,
                           sun ? &*sun : nullptr, shell.cubemap);
    if (sun) sun_seen = sun_visible(scene, portal.centre, sun->direction);
  }
  // 2b. Glazing, the continuous part (the sun's share below).
  const std::vector<Vec3>& directions = cubemap_texel_directions(face_size);
  const Vec3 outward = normalize(portal.outward);
  if (inputs.glazing) {
    for (std::size_t t = 0; t < shell.cubemap.size(); ++t) {
      shell.cubemap[t] =
          shell.cubemap[t] * glazing_transmittance(*inputs.glazing, dot(directions[t], outward));
    }
  }
  shell.sun_in_shell = sun && sun_seen && inputs.sun_disc;
  shell.sun_texel = 0;
  shell.sun_radiance = Rgb{};
  if (shell.sun_in_shell) {
    const SunDeposit d = deposit_sun(*sun, face_size, shell.cubemap);
    double radiance = d.radiance;
    if (inputs.glazing) {
      // The disc through the glass at its own incidence: what the glass holds back, taken off.
      radiance *= glazing_transmittance(*inputs.glazing, dot(sun->direction, outward));
      const double held_back = d.radiance - radiance;
      Rgb& l = shell.cubemap[d.texel];
      l = {std::max(0.0, l.r - held_back), std::max(0.0, l.g - held_back),
           std::max(0.0, l.b - held_back)};
    }
    shell.sun_texel = d.texel;
    shell.sun_radiance = Rgb{radiance, radiance, radiance} * inputs.tint;
  }
  if (inputs.glazing && inputs.glazing->diffusing) diffuse_through_glass(face_size, outward, shell);

  // 3. Frosted glass.
  if (inputs.frost_deg > 0) {
    if (!frost_plan_matches(workspace.frost, face_size, portal.outward, inputs.frost_deg))
      make_frost_plan(face_size, portal.outward, inputs.frost_deg, workspace.frost);
    apply_frost(workspace.frost, shell.cubemap, workspace.frost_scratch);
  }

  // 4. SH of a grey cubemap (a sky, no exterior object): its one channel projected, then
  // tinted — a third of the work of 5 (every hour of `relight annual` makes a shell).
  shell.sh_order = sh_order;
  // Texels the SH leaves out: those behind the portal's plane, for sh_outward_half.
  const auto left_out = [&](std::size_t t) {
    return inputs.sh_outward_half && dot(directions[t], portal.outward) <= 0;
  };
  const bool grey = std::all_of(shell.cubemap.begin(), shell.cubemap.end(),
                                [](const Rgb& l) { return l.r == l.g && l.r == l.b; });
  if (grey) {
    std::vector<double>& values = workspace.grey_scratch;
    values.resize(shell.cubemap.size());
    for (std::size_t t = 0; t < values.size(); ++t) {
      values[t] = left_out(t) ? 0.0 : shell.cubemap[t].r;
    }
    const std::vector<double> c =
        sh_project_cubemap(sh_order, face_size, std::span<const double>(values));
    shell.sh.resize(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) shell.sh[k] = inputs.tint * c[k];
  }

  // 5. Tint.
  for (Rgb& l : shell.cubemap) l = l * inputs.tint;
  if (grey) return;

  // 6. SH of the final cubemap, or of its outward half.
  if (!inputs.sh_outward_half) {
    shell.sh = sh_project_cubemap(sh_order, face_size, std::span<const Rgb>(shell.cubemap));
    return;
  }
  std::vector<Rgb>& half = workspace.sh_scratch;
  half = shell.cubemap;
  for (std::size_t t = 0; t < half.size(); ++t) {
    if (left_out(t)) half[t] = Rgb{};
  }
  shell.sh = sh_project_cubemap(sh_order, face_size, std::span<const Rgb>(half));
}

Shell render_shell(const ShellInputs& inputs, const PortalFrame& portal, int face_size,
                   int sh_order) {
  Shell shell;
  ShellWorkspace workspace;
  render_shell(inputs, portal, face_size, sh_order, shell, workspace);
  return shell;
}

}  // namespace relight

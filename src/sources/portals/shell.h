// The run-time shell of one portal (Yue et al. 2009 §3, §5, §6): the exterior seen
// from the portal centre, re-rendered at every state change into the two representations the
// run time needs — a radiance cubemap (math/cubemap.h layout, per-texel average radiance, for
// the direct portal transfer: sources/portals/cubemap_encoding.h prepare_shell_cubemap) and its
// real SH projection (math/sh.h, for the SH-encoded indirect transfer). §5: "we first capture the
// environmental light distribution for each shell [...] The environmental light distribution is
// then modified according to the change in the material of the portal, if necessary. Next, we
// represent the environmental light distribution in spherical harmonics bases, cubemap
// representation and wavelet bases."
//
// Pipeline, in this order:
//  1. Base: light/environment.h environment_cubemap of the environment's continuous part
//     (light/environment_irradiance.h environment_without_sun); the sun disc's ∫ L dω deposited
//     into the texel containing it (so with nothing else this is exactly environment_cubemap).
//  2. Exterior (light/exterior_objects.h), when exterior objects are given: ray-cast from
//  the
//     centre, k×k sub-rays per texel, shaded Lambertian under sun + R&H sky irradiance; the sun
//     disc is deposited only when the ray from the centre toward it escapes the objects.
//  2b. Glazing (math/glazing.h), when given: every texel × the panes' transmittance at its
//     incidence on the glass (cos = direction · outward; 0 behind the glass), the sun disc ×
//     the transmittance at its own. Diffusing glazing then spreads what it transmits evenly:
//     every texel in front of the glass shows L_d = (1/π)·Σ L·T·cos·Ω, the flux per area through
//     the glass as a Lambertian luminance (the sun disc included: it is never traced apart),
//     and nothing behind.
//  3. Frost (sources/portals/shell_frost.h): flux-preserving von Mises–Fisher blur in the portal
//  frame.
//  4. Tint: every texel × tint, exactly (the last change to the cubemap, so cubemap[i] is
//     bit-for-bit untinted[i]·tint; tint and frost commute, being linear per channel).
//  5. SH: math/cubemap.h sh_project_cubemap of the final cubemap (or of its outward half, with
//     ShellInputs::sh_outward_half), so both representations agree to the projection's
//     quadrature (c_lm = Σ L·Y_lm(centre)·Ω).
// A pure function of its inputs. ShellWorkspace keeps what is reusable between calls (the frost
// plan, which depends only on face size, outward normal and frost width).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "light/environment.h"
#include "light/exterior_objects.h"
#include "math/cubemap.h"
#include "math/glazing.h"
#include "math/rgb.h"
#include "sources/portals/shell_frost.h"

namespace relight {

struct ShellInputs {
  const Environment* environment = nullptr;  // the sky / map / uniform exterior (required)
  Rgb tint{1, 1, 1};                         // window colour: multiplies the shell (≥ 0)
  double frost_deg = 0;  // frosted glass: angular standard deviation of the blur in degrees
                         // (sources/portals/shell_frost.h), 0 = clear
  const Glazing* glazing = nullptr;          // the panes (math/glazing.h); null: an opening
  std::span<const ExteriorObject> exterior;  // dynamic exterior geometry, may be empty
  int exterior_subrays = 3;                  // k: k×k sub-rays per texel for the exterior
  // Project only the half of the shell in front of the portal (ω · outward > 0) onto SH: the
  // rest cannot pass the portal, and in a band-limited projection a bright feature there
  // rings into directions that do (the relighter's indirect weights use this).
  bool sh_outward_half = false;
  // Deposit the sun disc (step 1). Off when the run time traces the sun itself behind clear
  // glass (sources/portals/portal_sun.h): the shell then holds the sky, the ground and the
  // exterior objects (still lit by the sun), and the sun's energy is in neither representation.
  bool sun_disc = true;
};

struct Shell {
  int face_size = 0;
  std::vector<Rgb> cubemap;  // 6·N² per-texel radiances, cd/m² (math/cubemap.h layout)
  int sh_order = 0;
  std::vector<Rgb> sh;        // sh_order² coefficients c_lm of the cubemap (math/sh.h), or
                              // of its outward half (ShellInputs::sh_outward_half)
  bool sun_in_shell = false;  // the sun disc was deposited (a sun exists, is unoccluded and
                              // ShellInputs::sun_disc)
  // What the sun added to cubemap[sun_texel], tint included (when sun_in_shell); frost then
  // spreads it over the texels around.
  std::size_t sun_texel = 0;
  Rgb sun_radiance;
  std::size_t exterior_texels = 0;  // texels any exterior sub-ray hit

  // The radiance the shell shows along a direction (its cubemap texel): what a window shows
  // a camera ray or a ray gathering through it.
  Rgb radiance(Vec3 direction) const {
    return cubemap[cubemap_texel_index(face_size, cubemap_texel(face_size, direction))];
  }
};

// Reused between calls so that a steady state allocates little.
struct ShellWorkspace {
  FrostPlan frost;
  std::vector<Rgb> frost_scratch;
  std::vector<Rgb> sh_scratch;       // the outward half, for sh_outward_half
  std::vector<double> grey_scratch;  // the same of a grey cubemap, one value a texel
};

// Renders the shell into `shell`, reusing its storage and the workspace. face_size ≥ 1 (32 is
// the transfer default), sh_order ≥ 1 (6: l < 6). std::invalid_argument for a null
// environment, bad sizes, a negative or non-finite tint or frost width, a zero outward normal,
// k < 1, or bad exterior objects.
void render_shell(const ShellInputs& inputs, const PortalFrame& portal, int face_size, int sh_order,
                  Shell& shell, ShellWorkspace& workspace);
Shell render_shell(const ShellInputs& inputs, const PortalFrame& portal, int face_size = 32,
                   int sh_order = 6);

}  // namespace relight

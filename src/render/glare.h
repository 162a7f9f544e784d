// Glare at an observer's eye looking along a view direction (`relight glare`):
//
//  * UGR, the unified glare rating (CIE 117-1995):
//      UGR = 8·log10( (0.25 / L_b) · Σ L²·ω / p² )
//    over the luminaires in front of the eye and above the line of sight, each seen unoccluded
//    from the eye: L = I / A_p and ω = A_p / r², so L²ω = I² / (A_p·r²), with I the luminaire's
//    intensity toward the eye (its photometry, aim, colour and dimmer as the state sets them;
//    the photometric Y), A_p its luminous opening projected toward the eye (the IES/LDT
//    dimensions or the scene's "size": the bottom face w·l·|cos γ| plus the luminous sides
//    h·(w·|sin γ sin C| + l·|sin γ cos C|), round openings π d²/4·|cos γ| + d·h·sin γ), r the
//    distance; L_b = E_ind / π, E_ind the vertical illuminance at the eye without the
//    luminaires' direct light; p the Guth position index below. No luminaire in view: no UGR.
//    A luminaire in view without a luminous area (a point source: an analytic distribution
//    without a "size") has no luminance: it is left out of UGR and DGP and listed as unrated
//    (its direct light still counts in E_v).
//  * DGP, daylight glare probability (Wienold & Christoffersen 2006, Eq. 9):
//      DGP = 5.87·10⁻⁵·E_v + 9.18·10⁻²·log10(1 + Σ L_s²·ω_s / (E_v^1.87·p²)) + 0.16,
//    E_v the vertical illuminance at the eye (lx), the sum over glare sources: every direction
//    of the view hemisphere brighter than 5 times its mean luminance E_v/π (the threshold
//    evalglare uses by default), windows, the sun's disc and luminaires alike. DGP is defined
//    from 0.2 up; values below it are reported as computed.
//  * The view: 2·n² directions of equal solid angle over the hemisphere in front of the eye
//    (stratified in cos θ and azimuth about the view direction, n = 96: ω = 2π/18432 each),
//    each shaded as `relight render` shades vertices (render/relit_scene_image.h: the room's
//    light interpolated, windows showing their shells). The direct light of every kind of
//    light is not sampled but exact (runtime/direct_light.h): luminaires, suns behind clear
//    glass, near-field emitters and a top-level environment's compact sources (its sun) add
//    their vertical illuminance at the eye, and each one in view is a glare source of its own
//    luminance and solid angle (a luminaire: I/A_p and A_p/r² as for UGR; a sun or compact
//    source: its disc's luminance times the fraction of it seen, over the disc; an emitter: its
//    luminance over the solid angle of its visible part). The view's directions do not show
//    what is counted exactly: windows show their shells without the suns, and directions
//    within a compact source's disc show nothing (emitters are not part of the traced mesh).
//  * Guth position index (Luckiesh & Guth 1949, in the form of Einhorn used by CIE 117 and
//    Wienold & Christoffersen):
//      ln p = (35.2 − 0.31889·τ − 1.22·e^(−2τ/9))·10⁻³·σ + (21 + 0.26667·τ − 0.002963·τ²)·10⁻⁵·σ²
//    σ the angle between the line of sight and the source, τ the angle between the vertical
//    and the plane through the line of sight and the source (degrees). For sources below the
//    line of sight (DGP's windows) τ is mirrored about the horizontal plane of sight (a choice:
//    the Guth index was fitted above it).
// Tests: tests/cli/glare_command_test.cpp (DGP of a window view and UGR of one luminaire by
// hand; UGR in the CIE 190:2010 standard room, 4H × 8H at 0.7/0.5/0.2 with a tabulated LDT
// luminaire at spacing 1:1, within 1 unit of the standard's tabular value: 24.56 against 24.06,
// the room's own interreflection giving a background 14 % darker than the table's flux transfer).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "math/vec3.h"
#include "runtime/relit_scene.h"

namespace relight {

struct GlareSource {
  // "luminaire", "sun", "emitter", "environment" (a top-level environment's compact source)
  // or "view": the view's directions above the threshold (windows, bright surfaces) together —
  // their solid angle, mean luminance and mean direction (the DGP sums them one by one).
  std::string kind;
  std::string name;        // the luminaire's, the portal's, the emitter's; "" for the others
  Vec3 direction;          // unit, from the eye
  double luminance = 0;    // cd/m²
  double solid_angle = 0;  // sr
  double position_index = 1;
};

struct GlareResult {
  std::optional<double> ugr;  // none without a luminaire in view
  double dgp = 0;
  double ev = 0;                    // vertical illuminance at the eye, lx
  double luminaire_direct_ev = 0;   // of which directly from luminaires
  double background_luminance = 0;  // L_b = (E_v − direct luminaire light) / π
  std::vector<GlareSource> sources;
  std::vector<std::string> unrated;  // luminaires in view without a luminous area
};

// The Guth position index of a source in the unit direction `source` seen from an eye
// looking along the unit `view` with the unit `up` (orthogonal to view).
double guth_position_index(Vec3 view, Vec3 up, Vec3 source);

// Needs a non-zero view direction.
GlareResult evaluate_glare(RelitScene& scene, Vec3 eye, Vec3 view, int n = 96);

}  // namespace relight

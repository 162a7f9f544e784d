// A luminaire's luminous intensity distribution, loaded and ready to evaluate: the
// analytic models of the scene format (docs/scene-format.md, "Distributions") or a
// measured type-C web read from an IES LM-63 or EULUMDAT file. All in candela, in the
// luminaire's own photometric frame.
//
// Frame: local z = aim (γ = 0), local x = the C0 half-plane direction, local y = the C90
// direction, so a unit local_dir = (sinγ cosC, sinγ sinC, cosγ). The scene format puts C90
// at cross(c0, aim) (LM-63: C counter-clockwise seen from behind the luminaire), which is
// minus the b axis of a right-handed math/frame.h Frame{t = c0, n = aim}: use
// local = (dot(d, c0), dot(d, cross(c0, aim)), dot(d, aim)), or C comes out mirrored.
//
// flux_lm() is the exact integral of what intensity() returns: closed forms for the
// analytic models, the per-cell closed form of the bilinear web (photometric_web.h).
#pragma once

#include <optional>
#include <variant>
#include <vector>

#include "light/photometric_web.h"
#include "math/vec3.h"
#include "scene/distribution_spec.h"

namespace relight {

struct IsotropicModel {
  double candela = 0;
};

// I = candela · cos^exponent γ for γ ≤ cutoff and cos γ > 0, else 0.
struct CosinePowerModel {
  double candela = 0;
  double exponent = 1;
  double cutoff_rad = kPi / 2;
};

// Axisymmetric, linear in γ between control points, 0 beyond the last one.
struct CurveModel {
  std::vector<double> gamma_rad;  // ascending from 0, last ≤ π, at least 2
  std::vector<double> candela;    // same length, ≥ 0
};

struct Distribution {
  std::variant<IsotropicModel, CosinePowerModel, CurveModel, PhotometricWeb> model;

  double intensity(double c_rad, double gamma_rad) const;
  double intensity(Vec3 local_dir) const;  // local_dir: unit vector in the frame above
  double flux_lm() const;
  std::optional<double> rated_lumens() const;  // from the file; none for analytic models
  std::optional<double> input_watts() const;   // from the file (W); none for analytic models
  LuminousOpening opening() const;             // a point for analytic models
  bool axisymmetric() const;
  double max_intensity() const;
};

// Validates the analytic parameters (errors at spec.where) or reads the IES / LDT file
// (errors at FILE:LINE of that file; a missing file is reported at spec.where).
Distribution load_distribution(const DistributionSpec& spec);

}  // namespace relight

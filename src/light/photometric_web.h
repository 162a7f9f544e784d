// A luminaire's measured luminous intensity distribution as a type-C photometric web
// (CIE 121:1996 / IES LM-75 C-γ coordinates: γ from the aim axis, C counter-clockwise
// about it from the C0 plane), in absolute candela, with every file symmetry already
// expanded so that C runs over the whole circle 0..360°. Both IES LM-63 and EULUMDAT
// files end up here, so everything downstream (SH projection, the reference path tracer,
// flux checks) sees one representation and one interpolation rule: bilinear in (C, γ),
// periodic in C, zero outside the measured γ range.
//
// The flux is the exact integral of that bilinear interpolant over the sphere (closed
// form per cell, see flux_lm), so it agrees with what intensity() returns to rounding.
#pragma once

#include <cstdint>

#include <optional>
#include <string_view>
#include <vector>

namespace relight {

// Luminous opening shapes: IES LM-63-2019 Table 1 (sign rules of width/length/height),
// plus the EULUMDAT rule (luminous width 0 = circular, diameter = length). LM-63 rows
// appear in table order. "Length" lies along the C0-C180 axis (local x), "width" along
// C90-C270 (local y), "height" along the aim axis (local z).
enum class OpeningShape {
  kPoint,                                    //  0   0   0
  kRectangular,                              //  W   L   0
  kRectangularWithLuminousSides,             //  W   L   H
  kCircular,                                 // -D  -D   0
  kEllipse,                                  // -W  -L   0
  kVerticalCylinder,                         // -D  -D   H
  kVerticalEllipticalCylinder,               // -W  -L   H
  kSphere,                                   // -D  -D  -D
  kEllipsoidalSpheroid,                      // -W  -L  -H
  kHorizontalCylinderAlongLength,            // -D   L  -D   (axis along C0-C180)
  kHorizontalEllipticalCylinderAlongLength,  // -W   L  -H
  kHorizontalCylinderAlongWidth,             //  W  -D  -D   (axis along C90-C270)
  kHorizontalEllipticalCylinderAlongWidth,   //  W  -L  -H
  kVerticalCircleFacingC0,                   // -D   0  -D
  kVerticalEllipseFacingC0,                  // -W   0  -H
  kVerticalCircleFacingC90,                  //  0  -D  -D   (mirror of the row above)
  kVerticalEllipseFacingC90,                 //  0  -L  -H
  // A sign pattern LM-63 does not define (e.g. "-W L H"); treat as a |W|×|L|×|H| box.
  kIrregular,
};

std::string_view to_string(OpeningShape shape);

// Photometric files are small; anything larger is not one (and is not read whole).
inline constexpr std::uintmax_t kMaxPhotometryFileBytes = 64u << 20;

struct LuminousOpening {
  OpeningShape shape = OpeningShape::kPoint;
  double width_m = 0;  // magnitudes in metres, ≥ 0
  double length_m = 0;
  double height_m = 0;
};

// Classifies IES LM-63 dimensions (signed, already converted to metres). Pre-2002 files
// wrote a round opening as a negative width with zero length ("-D 0 0"); patterns outside
// Table 1 of that kind are read as circular / vertical cylinder, anything else as
// kIrregular.
LuminousOpening ies_luminous_opening(double width_m, double length_m, double height_m);

// IES LM-63 TILT block: candela multipliers as a function of the luminaire's tilt from
// its measured orientation. Kept, not applied: the tilt belongs to the installation.
struct TiltTable {
  int lamp_to_luminaire_geometry = 1;  // 1 vertical lamp, 2 horizontal along C0-C180,
                                       // 3 horizontal along C90-C270
  std::vector<double> angles_deg;      // ascending
  std::vector<double> factors;         // same length
};

// Multiplier for a luminaire tilted by tilt_deg: linear between table entries, held
// constant beyond the ends; 1 for an empty table.
double tilt_factor(const TiltTable& table, double tilt_deg);

struct PhotometricWeb {
  std::vector<double> c_deg;      // ascending, front() == 0, back() == 360 (same plane as 0)
  std::vector<double> gamma_deg;  // ascending, within [0, 180], at least 2 angles
  std::vector<double> candela;    // c_deg.size() × gamma_deg.size(), C-major
  // Luminaire lumens the file states or implies for relative photometry; absent for
  // absolute photometry without a stated flux.
  std::optional<double> rated_lumens;
  // Electrical input power the file states (IES input watts, EULUMDAT first lamp set's wattage
  // with ballast), W; absent when the file gives none (zero or negative).
  std::optional<double> input_watts;
  bool absolute_photometry = false;
  LuminousOpening opening;
  std::optional<TiltTable> tilt;  // IES TILT=INCLUDE / TILT=<file>

  double at(std::size_t ic, std::size_t ig) const { return candela[ic * gamma_deg.size() + ig]; }
};

// How the stored C planes of a file relate to the full circle.
enum class CSymmetry {
  kNone,              // planes as given; C wraps around from the last plane to 360 = 0
  kAxial,             // one plane for every C
  kQuadrant,          // planes 0..90, mirrored about the C0-C180 and C90-C270 planes
  kBilateralC0C180,   // planes 0..180, mirrored about the C0-C180 plane: I(C) = I(360-C)
  kBilateralC90C270,  // planes on one side of C90-C270, mirrored: I(C) = I(180-C)
};

// Builds the web from stored planes: stored_candela holds stored_c_deg.size() planes of
// gamma_deg.size() values (C-major), in candela. Mirrored planes are copies of the stored
// values (bit-exact). Precondition (checked, std::invalid_argument): finite ascending
// angles, γ within [0, 180] with ≥ 2 values, C within [0, 360], sizes consistent. File
// parsers validate first and report bad files as InputError.
PhotometricWeb make_web(const std::vector<double>& stored_c_deg,
                        const std::vector<double>& gamma_deg,
                        const std::vector<double>& stored_candela, CSymmetry symmetry);

// Candela in direction (C, γ) in radians; any real angles (γ outside [0, π] is folded
// back onto the sphere). Zero outside the web's γ range.
double intensity(const PhotometricWeb& web, double c_rad, double gamma_rad);

// ∫ I dω over the sphere of the bilinear interpolant, in lumens (exact per cell).
double flux_lm(const PhotometricWeb& web);

double max_intensity(const PhotometricWeb& web);

// True when every C plane holds the same values (rotationally symmetric data).
bool is_axisymmetric(const PhotometricWeb& web);

}  // namespace relight

// What a lighting designer reads off a photometric file before choosing it: who makes the
// luminaire, its output and power, its peak intensity and beam, its symmetry and luminous
// opening. `relight info FILE.ies|FILE.ldt` prints it as one JSON line and the studio's
// catalogue lists it.
//
// Definitions, and why:
// - lumens: ∫ I dω of the web as relight lights it (photometric_web.h, flux_lm), so the
//   figure is the light the scene receives, not a label that may disagree with the table.
// - lor (light output ratio): lumens / lamp lumens (IES lamps × lumens per lamp, EULUMDAT
//   the first lamp set's flux); absent for absolute photometry, which states no lamp.
// - watts: the file's input power (IES input watts, EULUMDAT first set's watts with
//   ballast); absent when the file gives none.
// - beam and field angle: the full angle within which the intensity stays at or above 50 %
//   and 10 % of the peak (CIE 43 / IES definitions), measured from the axis of the half
//   (down or up) that holds the peak. In each C half-plane the outermost crossing γ is
//   found on the web's own γ grid (the web is linear in γ between its angles); the figure
//   is twice the mean over 360 half-planes 1° apart, so an asymmetric file gets the angle
//   of the rotationally averaged beam.
// Pinned by tests/light/photometry_summary_test.cpp.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "light/photometric_web.h"

namespace relight {

struct PhotometrySummary {
  std::string format;        // "IES LM-63-2002", "EULUMDAT", ...
  std::string manufacturer;  // IES [MANUFAC], EULUMDAT company
  std::string catalogue;     // IES [LUMCAT], EULUMDAT luminaire number
  std::string luminaire;     // IES [LUMINAIRE], EULUMDAT luminaire name
  double lumens = 0;
  std::optional<double> watts;
  std::optional<double> lor;
  double max_cd = 0;
  double beam_angle_deg = 0;
  double field_angle_deg = 0;
  CSymmetry symmetry = CSymmetry::kNone;
  LuminousOpening opening;
  bool absolute_photometry = false;
  // The polar plot of a catalogue: candela at γ = 0, 5, …, 180° in the half-planes C0, C90,
  // C180 and C270 (kPolarStepDeg apart).
  std::array<std::vector<double>, 4> polar_cd;
};

inline constexpr int kPolarStepDeg = 5;

// The full angle (degrees) within which the web's intensity stays at or above
// `fraction` of its peak, as defined in the header comment.
double spread_angle_deg(const PhotometricWeb& web, double fraction);

// True when the name ends in .ies or .ldt (any case).
bool is_photometry_file(const std::filesystem::path& file);

// Parses `text` as IES LM-63 or EULUMDAT, chosen by the extension of `file` (.ies, .ldt in
// any case); InputError "FILE: ..." for any other extension and the parser's FILE:LINE
// message for a bad file.
PhotometrySummary summarize_photometry(std::string_view text, const std::filesystem::path& file);

// Reads the file (size-capped like every photometric file) and summarizes it.
PhotometrySummary summarize_photometry_file(const std::filesystem::path& file);

// One JSON object with the keys of `relight info FILE.ies` (docs/cli.md).
nlohmann::json to_json(const PhotometrySummary& summary);

// The polar plot as {"gamma_deg": [...], "c0": [...], "c90": [...], "c180": [...], "c270": [...]}.
nlohmann::json polar_json(const PhotometrySummary& summary);

std::string_view to_string(CSymmetry symmetry);

}  // namespace relight

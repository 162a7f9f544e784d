// IES LM-63 photometric files (LM-63-1986/1991/1995, -2002 and -2019 — the numeric
// layout is the same in all of them): header lines and [KEYWORD]s up to the TILT= line,
// the optional tilt block, then a stream of numbers separated by whitespace or commas
// that may wrap across lines anywhere.
//
// Choices, and why:
// - Photometric type C only. Types B (floodlight, horizontal polar axis) and A
//   (automotive) are rejected with a clear message rather than converted, because a
//   wrong axis convention would silently mis-aim the light.
// - Candela = file value × candela multiplier × ballast factor. The field after the
//   ballast factor changed meaning: the "ballast-lamp photometric factor" of LM-63-1995
//   and earlier (applied too, like the ballast factor), "future use" in -2002 and the
//   *file generation type* in -2019 (a code such as 1.10000, never a multiplier: applying
//   it over-scales by up to 11%). It is kept in IesData but only applied for ≤1995 files.
// - TILT=INCLUDE and TILT=<file> (resolved next to the IES file) are parsed and kept in
//   the web, not applied: the multipliers depend on how the luminaire is installed, which
//   the file cannot know. tilt_factor() evaluates them when a scene supplies the tilt.
// - Symmetry from the horizontal angles (LM-63-2019 §5.9): one angle → axial, 0..90 →
//   quadrant, 0..180 → bilateral about C0-C180, 90..270 → bilateral about C90-C270,
//   0..(>180) → none. Other layouts are errors.
// - Rated lumens = number of lamps × lumens per lamp (the lamp lumens the relative data
//   refer to; the luminaire's own output is that times its efficiency). Absolute
//   photometry (lumens per lamp -1, or any value ≤ 0) has no rated lumens.
// - Everything that is not a valid file is an InputError "FILE:LINE: reason", LINE being
//   the line where the problem shows (the last line for a file that ends early). Extra
//   numbers after the candela table mean the declared counts are wrong, and are errors.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "light/photometric_web.h"

namespace relight {

enum class IesVersion { kLm63_1986, kLm63_1991, kLm63_1995, kLm63_2002, kLm63_2019, kUnknown };

struct IesKeyword {
  std::string name;   // upper case, without brackets
  std::string value;  // [MORE] lines are appended to the previous keyword, '\n'-separated
};

// The file's content as stated, before any scaling.
struct IesData {
  IesVersion version = IesVersion::kLm63_1986;
  std::string version_line;  // the first line when it names the standard
  std::vector<IesKeyword> keywords;
  std::string tilt = "NONE";  // "NONE", "INCLUDE" or the file name after TILT=
  std::optional<TiltTable> tilt_table;
  int lamp_count = 1;
  double lumens_per_lamp = -1;  // ≤ 0: absolute photometry
  double candela_multiplier = 1;
  int photometric_type = 1;                  // 1 = C (the only one accepted)
  int units = 2;                             // 1 = feet, 2 = metres
  double width = 0, length = 0, height = 0;  // luminous opening, file units, signed
  double ballast_factor = 1;
  double ballast_lamp_factor = 1;  // see the header comment: meaning depends on version
  double input_watts = 0;
  std::vector<double> vertical_deg;    // γ
  std::vector<double> horizontal_deg;  // C
  std::vector<double> candela;         // file values, horizontal-major: all γ for each C in turn
  CSymmetry symmetry = CSymmetry::kNone;
};

// Parses IES text; `file` names it in messages and locates a TILT=<file> file.
IesData parse_ies(std::string_view text, const std::filesystem::path& file);

// Factor from file values to candela (multiplier × ballast factor, × ballast-lamp
// photometric factor for LM-63-1995 and earlier).
double ies_candela_scale(const IesData& data);

std::optional<double> ies_rated_lumens(const IesData& data);

PhotometricWeb make_ies_web(const IesData& data);

// Reads and parses the file (InputError on any problem, including a missing file).
PhotometricWeb load_ies(const std::filesystem::path& file);

}  // namespace relight

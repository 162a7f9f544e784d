// EULUMDAT (.ldt) photometric files (Stockmar 1990, "EULUMDAT/2" 1998): one field per
// line, in a fixed order, intensities in cd per 1000 lm of lamp flux.
//
// Choices, and why:
// - Stored C planes by Isym (the EULUMDAT Mc1..Mc2 rule): 0 → all Mc; 1 → one plane;
//   2 → C0..C180 (Mc/2+1 planes); 3 → C270..C(360-Dc) then C0..C90 (Mc/2+1 planes);
//   4 → C0..C90 (Mc/4+1 planes). The stored planes must sit at the angles the rule implies
//   (180 for Isym 2, 90/270 for Isym 3 and 4), else the file is refused.
// - Candela = value × CFLI (line 24, "conversion factor for luminous intensities"; 0 is read
//   as unset = 1) × Φ/1000 with Φ the total lamp flux of the first lamp set: the standard
//   set the relative data refer to (further sets are alternatives, kept but unused).
// - Absolute photometry (DIAL / Lighting Analysts / Ashdown convention of 2009, adopted by
//   DIALux and AGi32): a negative number of lamps in the first set marks it; the "lamp
//   flux" field then holds the luminaire's measured flux, LORL is 100 % and intensities are
//   still cd/klm of that flux. So the same conversion gives absolute candela either way.
// - Rated lumens = LORL/100 × Φ: the luminaire flux the file implies (for absolute
//   photometry this is the measured luminaire flux). Absent when LORL ≤ 0.
// - Lamp-set fields come in two orders in the wild: the standard one field at a time for
//   all n sets (n counts, n types, n fluxes, ...) and one set at a time (count, type, flux,
//   colour, CRI, watts per set). Both are accepted; the standard order wins a tie.
// - Dimensions are mm → metres. Luminous opening: length 0 and width 0 → point; width 0 →
//   circular of diameter = length (vertical cylinder when a luminous height is given);
//   else rectangular (with luminous sides when a height is given). The height is the
//   largest of the four C-plane heights. Length is mapped to the web's length (C0-C180
//   axis), width to its width, as IES ↔ EULUMDAT converters do.
// - Dc and Dg (lines 5 and 7) are informational: files in the wild contradict their own
//   angle lists (e.g. Dc 90 with 15° planes), so only the listed angles are used.
// - Numbers may use a decimal comma ("12,5"). Problems are InputError "FILE:LINE: reason";
//   non-empty lines after the last intensity mean Mc/Ng/Isym do not match the data.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "light/photometric_web.h"

namespace relight {

struct LdtLampSet {
  int count = 1;  // negative: absolute photometry
  std::string type;
  double flux_lm = 0;  // total luminous flux of the set's lamps
  std::string colour;
  std::string colour_rendering;
  double watts = 0;  // including ballast
};

// The file's content as stated (intensities in cd/klm, lengths in mm).
struct LdtData {
  std::string company;
  int ityp = 1;
  int isym = 0;
  int mc = 0;
  double dc = 0;
  int ng = 0;
  double dg = 0;
  std::string report_number, luminaire_name, luminaire_number, file_name, date_user;
  double length_mm = 0, width_mm = 0, height_mm = 0;     // luminaire
  double luminous_length_mm = 0, luminous_width_mm = 0;  // luminous area
  std::array<double, 4> luminous_height_mm{};            // at C0, C90, C180, C270
  double dff_percent = 0, lorl_percent = 0;
  double conversion_factor = 1;
  double tilt_deg = 0;
  std::vector<LdtLampSet> lamp_sets;
  bool lamp_sets_one_set_at_a_time = false;
  std::array<double, 10> direct_ratios{};
  std::vector<double> c_deg;        // Mc angles
  std::vector<double> gamma_deg;    // Ng angles
  std::vector<double> intensities;  // stored planes × Ng, cd/klm, in file order
};

// Parses EULUMDAT text; `file` names it in messages.
LdtData parse_ldt(std::string_view text, const std::filesystem::path& file);

// Indices into c_deg of the stored planes, in the order the file stores them.
std::vector<std::size_t> ldt_stored_planes(const LdtData& data);

// Factor from the file's cd/klm values to candela.
double ldt_candela_scale(const LdtData& data);

std::optional<double> ldt_rated_lumens(const LdtData& data);

bool ldt_absolute_photometry(const LdtData& data);

LuminousOpening ldt_luminous_opening(const LdtData& data);

PhotometricWeb make_ldt_web(const LdtData& data);

// Reads and parses the file (InputError on any problem, including a missing file).
PhotometricWeb load_ldt(const std::filesystem::path& file);

}  // namespace relight

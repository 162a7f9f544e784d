// EULUMDAT reader (field list: Stockmar 1990/1998, as tabulated by AGi32's and Helios32's
// format pages); conventions and choices are listed in ldt_parser.h.
#include "light/ldt_parser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <string>

#include "common/input_error.h"
#include "common/read_file.h"
#include "light/number_text.h"

namespace relight {
namespace {

constexpr long long kMaxPlanes = 100000;
constexpr long long kMaxLampSets = 1000;

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t eol = text.find('\n', start);
    const std::size_t end = eol == std::string_view::npos ? text.size() : eol;
    lines.push_back(trim(text.substr(start, end - start)));
    start = end + 1;
  }
  return lines;
}

// EULUMDAT numbers may carry a decimal comma.
std::string with_decimal_point(std::string_view s) {
  std::string out(s);
  if (out.find('.') == std::string::npos && std::count(out.begin(), out.end(), ',') == 1) {
    std::replace(out.begin(), out.end(), ',', '.');
  }
  return out;
}

std::optional<double> ldt_number(std::string_view s) {
  return parse_finite_number(with_decimal_point(s));
}
std::optional<long long> ldt_integer(std::string_view s) {
  return parse_integer(with_decimal_point(s));
}

std::string format_number(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// Line-by-line reader failing with FILE:LINE messages.
struct LineReader {
  std::vector<std::string_view> lines;
  std::filesystem::path file;
  std::size_t pos = 0;

  int last_line() const { return std::max<int>(1, static_cast<int>(lines.size())); }
  int line_no() const { return static_cast<int>(pos); }  // of the line read last

  [[noreturn]] void fail_at(int line, const std::string& reason) const {
    fail_input(at_line(file, line), reason);
  }

  std::string_view text(const std::string& what) {
    if (pos >= lines.size()) {
      fail_at(last_line(),
              "unexpected end of file: expected " + what + " on line " + std::to_string(pos + 1));
    }
    return lines[pos++];
  }

  double number(const std::string& what) {
    const std::string_view s = text(what);
    const auto v = ldt_number(s);
    if (!v)
      fail_at(line_no(), "expected " + what + " (a number), found '" + printable_token(s) + "'");
    return *v;
  }

  long long integer(const std::string& what) {
    const std::string_view s = text(what);
    const auto v = ldt_integer(s);
    if (!v) {
      fail_at(line_no(), "expected " + what + " (an integer), found '" + printable_token(s) + "'");
    }
    return *v;
  }

  double non_negative(const std::string& what) {
    const double v = number(what);
    if (v < 0) fail_at(line_no(), what + " must not be negative, found " + format_number(v));
    return v;
  }
};

// Whether the 6·n lines at `first` read as lamp sets in the given order.
bool lamp_block_fits(const std::vector<std::string_view>& lines, std::size_t first, std::size_t n,
                     bool one_set_at_a_time) {
  auto at = [&](std::size_t field, std::size_t set) {
    return lines[first + (one_set_at_a_time ? 6 * set + field : field * n + set)];
  };
  for (std::size_t k = 0; k < n; ++k) {
    if (!ldt_integer(at(0, k)) || !ldt_number(at(2, k)) || !ldt_number(at(5, k))) return false;
  }
  return true;
}

void read_lamp_sets(LineReader& in, LdtData& data, std::size_t n) {
  const std::size_t first = in.pos;
  if (first + 6 * n > in.lines.size()) {
    in.fail_at(in.last_line(), "unexpected end of file: expected " + std::to_string(6 * n) +
                                   " lines of lamp data for " + std::to_string(n) + " lamp sets");
  }
  data.lamp_sets_one_set_at_a_time = n > 1 && !lamp_block_fits(in.lines, first, n, false) &&
                                     lamp_block_fits(in.lines, first, n, true);
  data.lamp_sets.assign(n, LdtLampSet{});
  // Visit the 6·n lines in file order; each belongs to (field, set) per the layout.
  for (std::size_t i = 0; i < 6 * n; ++i) {
    const std::size_t field = data.lamp_sets_one_set_at_a_time ? i % 6 : i / n;
    const std::size_t set = data.lamp_sets_one_set_at_a_time ? i / 6 : i % n;
    LdtLampSet& lamp = data.lamp_sets[set];
    const std::string label = " of lamp set " + std::to_string(set + 1);
    switch (field) {
      case 0:
        lamp.count = static_cast<int>(in.integer("the number of lamps" + label));
        break;
      case 1:
        lamp.type = std::string(in.text("the lamp type" + label));
        break;
      case 2:
        lamp.flux_lm = in.non_negative("the total lamp flux" + label);
        break;
      case 3:
        lamp.colour = std::string(in.text("the colour appearance" + label));
        break;
      case 4:
        lamp.colour_rendering = std::string(in.text("the colour rendering group" + label));
        break;
      case 5:
        lamp.watts = in.number("the wattage" + label);
        break;
    }
  }
}

std::vector<double> read_angles(LineReader& in, std::size_t n, const std::string& what, double lo,
                                double hi) {
  std::vector<double> angles;
  angles.reserve(std::min(n, in.lines.size()));
  for (std::size_t i = 0; i < n; ++i) {
    const double a = in.number(what + " " + std::to_string(i + 1) + " of " + std::to_string(n));
    if (a < lo || a > hi) {
      in.fail_at(in.line_no(), what + " must lie in [" + format_number(lo) + ", " +
                                   format_number(hi) + "], found " + format_number(a));
    }
    if (!angles.empty() && !(a > angles.back())) {
      in.fail_at(in.line_no(), what + " must ascend strictly: " + format_number(a) + " follows " +
                                   format_number(angles.back()));
    }
    angles.push_back(a);
  }
  return angles;
}

std::size_t stored_plane_count(int isym, std::size_t mc) {
  switch (isym) {
    case 1:
      return 1;
    case 2:
    case 3:
      return mc / 2 + 1;
    case 4:
      return mc / 4 + 1;
    default:
      return mc;
  }
}

}  // namespace

LdtData parse_ldt(std::string_view text, const std::filesystem::path& file) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  LineReader in{split_lines(text), file};
  if (std::all_of(in.lines.begin(), in.lines.end(), [](std::string_view l) { return l.empty(); })) {
    fail_input(at_line(file, 1), "empty file");
  }
  LdtData d;
  d.company = std::string(in.text("the company identification"));
  const long long ityp = in.integer("the type indicator Ityp");
  if (ityp < 0 || ityp > 3) {
    in.fail_at(in.line_no(), "type indicator Ityp must be 0..3, found " + std::to_string(ityp));
  }
  d.ityp = static_cast<int>(ityp);
  const long long isym = in.integer("the symmetry indicator Isym");
  if (isym < 0 || isym > 4) {
    in.fail_at(in.line_no(), "symmetry indicator Isym must be 0..4, found " + std::to_string(isym));
  }
  d.isym = static_cast<int>(isym);
  const long long mc = in.integer("the number of C planes Mc");
  const int mc_line = in.line_no();
  if (mc < 1 || mc > kMaxPlanes) {
    in.fail_at(mc_line, "number of C planes Mc must be between 1 and " +
                            std::to_string(kMaxPlanes) + ", found " + std::to_string(mc));
  }
  if ((d.isym == 2 && mc % 2 != 0) || ((d.isym == 3 || d.isym == 4) && mc % 4 != 0)) {
    in.fail_at(mc_line, "Isym " + std::to_string(d.isym) + " needs Mc divisible by " +
                            (d.isym == 2 ? "2" : "4") + ", found Mc " + std::to_string(mc));
  }
  d.mc = static_cast<int>(mc);
  d.dc = in.number("the C plane distance Dc");
  const long long ng = in.integer("the number of intensities per C plane Ng");
  if (ng < 2 || ng > kMaxPlanes) {
    in.fail_at(in.line_no(), "number of intensities per C plane Ng must be between 2 and " +
                                 std::to_string(kMaxPlanes) + ", found " + std::to_string(ng));
  }
  d.ng = static_cast<int>(ng);
  d.dg = in.number("the gamma distance Dg");
  d.report_number = std::string(in.text("the measurement report number"));
  d.luminaire_name = std::string(in.text("the luminaire name"));
  d.luminaire_number = std::string(in.text("the luminaire number"));
  d.file_name = std::string(in.text("the file name"));
  d.date_user = std::string(in.text("the date/user"));
  d.length_mm = in.non_negative("the luminaire length");
  d.width_mm = in.non_negative("the luminaire width");
  d.height_mm = in.non_negative("the luminaire height");
  d.luminous_length_mm = in.non_negative("the luminous area length");
  d.luminous_width_mm = in.non_negative("the luminous area width");
  for (int i = 0; i < 4; ++i) {
    d.luminous_height_mm[i] =
        in.non_negative("the luminous area height at C" + std::to_string(90 * i));
  }
  d.dff_percent = in.number("the downward flux fraction DFF");
  d.lorl_percent = in.non_negative("the light output ratio LORL");
  d.conversion_factor = in.non_negative("the conversion factor for luminous intensities");
  d.tilt_deg = in.number("the tilt during measurement");
  const long long sets = in.integer("the number of lamp sets");
  if (sets < 1 || sets > kMaxLampSets) {
    in.fail_at(in.line_no(), "number of lamp sets must be between 1 and " +
                                 std::to_string(kMaxLampSets) + ", found " + std::to_string(sets));
  }
  const int first_lamp_line = in.line_no() + 1;
  read_lamp_sets(in, d, static_cast<std::size_t>(sets));
  if (!(d.lamp_sets.front().flux_lm > 0)) {
    const int flux_line =
        first_lamp_line +
        (d.lamp_sets_one_set_at_a_time || sets == 1 ? 2 : 2 * static_cast<int>(sets));
    in.fail_at(flux_line,
               "the first lamp set's flux must be positive: intensities are cd/klm "
               "of it");
  }
  for (std::size_t k = 0; k < d.direct_ratios.size(); ++k) {
    d.direct_ratios[k] = in.number("direct ratio " + std::to_string(k + 1) + " of 10");
  }
  d.c_deg = read_angles(in, d.mc, "C angle", 0, 360);
  d.gamma_deg = read_angles(in, d.ng, "gamma angle", 0, 180);

  // The stored planes must be where the symmetry puts them.
  const int c_first_line = in.line_no() - d.ng - d.mc + 1;
  auto require_angle = [&](std::size_t index, double expected) {
    if (d.c_deg[index] != expected) {
      in.fail_at(c_first_line + static_cast<int>(index),
                 "Isym " + std::to_string(d.isym) + " stores C planes up to " +
                     format_number(expected) + " degrees, but C angle " +
                     std::to_string(index + 1) + " is " + format_number(d.c_deg[index]));
    }
  };
  const std::size_t m = static_cast<std::size_t>(d.mc);
  if (d.isym >= 2) require_angle(0, 0);
  if (d.isym == 2) require_angle(m / 2, 180);
  if (d.isym == 3) {
    require_angle(m / 4, 90);
    require_angle(3 * m / 4, 270);
  }
  if (d.isym == 4) require_angle(m / 4, 90);

  const std::size_t planes = stored_plane_count(d.isym, m);
  const std::size_t count = planes * static_cast<std::size_t>(d.ng);
  d.intensities.reserve(std::min(count, in.lines.size()));
  for (std::size_t i = 0; i < count; ++i) {
    if (in.pos >= in.lines.size()) {
      in.fail_at(in.last_line(), "unexpected end of file after " + std::to_string(i) + " of " +
                                     std::to_string(count) + " luminous intensities (Isym " +
                                     std::to_string(d.isym) + " stores " + std::to_string(planes) +
                                     " C planes of Mc " + std::to_string(d.mc) + ", x Ng " +
                                     std::to_string(d.ng) + ")");
    }
    const double v = in.number("a luminous intensity");
    if (v < 0) {
      in.fail_at(in.line_no(), "negative luminous intensity " + format_number(v));
    }
    d.intensities.push_back(v);
  }
  for (std::size_t i = in.pos; i < in.lines.size(); ++i) {
    if (!in.lines[i].empty() && in.lines[i] != "\x1a") {
      in.fail_at(static_cast<int>(i) + 1, "unexpected content '" + printable_token(in.lines[i]) +
                                              "' after the " + std::to_string(count) +
                                              " luminous intensities: Isym, Mc (line 4) or Ng "
                                              "(line 6) do not match the data");
    }
  }
  return d;
}

std::vector<std::size_t> ldt_stored_planes(const LdtData& data) {
  const std::size_t m = data.c_deg.size();
  std::vector<std::size_t> planes;
  switch (data.isym) {
    case 1:
      planes.push_back(0);
      break;
    case 3:  // C270 .. C(360-Dc), then C0 .. C90
      for (std::size_t i = 3 * m / 4; i < m; ++i) planes.push_back(i);
      for (std::size_t i = 0; i <= m / 4; ++i) planes.push_back(i);
      break;
    default:
      planes.resize(stored_plane_count(data.isym, m));
      std::iota(planes.begin(), planes.end(), 0);
  }
  return planes;
}

double ldt_candela_scale(const LdtData& data) {
  const double cfli = data.conversion_factor > 0 ? data.conversion_factor : 1.0;
  const double flux = data.lamp_sets.empty() ? 0.0 : data.lamp_sets.front().flux_lm;
  return cfli * flux / 1000.0;
}

std::optional<double> ldt_rated_lumens(const LdtData& data) {
  if (data.lamp_sets.empty() || !(data.lorl_percent > 0)) return std::nullopt;
  return data.lorl_percent / 100.0 * data.lamp_sets.front().flux_lm;
}

bool ldt_absolute_photometry(const LdtData& data) {
  return !data.lamp_sets.empty() && data.lamp_sets.front().count < 0;
}

LuminousOpening ldt_luminous_opening(const LdtData& data) {
  const double l = data.luminous_length_mm / 1000.0;
  const double w = data.luminous_width_mm / 1000.0;
  const double h =
      *std::max_element(data.luminous_height_mm.begin(), data.luminous_height_mm.end()) / 1000.0;
  using S = OpeningShape;
  if (l == 0 && w == 0) return {S::kPoint, 0, 0, h};
  if (w == 0) return {h > 0 ? S::kVerticalCylinder : S::kCircular, l, l, h};
  return {h > 0 ? S::kRectangularWithLuminousSides : S::kRectangular, w, l, h};
}

PhotometricWeb make_ldt_web(const LdtData& data) {
  const std::size_t ng = data.gamma_deg.size();
  std::vector<std::size_t> order(ldt_stored_planes(data).size());
  std::iota(order.begin(), order.end(), 0);
  const std::vector<std::size_t> planes = ldt_stored_planes(data);
  // make_web wants ascending angles; Isym 3 stores C270.. first.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return data.c_deg[planes[a]] < data.c_deg[planes[b]];
  });
  const double scale = ldt_candela_scale(data);
  std::vector<double> c_deg, candela;
  for (const std::size_t k : order) {
    c_deg.push_back(data.c_deg[planes[k]]);
    for (std::size_t g = 0; g < ng; ++g) candela.push_back(data.intensities[k * ng + g] * scale);
  }
  CSymmetry symmetry = CSymmetry::kNone;
  switch (data.isym) {
    case 1:
      symmetry = CSymmetry::kAxial;
      break;
    case 2:
      symmetry = CSymmetry::kBilateralC0C180;
      break;
    case 3:
      symmetry = CSymmetry::kBilateralC90C270;
      break;
    case 4:
      symmetry = CSymmetry::kQuadrant;
      break;
    default:
      break;
  }
  PhotometricWeb web = make_web(c_deg, data.gamma_deg, candela, symmetry);
  web.rated_lumens = ldt_rated_lumens(data);
  if (!data.lamp_sets.empty() && data.lamp_sets.front().watts > 0) {
    web.input_watts = data.lamp_sets.front().watts;
  }
  web.absolute_photometry = ldt_absolute_photometry(data);
  web.opening = ldt_luminous_opening(data);
  return web;
}

PhotometricWeb load_ldt(const std::filesystem::path& file) {
  return make_ldt_web(parse_ldt(read_file(file, kMaxPhotometryFileBytes), file));
}

}  // namespace relight

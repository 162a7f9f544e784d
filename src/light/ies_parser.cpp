// IES LM-63 reader (LM-63-1995 §3, LM-63-2002 §5, LM-63-2019 §5 and Annex F for TILT);
// conventions and choices are listed in ies_parser.h.
#include "light/ies_parser.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "common/input_error.h"
#include "common/read_file.h"
#include "light/number_text.h"

namespace relight {
namespace {

constexpr double kFeetToMetres = 0.3048;
constexpr long long kMaxAngles = 100000;

struct Token {
  std::string_view text;
  int line;
};

bool is_separator(char ch) {
  return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n' || ch == '\f' || ch == '\v' ||
         ch == ',' || ch == '\x1a';  // \x1a: DOS end-of-file mark some writers leave
}

// Splits text into numbers-to-be on whitespace and commas, remembering each one's line.
std::vector<Token> tokenize(std::string_view text, int first_line) {
  std::vector<Token> tokens;
  int line = first_line;
  std::size_t i = 0;
  while (i < text.size()) {
    if (is_separator(text[i])) {
      if (text[i] == '\n') ++line;
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < text.size() && !is_separator(text[i])) ++i;
    tokens.push_back({text.substr(start, i - start), line});
  }
  return tokens;
}

int count_lines(std::string_view text) {
  int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  if (!text.empty() && text.back() != '\n') ++lines;
  return std::max(lines, 1);
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& ch : out) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return out;
}

// Sequential reader over the numeric part of a file, failing with FILE:LINE messages.
struct NumberStream {
  std::vector<Token> tokens;
  std::filesystem::path file;
  int last_line = 1;
  std::size_t pos = 0;

  bool done() const { return pos >= tokens.size(); }

  [[noreturn]] void fail_at(int line, const std::string& reason) const {
    fail_input(at_line(file, line), reason);
  }

  const Token& next(const std::string& what) {
    if (done()) fail_at(last_line, "unexpected end of file: expected " + what);
    return tokens[pos++];
  }

  double number(const std::string& what, int* line = nullptr) {
    const Token& t = next(what);
    if (line) *line = t.line;
    const auto v = parse_finite_number(t.text);
    if (!v) fail_at(t.line, "expected " + what + ", found '" + printable_token(t.text) + "'");
    return *v;
  }

  long long integer(const std::string& what, int* line = nullptr) {
    const Token& t = next(what);
    if (line) *line = t.line;
    const auto v = parse_integer(t.text);
    if (!v) {
      fail_at(t.line,
              "expected " + what + " (an integer), found '" + printable_token(t.text) + "'");
    }
    return *v;
  }

  // n numbers; a file ending early reports how many of them it had.
  std::vector<double> numbers(std::size_t n, const std::string& what, std::vector<int>* lines) {
    std::vector<double> out;
    out.reserve(std::min(n, tokens.size() - std::min(pos, tokens.size())));
    for (std::size_t i = 0; i < n; ++i) {
      if (done()) {
        fail_at(last_line, "unexpected end of file: expected " + std::to_string(n) + " " + what +
                               ", found " + std::to_string(i));
      }
      const Token& t = tokens[pos++];
      const auto v = parse_finite_number(t.text);
      if (!v) {
        fail_at(t.line, "expected a number (" + what + " " + std::to_string(i + 1) + " of " +
                            std::to_string(n) + "), found '" + printable_token(t.text) + "'");
      }
      out.push_back(*v);
      if (lines) lines->push_back(t.line);
    }
    return out;
  }
};

std::string format_number(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

IesVersion version_from_line(std::string_view line) {
  const std::string u = upper(line);
  if (u.find("2019") != std::string::npos) return IesVersion::kLm63_2019;
  if (u.find("2002") != std::string::npos) return IesVersion::kLm63_2002;
  if (u.find("1995") != std::string::npos) return IesVersion::kLm63_1995;
  if (u.find("IESNA91") != std::string::npos || u.find("1991") != std::string::npos) {
    return IesVersion::kLm63_1991;
  }
  return IesVersion::kUnknown;
}

TiltTable read_tilt_block(NumberStream& in) {
  TiltTable tilt;
  int line = 0;
  const long long geometry = in.integer("the tilt lamp-to-luminaire geometry", &line);
  if (geometry < 1 || geometry > 3) {
    in.fail_at(line, "tilt lamp-to-luminaire geometry must be 1, 2 or 3, found " +
                         std::to_string(geometry));
  }
  tilt.lamp_to_luminaire_geometry = static_cast<int>(geometry);
  const long long n = in.integer("the number of tilt angles", &line);
  if (n < 1 || n > kMaxAngles) {
    in.fail_at(line, "number of tilt angles must be between 1 and " + std::to_string(kMaxAngles) +
                         ", found " + std::to_string(n));
  }
  std::vector<int> lines;
  tilt.angles_deg = in.numbers(static_cast<std::size_t>(n), "tilt angles", &lines);
  for (std::size_t i = 1; i < tilt.angles_deg.size(); ++i) {
    if (!(tilt.angles_deg[i] > tilt.angles_deg[i - 1])) {
      in.fail_at(lines[i], "tilt angles must ascend: " + format_number(tilt.angles_deg[i]) +
                               " follows " + format_number(tilt.angles_deg[i - 1]));
    }
  }
  lines.clear();
  tilt.factors = in.numbers(static_cast<std::size_t>(n), "tilt multiplying factors", &lines);
  for (std::size_t i = 0; i < tilt.factors.size(); ++i) {
    if (tilt.factors[i] < 0) {
      in.fail_at(lines[i], "tilt multiplying factor must not be negative, found " +
                               format_number(tilt.factors[i]));
    }
  }
  return tilt;
}

std::vector<double> read_angles(NumberStream& in, std::size_t n, const std::string& what, double lo,
                                double hi) {
  std::vector<int> lines;
  std::vector<double> angles = in.numbers(n, what, &lines);
  for (std::size_t i = 0; i < angles.size(); ++i) {
    if (angles[i] < lo || angles[i] > hi) {
      in.fail_at(lines[i], what + " must lie in [" + format_number(lo) + ", " + format_number(hi) +
                               "], found " + format_number(angles[i]));
    }
    if (i > 0 && !(angles[i] > angles[i - 1])) {
      in.fail_at(lines[i], what + " must ascend strictly: " + format_number(angles[i]) +
                               " follows " + format_number(angles[i - 1]));
    }
  }
  return angles;
}

// The field after the ballast factor is a photometric factor only up to LM-63-1995.
bool ballast_lamp_factor_applies(IesVersion version) {
  return version == IesVersion::kLm63_1986 || version == IesVersion::kLm63_1991 ||
         version == IesVersion::kLm63_1995;
}

// LM-63-2019 §5.9 (type C): the horizontal angles say which part of the circle is stored.
CSymmetry symmetry_from_horizontal(const std::vector<double>& h, const NumberStream& in, int line) {
  if (h.size() == 1) return CSymmetry::kAxial;
  const double first = h.front(), last = h.back();
  if (first == 0) {
    if (last == 90) return CSymmetry::kQuadrant;
    if (last == 180) return CSymmetry::kBilateralC0C180;
    if (last > 180) return CSymmetry::kNone;
  } else if (first == 90 && last == 270) {
    return CSymmetry::kBilateralC90C270;
  }
  in.fail_at(line, "horizontal angles " + format_number(first) + ".." + format_number(last) +
                       " match no type C symmetry (LM-63: first angle 0 with last 0, 90, 180 "
                       "or above 180; or 90..270)");
}

}  // namespace

IesData parse_ies(std::string_view text, const std::filesystem::path& file) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  IesData data;
  const int total_lines = count_lines(text);
  if (trim(text).empty()) fail_input(at_line(file, 1), "empty file");

  // Header: everything up to the TILT= line.
  std::size_t offset = 0;
  int line_no = 0;
  std::optional<std::size_t> data_start;
  int tilt_line = 0;
  while (offset < text.size()) {
    const std::size_t eol = text.find('\n', offset);
    const std::size_t end = eol == std::string_view::npos ? text.size() : eol;
    const std::string_view line = trim(text.substr(offset, end - offset));
    ++line_no;
    offset = eol == std::string_view::npos ? text.size() : eol + 1;
    const std::string u = upper(line.substr(0, std::min<std::size_t>(line.size(), 64)));
    if (u.rfind("TILT", 0) == 0 && trim(std::string_view(u).substr(4)).rfind('=', 0) == 0) {
      const std::size_t eq = line.find('=');
      data.tilt = std::string(trim(line.substr(eq + 1)));
      tilt_line = line_no;
      data_start = offset;
      break;
    }
    if (line_no == 1 && u.rfind("IES", 0) == 0) {
      data.version_line = std::string(line);
      data.version = version_from_line(line);
      continue;
    }
    if (!line.empty() && line.front() == '[') {
      const std::size_t close = line.find(']');
      if (close != std::string_view::npos) {
        const std::string name = upper(trim(line.substr(1, close - 1)));
        const std::string value(trim(line.substr(close + 1)));
        if (name == "MORE" && !data.keywords.empty()) {
          data.keywords.back().value += "\n" + value;
        } else {
          data.keywords.push_back({name, value});
        }
      }
    }
  }
  if (!data_start) {
    fail_input(at_line(file, total_lines),
               "no TILT= line: LM-63 requires TILT=NONE, TILT=INCLUDE or TILT=<file> before "
               "the photometric data");
  }

  NumberStream in{tokenize(text.substr(*data_start), tilt_line + 1), file, total_lines};

  const std::string tilt_mode = upper(data.tilt);
  if (data.tilt.empty()) {
    in.fail_at(tilt_line, "TILT= names nothing: expected NONE, INCLUDE or a file name");
  } else if (tilt_mode == "INCLUDE") {
    data.tilt_table = read_tilt_block(in);
  } else if (tilt_mode != "NONE") {
    const std::filesystem::path tilt_file = file.parent_path() / data.tilt;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(tilt_file, ec)) {
      in.fail_at(tilt_line,
                 "TILT file '" + data.tilt + "' not found (looked for " + tilt_file.string() + ")");
    }
    const std::string tilt_text = read_file(tilt_file, kMaxPhotometryFileBytes);
    NumberStream tilt_in{tokenize(tilt_text, 1), tilt_file, count_lines(tilt_text)};
    data.tilt_table = read_tilt_block(tilt_in);
  }

  int line = 0;
  const long long lamps = in.integer("the number of lamps", &line);
  if (lamps < 1) {
    in.fail_at(line, "number of lamps must be at least 1, found " + std::to_string(lamps));
  }
  data.lamp_count = static_cast<int>(lamps);
  data.lumens_per_lamp = in.number("lumens per lamp");
  data.candela_multiplier = in.number("the candela multiplier", &line);
  if (!(data.candela_multiplier > 0)) {
    in.fail_at(line, "candela multiplier must be positive, found " +
                         format_number(data.candela_multiplier));
  }
  int nv_line = 0, nh_line = 0;
  const long long nv = in.integer("the number of vertical angles", &nv_line);
  if (nv < 2 || nv > kMaxAngles) {
    in.fail_at(nv_line, "number of vertical angles must be between 2 and " +
                            std::to_string(kMaxAngles) + ", found " + std::to_string(nv));
  }
  const long long nh = in.integer("the number of horizontal angles", &nh_line);
  if (nh < 1 || nh > kMaxAngles) {
    in.fail_at(nh_line, "number of horizontal angles must be between 1 and " +
                            std::to_string(kMaxAngles) + ", found " + std::to_string(nh));
  }
  const long long type = in.integer("the photometric type", &line);
  if (type == 2 || type == 3) {
    in.fail_at(line, std::string("photometric type ") +
                         (type == 2 ? "B (2, floodlight coordinates with a horizontal polar axis)"
                                    : "A (3, automotive coordinates)") +
                         " is not supported: only type C (1) files can be read");
  }
  if (type != 1) {
    in.fail_at(line,
               "photometric type must be 1 (C), 2 (B) or 3 (A), found " + std::to_string(type));
  }
  data.photometric_type = 1;
  const long long units = in.integer("the units type", &line);
  if (units != 1 && units != 2) {
    in.fail_at(line, "units type must be 1 (feet) or 2 (metres), found " + std::to_string(units));
  }
  data.units = static_cast<int>(units);
  data.width = in.number("the luminous opening width");
  data.length = in.number("the luminous opening length");
  data.height = in.number("the luminous opening height");
  data.ballast_factor = in.number("the ballast factor", &line);
  if (!(data.ballast_factor > 0)) {
    in.fail_at(line,
               "ballast factor must be positive, found " + format_number(data.ballast_factor));
  }
  data.ballast_lamp_factor = in.number("the ballast-lamp factor / file generation type", &line);
  if (!(data.ballast_lamp_factor > 0) && ballast_lamp_factor_applies(data.version)) {
    in.fail_at(line, "ballast-lamp photometric factor must be positive, found " +
                         format_number(data.ballast_lamp_factor));
  }
  data.input_watts = in.number("the input watts");

  data.vertical_deg = read_angles(in, static_cast<std::size_t>(nv), "vertical angles", 0, 180);
  data.horizontal_deg = read_angles(in, static_cast<std::size_t>(nh), "horizontal angles", 0, 360);
  data.symmetry = symmetry_from_horizontal(data.horizontal_deg, in, in.tokens[in.pos - 1].line);

  const std::size_t count = static_cast<std::size_t>(nv) * static_cast<std::size_t>(nh);
  std::vector<int> lines;
  data.candela = in.numbers(count, "candela values", &lines);
  for (std::size_t i = 0; i < count; ++i) {
    if (data.candela[i] < 0) {
      const std::size_t ih = i / static_cast<std::size_t>(nv);
      const std::size_t iv = i % static_cast<std::size_t>(nv);
      in.fail_at(lines[i], "negative candela value " + format_number(data.candela[i]) +
                               " at horizontal angle " + format_number(data.horizontal_deg[ih]) +
                               ", vertical angle " + format_number(data.vertical_deg[iv]));
    }
  }
  if (!in.done()) {
    const Token& extra = in.tokens[in.pos];
    in.fail_at(extra.line, "unexpected value '" + printable_token(extra.text) + "' after the " +
                               std::to_string(count) + " candela values (" + std::to_string(nv) +
                               " vertical x " + std::to_string(nh) +
                               " horizontal angles declared on line " + std::to_string(nv_line) +
                               "): the counts do not match the data");
  }
  return data;
}

double ies_candela_scale(const IesData& data) {
  double scale = data.candela_multiplier * data.ballast_factor;
  if (ballast_lamp_factor_applies(data.version)) scale *= data.ballast_lamp_factor;
  return scale;
}

std::optional<double> ies_rated_lumens(const IesData& data) {
  if (!(data.lumens_per_lamp > 0)) return std::nullopt;
  return data.lamp_count * data.lumens_per_lamp;
}

PhotometricWeb make_ies_web(const IesData& data) {
  const double scale = ies_candela_scale(data);
  std::vector<double> candela(data.candela.size());
  for (std::size_t i = 0; i < candela.size(); ++i) candela[i] = data.candela[i] * scale;
  PhotometricWeb web = make_web(data.horizontal_deg, data.vertical_deg, candela, data.symmetry);
  web.rated_lumens = ies_rated_lumens(data);
  if (data.input_watts > 0) web.input_watts = data.input_watts;
  web.absolute_photometry = !(data.lumens_per_lamp > 0);
  const double to_m = data.units == 1 ? kFeetToMetres : 1.0;
  web.opening = ies_luminous_opening(data.width * to_m, data.length * to_m, data.height * to_m);
  web.tilt = data.tilt_table;
  return web;
}

PhotometricWeb load_ies(const std::filesystem::path& file) {
  return make_ies_web(parse_ies(read_file(file, kMaxPhotometryFileBytes), file));
}

}  // namespace relight

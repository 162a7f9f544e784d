#include "light/photometry_summary.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "common/input_error.h"
#include "common/read_file.h"
#include "light/ies_parser.h"
#include "light/ldt_parser.h"
#include "math/vec3.h"

namespace relight {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(first, last - first + 1));
}

std::string ies_keyword(const IesData& data, std::string_view name) {
  for (const IesKeyword& k : data.keywords) {
    if (k.name == name) return trimmed(k.value);
  }
  return {};
}

std::string_view ies_format(IesVersion version) {
  switch (version) {
    case IesVersion::kLm63_1986:
      return "IES LM-63-1986";
    case IesVersion::kLm63_1991:
      return "IES LM-63-1991";
    case IesVersion::kLm63_1995:
      return "IES LM-63-1995";
    case IesVersion::kLm63_2002:
      return "IES LM-63-2002";
    case IesVersion::kLm63_2019:
      return "IES LM-63-2019";
    case IesVersion::kUnknown:
      break;
  }
  return "IES LM-63";
}

// The outermost γ (measured from the axis that holds the peak) at which I(C, ·) is still at
// or above `level`, interpolated linearly on the web's γ grid; 0 when it never is.
double outermost_crossing_deg(const PhotometricWeb& web, double c_rad, double level, bool peak_up) {
  const std::vector<double>& g = web.gamma_deg;
  const auto at = [&](std::size_t k) { return intensity(web, c_rad, g[k] * kPi / 180.0); };
  const auto from_axis = [&](double gamma) { return peak_up ? 180.0 - gamma : gamma; };
  // Walk from the far side toward the peak's axis; the first sample at or above the level
  // ends the walk, the crossing lies between it and the previous sample.
  const std::size_t n = g.size();
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t k = peak_up ? s : n - 1 - s;
    const double v = at(k);
    if (v < level) continue;
    if (s == 0) return from_axis(g[k]);
    const std::size_t outer = peak_up ? k - 1 : k + 1;
    const double w = at(outer);
    const double t = (v - level) / (v - w);  // v ≥ level > w
    return from_axis(g[k] + t * (g[outer] - g[k]));
  }
  return 0;
}

}  // namespace

nlohmann::json polar_json(const PhotometrySummary& s) {
  std::vector<int> gamma;
  for (int g = 0; g <= 180; g += kPolarStepDeg) gamma.push_back(g);
  return {{"gamma_deg", gamma},
          {"c0", s.polar_cd[0]},
          {"c90", s.polar_cd[1]},
          {"c180", s.polar_cd[2]},
          {"c270", s.polar_cd[3]}};
}

std::string_view to_string(CSymmetry symmetry) {
  switch (symmetry) {
    case CSymmetry::kNone:
      return "none";
    case CSymmetry::kAxial:
      return "axial";
    case CSymmetry::kQuadrant:
      return "quadrant";
    case CSymmetry::kBilateralC0C180:
      return "bilateral_c0_c180";
    case CSymmetry::kBilateralC90C270:
      return "bilateral_c90_c270";
  }
  return "none";
}

double spread_angle_deg(const PhotometricWeb& web, double fraction) {
  double peak = 0, peak_gamma = 0;
  for (std::size_t c = 0; c < web.c_deg.size(); ++c) {
    for (std::size_t k = 0; k < web.gamma_deg.size(); ++k) {
      if (web.at(c, k) > peak) {
        peak = web.at(c, k);
        peak_gamma = web.gamma_deg[k];
      }
    }
  }
  if (peak <= 0) return 0;
  const bool peak_up = peak_gamma > 90.0;
  constexpr int kHalfPlanes = 360;
  double sum = 0;
  for (int i = 0; i < kHalfPlanes; ++i) {
    const double c_rad = 2.0 * kPi * i / kHalfPlanes;
    sum += outermost_crossing_deg(web, c_rad, fraction * peak, peak_up);
  }
  return 2.0 * sum / kHalfPlanes;
}

bool is_photometry_file(const std::filesystem::path& file) {
  const std::string ext = lower(file.extension().string());
  return ext == ".ies" || ext == ".ldt";
}

PhotometrySummary summarize_photometry(std::string_view text, const std::filesystem::path& file) {
  const std::string ext = lower(file.extension().string());
  PhotometrySummary s;
  PhotometricWeb web;
  std::optional<double> lamp_lumens;
  if (ext == ".ies") {
    const IesData data = parse_ies(text, file);
    web = make_ies_web(data);
    s.format = ies_format(data.version);
    s.manufacturer = ies_keyword(data, "MANUFAC");
    s.catalogue = ies_keyword(data, "LUMCAT");
    s.luminaire = ies_keyword(data, "LUMINAIRE");
    s.symmetry = data.symmetry;
    lamp_lumens = ies_rated_lumens(data);
  } else if (ext == ".ldt") {
    const LdtData data = parse_ldt(text, file);
    web = make_ldt_web(data);
    s.format = "EULUMDAT";
    s.manufacturer = trimmed(data.company);
    s.catalogue = trimmed(data.luminaire_number);
    s.luminaire = trimmed(data.luminaire_name);
    const CSymmetry by_isym[] = {CSymmetry::kNone, CSymmetry::kAxial, CSymmetry::kBilateralC0C180,
                                 CSymmetry::kBilateralC90C270, CSymmetry::kQuadrant};
    s.symmetry = by_isym[data.isym];  // the parser accepts Isym 0..4 only
    if (!ldt_absolute_photometry(data) && !data.lamp_sets.empty() &&
        data.lamp_sets.front().flux_lm > 0) {
      lamp_lumens = data.lamp_sets.front().flux_lm;
    }
  } else {
    throw InputError(file.string() +
                     ": not a photometric file (the name must end in .ies or .ldt)");
  }
  s.lumens = flux_lm(web);
  s.watts = web.input_watts;
  s.absolute_photometry = web.absolute_photometry;
  if (!web.absolute_photometry && lamp_lumens && *lamp_lumens > 0) {
    s.lor = s.lumens / *lamp_lumens;
  }
  s.max_cd = max_intensity(web);
  s.beam_angle_deg = spread_angle_deg(web, 0.5);
  s.field_angle_deg = spread_angle_deg(web, 0.1);
  s.opening = web.opening;
  for (std::size_t plane = 0; plane < 4; ++plane) {
    const double c_rad = kPi / 2 * static_cast<double>(plane);
    for (int g = 0; g <= 180; g += kPolarStepDeg) {
      s.polar_cd[plane].push_back(intensity(web, c_rad, g * kPi / 180.0));
    }
  }
  return s;
}

PhotometrySummary summarize_photometry_file(const std::filesystem::path& file) {
  return summarize_photometry(read_file(file, kMaxPhotometryFileBytes), file);
}

nlohmann::json to_json(const PhotometrySummary& s) {
  const auto or_null = [](const std::optional<double>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  return {
      {"format", s.format},
      {"manufacturer", s.manufacturer},
      {"catalogue", s.catalogue},
      {"luminaire", s.luminaire},
      {"lumens", s.lumens},
      {"watts", or_null(s.watts)},
      {"lor", or_null(s.lor)},
      {"max_cd", s.max_cd},
      {"beam_angle_deg", s.beam_angle_deg},
      {"field_angle_deg", s.field_angle_deg},
      {"symmetry", std::string(to_string(s.symmetry))},
      {"opening_m",
       {{"shape", std::string(to_string(s.opening.shape))},
        {"length", s.opening.length_m},
        {"width", s.opening.width_m},
        {"height", s.opening.height_m}}},
      {"absolute_photometry", s.absolute_photometry},
  };
}

}  // namespace relight

// Evaluation, flux and loading of luminaire distributions (see distribution.h). The
// analytic fluxes are closed forms: isotropic 4πI; cosine power
// 2πI·(1 - cos^(n+1)θc)/(n+1) with θc = min(cutoff, 90°); curve: per linear segment the
// same ∫ I sinγ dγ weights as a web cell.
#include "light/distribution.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <system_error>

#include "common/input_error.h"
#include "light/ies_parser.h"
#include "light/ldt_parser.h"

namespace relight {
namespace {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

// γ folded into [0, π] (the same direction on the other side of the pole).
double fold_gamma(double gamma_rad) {
  double g = std::fmod(gamma_rad, 2.0 * kPi);
  if (g < 0) g += 2.0 * kPi;
  return g > kPi ? 2.0 * kPi - g : g;
}

double cosine_power(const CosinePowerModel& m, double cos_gamma, double gamma_rad) {
  if (!(cos_gamma > 0) || gamma_rad > m.cutoff_rad) return 0.0;
  return m.candela * std::pow(cos_gamma, m.exponent);
}

double curve_at(const CurveModel& m, double gamma_rad) {
  const auto& g = m.gamma_rad;
  if (g.size() < 2 || gamma_rad < g.front() || gamma_rad > g.back()) return 0.0;
  const auto it = std::upper_bound(g.begin(), g.end(), gamma_rad);
  const std::size_t i = std::min<std::size_t>(
      static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - g.begin() - 1, 0)), g.size() - 2);
  const double t = (gamma_rad - g[i]) / (g[i + 1] - g[i]);
  return m.candela[i] + t * (m.candela[i + 1] - m.candela[i]);
}

double curve_flux(const CurveModel& m) {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < m.gamma_rad.size(); ++i) {
    const double g0 = m.gamma_rad[i], g1 = m.gamma_rad[i + 1], d = g1 - g0;
    const double a = 2.0 * std::sin(0.5 * (g0 + g1)) * std::sin(0.5 * d);  // ∫ sinγ
    const double b = (std::sin(g1) - g1 * std::cos(g1)) - (std::sin(g0) - g0 * std::cos(g0));
    sum += m.candela[i] * (g1 * a - b) / d + m.candela[i + 1] * (b - g0 * a) / d;
  }
  return 2.0 * kPi * sum;
}

bool finite_non_negative(double v) {
  return std::isfinite(v) && v >= 0;
}

std::string number_text(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace

double Distribution::intensity(double c_rad, double gamma_rad) const {
  return std::visit(
      Overloaded{
          [&](const IsotropicModel& m) { return m.candela; },
          [&](const CosinePowerModel& m) {
            const double g = fold_gamma(gamma_rad);
            return cosine_power(m, std::cos(g), g);
          },
          [&](const CurveModel& m) { return curve_at(m, fold_gamma(gamma_rad)); },
          [&](const PhotometricWeb& w) { return relight::intensity(w, c_rad, gamma_rad); },
      },
      model);
}

double Distribution::intensity(Vec3 d) const {
  const double z = std::clamp(d.z, -1.0, 1.0);
  return std::visit(Overloaded{
                        [&](const IsotropicModel& m) { return m.candela; },
                        [&](const CosinePowerModel& m) { return cosine_power(m, z, std::acos(z)); },
                        [&](const CurveModel& m) { return curve_at(m, std::acos(z)); },
                        [&](const PhotometricWeb& w) {
                          const double c = (d.x == 0 && d.y == 0) ? 0.0 : std::atan2(d.y, d.x);
                          return relight::intensity(w, c, std::acos(z));
                        },
                    },
                    model);
}

double Distribution::flux_lm() const {
  return std::visit(Overloaded{
                        [](const IsotropicModel& m) { return 4.0 * kPi * m.candela; },
                        [](const CosinePowerModel& m) {
                          const double cut = std::min(m.cutoff_rad, kPi / 2);
                          const double n1 = m.exponent + 1.0;
                          return 2.0 * kPi * m.candela * (1.0 - std::pow(std::cos(cut), n1)) / n1;
                        },
                        [](const CurveModel& m) { return curve_flux(m); },
                        [](const PhotometricWeb& w) { return relight::flux_lm(w); },
                    },
                    model);
}

std::optional<double> Distribution::rated_lumens() const {
  if (const auto* w = std::get_if<PhotometricWeb>(&model)) return w->rated_lumens;
  return std::nullopt;
}

std::optional<double> Distribution::input_watts() const {
  if (const auto* w = std::get_if<PhotometricWeb>(&model)) return w->input_watts;
  return std::nullopt;
}

LuminousOpening Distribution::opening() const {
  if (const auto* w = std::get_if<PhotometricWeb>(&model)) return w->opening;
  return {};
}

bool Distribution::axisymmetric() const {
  if (const auto* w = std::get_if<PhotometricWeb>(&model)) return is_axisymmetric(*w);
  return true;
}

double Distribution::max_intensity() const {
  return std::visit(
      Overloaded{
          [](const IsotropicModel& m) { return m.candela; },
          [](const CosinePowerModel& m) { return m.candela; },
          [](const CurveModel& m) {
            return m.candela.empty() ? 0.0 : *std::max_element(m.candela.begin(), m.candela.end());
          },
          [](const PhotometricWeb& w) { return relight::max_intensity(w); },
      },
      model);
}

Distribution load_distribution(const DistributionSpec& spec) {
  const std::string& where = spec.where;
  switch (spec.type) {
    case DistributionType::kIsotropic:
      if (!finite_non_negative(spec.candela)) {
        fail_input(where,
                   "candela must be a finite number >= 0, found " + number_text(spec.candela));
      }
      return {IsotropicModel{spec.candela}};
    case DistributionType::kCosinePower:
      if (!finite_non_negative(spec.candela)) {
        fail_input(where,
                   "candela must be a finite number >= 0, found " + number_text(spec.candela));
      }
      if (!finite_non_negative(spec.exponent)) {
        fail_input(where,
                   "exponent must be a finite number >= 0, found " + number_text(spec.exponent));
      }
      if (!std::isfinite(spec.cutoff_deg) || !(spec.cutoff_deg > 0) || spec.cutoff_deg > 180) {
        fail_input(where, "cutoff_deg must lie in (0, 180], found " + number_text(spec.cutoff_deg));
      }
      return {CosinePowerModel{spec.candela, spec.exponent, radians(spec.cutoff_deg)}};
    case DistributionType::kCurve: {
      const auto& g = spec.gamma_deg;
      const auto& c = spec.curve_candela;
      if (g.size() != c.size()) {
        fail_input(where, "gamma_deg has " + std::to_string(g.size()) + " values but candela has " +
                              std::to_string(c.size()));
      }
      if (g.size() < 2) fail_input(where, "a curve needs at least 2 control points");
      for (std::size_t i = 0; i < g.size(); ++i) {
        if (!std::isfinite(g[i]))
          fail_input(where, "gamma_deg[" + std::to_string(i) + "] is not finite");
        if (i == 0 && g[0] != 0) {
          fail_input(where, "gamma_deg must start at 0, found " + number_text(g[0]));
        }
        if (i > 0 && !(g[i] > g[i - 1])) {
          fail_input(where, "gamma_deg must ascend strictly: " + number_text(g[i]) + " follows " +
                                number_text(g[i - 1]));
        }
        if (g[i] > 180)
          fail_input(where, "gamma_deg must not exceed 180, found " + number_text(g[i]));
        if (!finite_non_negative(c[i])) {
          fail_input(where, "candela[" + std::to_string(i) +
                                "] must be a finite number >= 0, found " + number_text(c[i]));
        }
      }
      CurveModel curve;
      for (const double deg : g) curve.gamma_rad.push_back(radians(deg));
      curve.candela = c;
      return {std::move(curve)};
    }
    case DistributionType::kIes:
    case DistributionType::kLdt: {
      const char* kind = spec.type == DistributionType::kIes ? "IES" : "EULUMDAT";
      if (spec.contents) {
        return {spec.type == DistributionType::kIes
                    ? make_ies_web(parse_ies(*spec.contents, spec.file))
                    : make_ldt_web(parse_ldt(*spec.contents, spec.file))};
      }
      if (spec.file.empty()) fail_input(where, std::string("no ") + kind + " file given");
      std::error_code ec;
      if (!std::filesystem::is_regular_file(spec.file, ec)) {
        fail_input(where, std::string(kind) + " file '" + spec.file.string() + "' not found");
      }
      return {spec.type == DistributionType::kIes ? load_ies(spec.file) : load_ldt(spec.file)};
    }
  }
  fail_input(where, "unknown distribution type");
}

}  // namespace relight

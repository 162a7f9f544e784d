// Luminaire SH weights: Legendre weights by Simpson on the support pieces (Dobashi et al.
// 1995 Eq. 3, 19), windowing (Eq. 12-13), aiming by the addition theorem (Eq. 7-10) or a
// general rotation; see luminaire_sh.h.
#include "sources/luminaires/luminaire_sh.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

#include "math/legendre.h"
#include "math/sh.h"
#include "math/sh_rotation.h"
#include "math/zonal.h"
#include "sources/luminaires/luminaire_sh_web.h"

namespace relight {
namespace {

// Adds (2l+1)/2 ∫_a^b I(γ) P_l(cosγ) sinγ dγ to w[l] by composite Simpson with an even number
// of intervals (≈ density per π, at least 2). value(γ) is I on the closed piece [a, b]
// (one-sided limits at the ends).
template <class Value>
void add_simpson_piece(double a, double b, int density, Value&& value, std::span<double> w,
                       std::span<double> p) {
  if (!(b > a)) return;
  int n = static_cast<int>(std::ceil(density * (b - a) / kPi));
  n = std::max(2, n + (n % 2));
  const double h = (b - a) / n;
  const int order = static_cast<int>(w.size());
  for (int i = 0; i <= n; ++i) {
    const double gamma = i == n ? b : a + i * h;
    const double t = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const double v = value(gamma);
    if (v == 0.0) continue;
    const double s = t * h / 3.0 * std::sin(gamma) * v;
    if (s == 0.0) continue;
    legendre_all(std::cos(gamma), p);
    for (int l = 0; l < order; ++l) w[l] += s * p[l];
  }
}

// Piecewise-linear I(γ) between nodes (γ ascending, radians), zero outside: one Simpson piece
// per segment.
void add_linear_pieces(std::span<const double> gamma, std::span<const double> value, int density,
                       std::span<double> w, std::span<double> p) {
  for (std::size_t k = 0; k + 1 < gamma.size(); ++k) {
    const double g0 = gamma[k], g1 = gamma[k + 1], v0 = value[k], v1 = value[k + 1];
    if (v0 == 0.0 && v1 == 0.0) continue;
    add_simpson_piece(
        g0, g1, density, [&](double g) { return v0 + (v1 - v0) * ((g - g0) / (g1 - g0)); }, w, p);
  }
}

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

void check_order(int order) {
  if (order < 1) throw std::invalid_argument("luminaire SH: order must be >= 1");
}

}  // namespace

Frame luminaire_sh_frame(Vec3 aim, Vec3 c0) {
  const double len = length(aim);
  if (!(len > 0) || !std::isfinite(len))
    throw std::invalid_argument("luminaire SH: aim must be a finite non-zero vector");
  // t = c0 ⟂ aim, b = cross(aim, t) = −c90, n = aim: right-handed, cross(t, b) = n.
  return frame_from_normal_and_hint(aim / len, c0);
}

std::vector<double> distribution_legendre_weights(const Distribution& distribution, int order,
                                                  int simpson_intervals) {
  check_order(order);
  if (!distribution.axisymmetric())
    throw std::invalid_argument("luminaire SH: Legendre weights need an axisymmetric distribution");
  const int density = std::max(2, simpson_intervals);
  std::vector<double> w(order, 0.0), p(order);
  std::visit(
      Overloaded{
          // Eq. 3 with I constant: ∫ I sinγ dγ = 2I exactly (½ applied below).
          [&](const IsotropicModel& m) { w[0] = 2.0 * m.candela; },
          [&](const CosinePowerModel& m) {
            // Support [0, min(cut-off, 90°)]: cos^n γ is smooth there, zero beyond.
            const double end = std::min(m.cutoff_rad, kPi / 2);
            add_simpson_piece(
                0.0, end, density,
                [&](double g) {
                  return m.candela * std::pow(std::max(std::cos(g), 0.0), m.exponent);
                },
                w, p);
          },
          [&](const CurveModel& m) { add_linear_pieces(m.gamma_rad, m.candela, density, w, p); },
          [&](const PhotometricWeb& web) {
            // All planes equal: the first one, on the web's γ nodes.
            const std::size_t ng = web.gamma_deg.size();
            if (web.c_deg.empty() || web.candela.size() < ng) return;
            std::vector<double> g(ng);
            for (std::size_t j = 0; j < ng; ++j) g[j] = radians(web.gamma_deg[j]);
            add_linear_pieces(g, std::span<const double>(web.candela.data(), ng), density, w, p);
          },
      },
      distribution.model);
  // The (2l+1)/2 of Eq. 3.
  for (int l = 0; l < order; ++l) w[l] *= 0.5 * (2 * l + 1);
  return w;
}

LocalLuminaireSh project_luminaire_local(const Distribution& distribution,
                                         const LuminaireShSettings& settings) {
  const int order = settings.order;
  check_order(order);
  const bool axisymmetric = distribution.axisymmetric();
  if (settings.path == LuminaireShPath::kLegendre && !axisymmetric)
    throw std::invalid_argument(
        "luminaire SH: the Legendre path needs an axisymmetric distribution");

  LocalLuminaireSh local;
  local.order = order;
  const auto* web = std::get_if<PhotometricWeb>(&distribution.model);
  if (web != nullptr && (settings.path == LuminaireShPath::kFull || !axisymmetric)) {
    local.coeffs = web_local_sh(*web, order);
    sh_apply_window(settings.window, local.coeffs, settings.window_param);
    return local;
  }
  std::vector<double> z =
      distribution_legendre_weights(distribution, order, settings.simpson_intervals);
  legendre_to_zonal(z, z);
  zonal_apply_window(settings.window, z, settings.window_param);
  if (settings.path == LuminaireShPath::kFull) {
    // An analytic model on the general path: its zonal coefficients are its exact SH
    // projection about +z (m = 0 only); aim_luminaire_sh then rotates them generally.
    local.coeffs.assign(sh_count(order), 0.0);
    for (int l = 0; l < order; ++l) local.coeffs[sh_index(l, 0)] = z[l];
    return local;
  }
  local.zonal = true;
  local.coeffs = std::move(z);
  return local;
}

void aim_luminaire_sh(const LocalLuminaireSh& local, Vec3 aim, Vec3 c0, std::span<double> world) {
  if (static_cast<int>(world.size()) != sh_count(local.order))
    throw std::invalid_argument("luminaire SH: output must hold order² values");
  const Frame frame = luminaire_sh_frame(aim, c0);
  if (local.zonal) {
    // Eq. 9-10: w_lm = sqrt(4π/(2l+1)) z_l Y_lm(aim).
    zonal_rotate(local.coeffs, frame.n, world);
    return;
  }
  sh_rotate(make_sh_rotation(local.order, frame), local.coeffs, world);
}

std::vector<double> aim_luminaire_sh(const LocalLuminaireSh& local, Vec3 aim, Vec3 c0) {
  std::vector<double> world(sh_count(local.order));
  aim_luminaire_sh(local, aim, c0, world);
  return world;
}

std::vector<double> luminaire_world_sh(const Distribution& distribution, Vec3 aim, Vec3 c0,
                                       const LuminaireShSettings& settings) {
  return aim_luminaire_sh(project_luminaire_local(distribution, settings), aim, c0);
}

double sh_flux_lm(std::span<const double> world_sh) {
  if (world_sh.empty()) return 0.0;
  return std::sqrt(4.0 * kPi) * world_sh[0];
}

}  // namespace relight

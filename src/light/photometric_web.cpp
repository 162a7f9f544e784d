// Type-C web: symmetry expansion, bilinear evaluation and the exact flux of the bilinear
// interpolant. See photometric_web.h for the conventions (CIE 121, IES LM-63-2019 §5.10 /
// Table 1 for the luminous opening).
#include "light/photometric_web.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "math/vec3.h"

namespace relight {
namespace {

constexpr double kAngleTolDeg = 1e-9;

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("make_web: ") + what);
}

bool strictly_ascending_finite(const std::vector<double>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) return false;
    if (i > 0 && !(v[i] > v[i - 1])) return false;
  }
  return true;
}

// Index i of the cell [v[i], v[i+1]] holding x, for v with ≥ 2 ascending entries; x is
// expected inside [v.front(), v.back()] and clamped into the end cells otherwise.
std::size_t cell_index(const std::vector<double>& v, double x) {
  const auto it = std::upper_bound(v.begin(), v.end(), x);
  const std::ptrdiff_t i = (it - v.begin()) - 1;
  return static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(i, 0, std::ssize(v) - 2));
}

bool near_equal(double a, double b) {
  return std::abs(a - b) <= 1e-9 + 1e-6 * std::max(std::abs(a), std::abs(b));
}

int sign_of(double x) {
  return x > 0 ? 1 : (x < 0 ? -1 : 0);
}

}  // namespace

std::string_view to_string(OpeningShape shape) {
  switch (shape) {
    case OpeningShape::kPoint:
      return "point";
    case OpeningShape::kRectangular:
      return "rectangular";
    case OpeningShape::kRectangularWithLuminousSides:
      return "rectangular with luminous sides";
    case OpeningShape::kCircular:
      return "circular";
    case OpeningShape::kEllipse:
      return "ellipse";
    case OpeningShape::kVerticalCylinder:
      return "vertical cylinder";
    case OpeningShape::kVerticalEllipticalCylinder:
      return "vertical elliptical cylinder";
    case OpeningShape::kSphere:
      return "sphere";
    case OpeningShape::kEllipsoidalSpheroid:
      return "ellipsoidal spheroid";
    case OpeningShape::kHorizontalCylinderAlongLength:
      return "horizontal cylinder along length (C0-C180)";
    case OpeningShape::kHorizontalEllipticalCylinderAlongLength:
      return "horizontal elliptical cylinder along length (C0-C180)";
    case OpeningShape::kHorizontalCylinderAlongWidth:
      return "horizontal cylinder along width (C90-C270)";
    case OpeningShape::kHorizontalEllipticalCylinderAlongWidth:
      return "horizontal elliptical cylinder along width (C90-C270)";
    case OpeningShape::kVerticalCircleFacingC0:
      return "vertical circle facing C0";
    case OpeningShape::kVerticalEllipseFacingC0:
      return "vertical ellipse facing C0";
    case OpeningShape::kVerticalCircleFacingC90:
      return "vertical circle facing C90";
    case OpeningShape::kVerticalEllipseFacingC90:
      return "vertical ellipse facing C90";
    case OpeningShape::kIrregular:
      return "irregular";
  }
  return "unknown";
}

LuminousOpening ies_luminous_opening(double width_m, double length_m, double height_m) {
  const double w = std::abs(width_m), l = std::abs(length_m), h = std::abs(height_m);
  const int sw = sign_of(width_m), sl = sign_of(length_m), sh = sign_of(height_m);
  using S = OpeningShape;
  auto make = [&](S shape) { return LuminousOpening{shape, w, l, h}; };
  if (sw == 0 && sl == 0 && sh == 0) return make(S::kPoint);
  if (sw > 0 && sl > 0 && sh == 0) return make(S::kRectangular);
  if (sw > 0 && sl > 0 && sh > 0) return make(S::kRectangularWithLuminousSides);
  if (sw < 0 && sl < 0 && sh == 0) return make(near_equal(w, l) ? S::kCircular : S::kEllipse);
  if (sw < 0 && sl < 0 && sh > 0) {
    return make(near_equal(w, l) ? S::kVerticalCylinder : S::kVerticalEllipticalCylinder);
  }
  if (sw < 0 && sl < 0 && sh < 0) {
    return make(near_equal(w, l) && near_equal(w, h) ? S::kSphere : S::kEllipsoidalSpheroid);
  }
  if (sw < 0 && sl > 0 && sh < 0) {
    return make(near_equal(w, h) ? S::kHorizontalCylinderAlongLength
                                 : S::kHorizontalEllipticalCylinderAlongLength);
  }
  if (sw > 0 && sl < 0 && sh < 0) {
    return make(near_equal(l, h) ? S::kHorizontalCylinderAlongWidth
                                 : S::kHorizontalEllipticalCylinderAlongWidth);
  }
  if (sw < 0 && sl == 0 && sh < 0) {
    return make(near_equal(w, h) ? S::kVerticalCircleFacingC0 : S::kVerticalEllipseFacingC0);
  }
  if (sw == 0 && sl < 0 && sh < 0) {
    return make(near_equal(l, h) ? S::kVerticalCircleFacingC90 : S::kVerticalEllipseFacingC90);
  }
  // Legacy round openings: one negative horizontal dimension (the diameter), the other 0.
  if ((sw < 0 && sl == 0) || (sw == 0 && sl < 0)) {
    const double d = std::max(w, l);
    return LuminousOpening{sh > 0 ? S::kVerticalCylinder : S::kCircular, d, d, h};
  }
  return make(S::kIrregular);
}

double tilt_factor(const TiltTable& table, double tilt_deg) {
  const auto& a = table.angles_deg;
  const auto& f = table.factors;
  const std::size_t n = std::min(a.size(), f.size());
  if (n == 0) return 1.0;
  if (n == 1 || tilt_deg <= a.front()) return f.front();
  if (tilt_deg >= a[n - 1]) return f[n - 1];
  const std::size_t i = static_cast<std::size_t>(
      std::upper_bound(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(n), tilt_deg) -
      a.begin() - 1);
  const double t = (tilt_deg - a[i]) / (a[i + 1] - a[i]);
  return f[i] + t * (f[i + 1] - f[i]);
}

PhotometricWeb make_web(const std::vector<double>& stored_c_deg,
                        const std::vector<double>& gamma_deg,
                        const std::vector<double>& stored_candela, CSymmetry symmetry) {
  const std::size_t ng = gamma_deg.size();
  const std::size_t nc = stored_c_deg.size();
  require(ng >= 2, "need at least two gamma angles");
  require(nc >= 1, "need at least one C plane");
  require(symmetry != CSymmetry::kAxial || nc == 1, "axial symmetry stores one plane");
  require(stored_candela.size() == nc * ng, "candela count does not match the angles");
  require(strictly_ascending_finite(gamma_deg), "gamma angles must ascend");
  require(gamma_deg.front() >= 0 && gamma_deg.back() <= 180, "gamma outside [0, 180]");
  require(strictly_ascending_finite(stored_c_deg), "C angles must ascend");
  require(stored_c_deg.front() >= 0 && stored_c_deg.back() <= 360, "C outside [0, 360]");
  for (const double v : stored_candela) require(std::isfinite(v), "candela must be finite");

  // Rows of candela (one per plane source) and (angle, row) pairs placing them on the
  // circle. Mirrored planes reference the stored row, so values are copied bit-exactly.
  std::vector<std::vector<double>> rows(nc);
  for (std::size_t i = 0; i < nc; ++i) {
    rows[i].assign(stored_candela.begin() + static_cast<std::ptrdiff_t>(i * ng),
                   stored_candela.begin() + static_cast<std::ptrdiff_t>((i + 1) * ng));
  }
  struct Placed {
    double c;
    std::size_t row;
  };
  std::vector<Placed> placed;
  auto place = [&](double c, std::size_t row) {
    if (c < 0) c += 360.0;
    if (c > 360) c -= 360.0;
    if (std::abs(c) < kAngleTolDeg) c = 0.0;
    if (std::abs(c - 360.0) < kAngleTolDeg) c = 360.0;
    placed.push_back({c, row});
  };
  for (std::size_t i = 0; i < nc; ++i) {
    const double a = stored_c_deg[i];
    switch (symmetry) {
      case CSymmetry::kAxial:
        place(0.0, i);
        place(360.0, i);
        break;
      case CSymmetry::kNone:
        place(a, i);
        break;
      case CSymmetry::kQuadrant:
        place(a, i);
        place(180.0 - a, i);
        place(180.0 + a, i);
        place(360.0 - a, i);
        break;
      case CSymmetry::kBilateralC0C180:
        place(a, i);
        place(360.0 - a, i);
        break;
      case CSymmetry::kBilateralC90C270:
        place(a, i);
        place(180.0 - a, i);
        break;
    }
  }
  std::stable_sort(placed.begin(), placed.end(),
                   [](const Placed& x, const Placed& y) { return x.c < y.c; });
  std::vector<Placed> planes;
  for (const Placed& p : placed) {
    if (planes.empty() || p.c - planes.back().c > kAngleTolDeg) planes.push_back(p);
  }
  // Close the circle: a plane at 0 (interpolated across the gap when the data start
  // later) and the same plane again at 360.
  if (planes.front().c > 0.0) {
    const Placed& first = planes.front();
    const Placed& last = planes.back();
    const double span = first.c + 360.0 - last.c;
    const double t = span > 0 ? (360.0 - last.c) / span : 0.0;
    std::vector<double> row(ng);
    for (std::size_t g = 0; g < ng; ++g) {
      row[g] = rows[last.row][g] + t * (rows[first.row][g] - rows[last.row][g]);
    }
    rows.push_back(std::move(row));
    planes.insert(planes.begin(), Placed{0.0, rows.size() - 1});
  }
  if (planes.back().c < 360.0) planes.push_back({360.0, planes.front().row});

  PhotometricWeb web;
  web.gamma_deg = gamma_deg;
  web.c_deg.reserve(planes.size());
  web.candela.reserve(planes.size() * ng);
  for (const Placed& p : planes) {
    web.c_deg.push_back(p.c);
    web.candela.insert(web.candela.end(), rows[p.row].begin(), rows[p.row].end());
  }
  return web;
}

double intensity(const PhotometricWeb& web, double c_rad, double gamma_rad) {
  if (!std::isfinite(c_rad) || !std::isfinite(gamma_rad)) return 0.0;
  if (web.c_deg.size() < 2 || web.gamma_deg.size() < 2) return 0.0;
  double g = std::fmod(degrees(gamma_rad), 360.0);
  double c = degrees(c_rad);
  if (g < 0) g += 360.0;
  if (g > 180.0) {  // the same direction seen from the other side of the pole
    g = 360.0 - g;
    c += 180.0;
  }
  c = std::fmod(c, 360.0);
  if (c < 0) c += 360.0;
  const auto& gs = web.gamma_deg;
  if (g < gs.front() || g > gs.back()) return 0.0;
  const std::size_t ig = cell_index(gs, g);
  const std::size_t ic = cell_index(web.c_deg, c);
  const double tg = (g - gs[ig]) / (gs[ig + 1] - gs[ig]);
  const double tc = (c - web.c_deg[ic]) / (web.c_deg[ic + 1] - web.c_deg[ic]);
  const double lo = web.at(ic, ig) + tc * (web.at(ic + 1, ig) - web.at(ic, ig));
  const double hi = web.at(ic, ig + 1) + tc * (web.at(ic + 1, ig + 1) - web.at(ic, ig + 1));
  return lo + tg * (hi - lo);
}

double flux_lm(const PhotometricWeb& web) {
  const std::size_t nc = web.c_deg.size();
  const std::size_t ng = web.gamma_deg.size();
  if (nc < 2 || ng < 2) return 0.0;
  // Over γ in [g0, g1], I is linear: I0·(g1-γ)/d + I1·(γ-g0)/d. With
  // A = ∫ sinγ dγ = cos g0 - cos g1 and B = ∫ γ sinγ dγ = [sinγ - γ cosγ], the weights of
  // I0 and I1 in ∫ I sinγ dγ are (g1·A - B)/d and (B - g0·A)/d. Over C the integrand is
  // linear too: each end plane weighs ΔC/2.
  std::vector<double> w0(ng - 1), w1(ng - 1);
  for (std::size_t ig = 0; ig + 1 < ng; ++ig) {
    const double g0 = radians(web.gamma_deg[ig]);
    const double g1 = radians(web.gamma_deg[ig + 1]);
    const double d = g1 - g0;
    const double a = 2.0 * std::sin(0.5 * (g0 + g1)) * std::sin(0.5 * d);
    const double b = (std::sin(g1) - g1 * std::cos(g1)) - (std::sin(g0) - g0 * std::cos(g0));
    w0[ig] = (g1 * a - b) / d;
    w1[ig] = (b - g0 * a) / d;
  }
  double flux = 0.0;
  for (std::size_t ic = 0; ic + 1 < nc; ++ic) {
    const double half_dc = 0.5 * radians(web.c_deg[ic + 1] - web.c_deg[ic]);
    double plane_sum = 0.0;
    for (std::size_t ig = 0; ig + 1 < ng; ++ig) {
      plane_sum += (web.at(ic, ig) + web.at(ic + 1, ig)) * w0[ig] +
                   (web.at(ic, ig + 1) + web.at(ic + 1, ig + 1)) * w1[ig];
    }
    flux += half_dc * plane_sum;
  }
  return flux;
}

double max_intensity(const PhotometricWeb& web) {
  if (web.candela.empty()) return 0.0;
  return *std::max_element(web.candela.begin(), web.candela.end());
}

bool is_axisymmetric(const PhotometricWeb& web) {
  const std::size_t ng = web.gamma_deg.size();
  for (std::size_t i = ng; i < web.candela.size(); ++i) {
    if (web.candela[i] != web.candela[i % ng]) return false;
  }
  return true;
}

}  // namespace relight

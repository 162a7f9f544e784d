// `relight glare`: DGP of a bright window view and UGR of one luminaire against the formulas
// evaluated by hand (Wienold & Christoffersen 2006; CIE 117-1995, the Guth position index written
// out again here), UGR in the CIE 190 standard room against the standard's tabular value, and bad
// arguments.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "light/ldt_parser.h"
#include "light/photometric_web.h"
#include "run_command.h"
#include "support/daylight_room.h"
#include "support/scene_json.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::run_relight;
using testing::TempDir;

// Guth's position index, σ and τ in degrees (Einhorn's form, as CIE 117 uses it).
double guth(double sigma, double tau) {
  return std::exp((35.2 - 0.31889 * tau - 1.22 * std::exp(-2 * tau / 9)) * 1e-3 * sigma +
                  (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma);
}

nlohmann::json glare(const fs::path& rlt, const std::string& args) {
  const auto r = run_relight("glare '" + rlt.string() + "' " + args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::printf("%s", r.out.c_str());
  return nlohmann::json::parse(r.out);
}

fs::path precompute(const TempDir& dir, const nlohmann::json& scene, const std::string& name) {
  return testing::precompute_scene(dir, name, scene.dump());
}

// A black room whose south window (x 1..3, y 0.9..2.1 on z = 5) shows a uniform 3000 cd/m²;
// the eye at (2, 1.5, 2) looks at it. By hand, over a fine grid of the window: E_v = Σ L cos θ
// dω; the window is the only glare source (L > 5·E_v/π), Σ L² dω / P² with each element's
// σ and τ; then DGP.
TEST(GlareCommand, DgpOfAWindowViewMatchesTheFormulaByHand) {
  const TempDir dir;
  testing::WindowRoom room;
  room.south_window = testing::kWindow;
  nlohmann::json scene = testing::window_room_json(room);
  const double l = 3000;
  scene["portals"][0]["environment"] = {{"type", "uniform"}, {"luminance", l}};
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 16}};
  const fs::path rlt = precompute(dir, scene, "window");
  const nlohmann::json g = glare(rlt, "--observer 2,1.5,2 --view 0,0,1");

  const double ex = 2, ey = 1.5, ez = 2, depth = 5 - ez;
  double ev = 0, sum = 0;
  const int n = 800;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = 1 + 2.0 * (i + 0.5) / n - ex, y = 0.9 + 1.2 * (j + 0.5) / n - ey;
      const double r2 = x * x + y * y + depth * depth, r = std::sqrt(r2);
      const double cos_theta = depth / r;
      const double d_omega = (2.0 / n) * (1.2 / n) * cos_theta / r2;
      ev += l * cos_theta * d_omega;
      const double sigma = std::acos(cos_theta) * 180 / kPi;
      const double tau = std::atan2(std::abs(x), std::abs(y)) * 180 / kPi;
      const double p = guth(sigma, tau);
      sum += l * l * d_omega / (p * p);
    }
  }
  const double dgp = 5.87e-5 * ev + 9.18e-2 * std::log10(1 + sum / std::pow(ev, 1.87)) + 0.16;
  std::printf("[ measured ] E_v %.1f lx (by hand %.1f), DGP %.4f (by hand %.4f)\n",
              g["ev"].get<double>(), ev, g["dgp"].get<double>(), dgp);
  EXPECT_NEAR(g["ev"].get<double>(), ev, 0.01 * ev);
  EXPECT_NEAR(g["dgp"].get<double>(), dgp, 0.01);
  EXPECT_TRUE(g["ugr"].is_null());  // no luminaire
  ASSERT_EQ(g["sources"].size(), 1u);
  EXPECT_EQ(g["sources"][0]["kind"], "view");
  EXPECT_NEAR(g["sources"][0]["luminance"].get<double>(), l, 0.02 * l);
}

// A black open floor under a clear CIE sky whose sun stands 30° high in the south (+z), and a
// 0.5 × 0.5 m panel emitter of 10⁵ cd/m² (a bare LED board) 2 m north of the eye at (0, 1.2, 0),
// 0.55–1.05 m to its side, facing it. Each is a glare source of its own luminance, exactly as
// its kind's direct light gives it (runtime/direct_light.h): looking north, the panel its
// 10⁵ cd/m² over the solid angle it subtends; looking at the sun, the sun E_n / (π sin² r) over
// its disc 2π(1 − cos r), r its angular radius. E_v takes the panel's direct light: with it
// switched off, E_v falls by ∫ L cos θ dω over the panel, by hand over a fine grid.
TEST(GlareCommand, AnEmitterAndAnEnvironmentSunInViewAreSourcesOfTheirOwnLuminance) {
  const TempDir dir;
  const double sun_e = 60000, panel_l = 1e5;
  const nlohmann::json scene = nlohmann::json::parse(R"({
    "materials": {"floor": {"albedo": [0, 0, 0]}},
    "geometry": [{"type": "quad", "corner": [-4, 0, -4], "u": [0, 0, 8], "v": [8, 0, 0],
                  "material": "floor"}],
    "environment": {"type": "cie_sky", "sky_type": 12, "horizontal_illuminance": 15000,
                    "sun": {"azimuth_deg": 180, "altitude_deg": 30}, "sun_illuminance": 60000},
    "emitters": [{"name": "panel", "geometry": {"type": "quad", "corner": [0.55, 0.95, -2],
                  "u": [0.5, 0, 0], "v": [0, 0.5, 0]}, "luminance": 100000}],
    "precompute": {"max_edge": 0.5, "gather_rays": 64, "cuts": {"directions": 1024}}
  })");
  const fs::path rlt = precompute(dir, scene, "open");
  const auto source = [](const nlohmann::json& g, const std::string& kind) -> nlohmann::json {
    for (const nlohmann::json& s : g["sources"]) {
      if (s["kind"] == kind) return s;
    }
    ADD_FAILURE() << "no " << kind << " source in " << g.dump();
    return nlohmann::json::object();
  };

  // Looking north at the panel; by hand its solid angle and ∫ L cos θ dω on the view plane.
  const std::string north = "--observer 0,1.2,0 --view 0,0,-1";
  const nlohmann::json lit = glare(rlt, north);
  const nlohmann::json panel = source(lit, "emitter");
  double omega = 0, e_panel = 0;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = 0.55 + 0.5 * (i + 0.5) / n, y = 0.95 + 0.5 * (j + 0.5) / n - 1.2, z = 2;
      const double r2 = x * x + y * y + z * z, r = std::sqrt(r2);
      const double d_omega = (0.5 / n) * (0.5 / n) * (z / r) / r2;
      omega += d_omega;
      e_panel += panel_l * (z / r) * d_omega;
    }
  }
  EXPECT_EQ(panel.value("name", ""), "panel");
  EXPECT_NEAR(panel.value("luminance", 0.0), panel_l, 1e-9 * panel_l);
  EXPECT_NEAR(panel.value("solid_angle", 0.0), omega, 1e-3 * omega);
  const fs::path off = dir.write("off.json", R"({"emitters": {"panel": {"on": false}}})");
  const nlohmann::json dark = glare(rlt, north + " --state '" + off.string() + "'");
  const double panel_ev = lit["ev"].get<double>() - dark["ev"].get<double>();
  EXPECT_NEAR(panel_ev, e_panel, 0.01 * e_panel);

  // Looking at the sun: its disc's angular radius from the solid angle reported, L by hand.
  const nlohmann::json g = glare(rlt, "--observer 0,1.2,0 --view 0,0.5,0.8660254");
  const nlohmann::json sun = source(g, "environment");
  const double sun_omega = sun.value("solid_angle", 0.0);
  const double radius = std::acos(1 - sun_omega / (2 * kPi));
  const double sun_l = sun_e / (kPi * std::sin(radius) * std::sin(radius));
  EXPECT_NEAR(radius * 180 / kPi, 0.265, 0.01);
  EXPECT_NEAR(sun.value("luminance", 0.0), sun_l, 1e-3 * sun_l);
  EXPECT_GT(g["ev"].get<double>(), sun_e);  // the sun, seen head on, and the sky
  std::printf(
      "[ measured ] panel %.0f cd/m² over %.6f sr (by hand %.6f), E %.2f lx (by hand "
      "%.2f); sun %.4g cd/m² (by hand %.4g), E_v %.0f lx\n",
      panel.value("luminance", 0.0), panel.value("solid_angle", 0.0), omega, panel_ev, e_panel,
      sun.value("luminance", 0.0), sun_l, g["ev"].get<double>());
}

// One 0.6 × 0.6 m isotropic 1000 cd luminaire at (2, 2.9, 3) aimed down, in a grey room; the
// eye at (2, 1.2, 1) looks along +z: r = 2.6249 m, cos γ = 1.7/r, A_p = 0.36·cos γ,
// L = 1000/A_p, ω = A_p/r², σ = acos(2/r) = 40.36°, τ = 0; L_b = (E_v − E_direct)/π from
// the command, E_direct = 1000·(2/r)/r² by hand.
TEST(GlareCommand, UgrOfOneLuminaireMatchesTheFormulaByHand) {
  const TempDir dir;
  testing::WindowRoom room;
  room.albedo = 0.5;
  nlohmann::json scene = testing::window_room_json(room);
  scene["luminaires"] = {testing::panel_luminaire("panel")};
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 64}};
  const fs::path rlt = precompute(dir, scene, "panel");
  const nlohmann::json g = glare(rlt, "--observer 2,1.2,1 --view 0,0,1");
  const double r = std::sqrt(1.7 * 1.7 + 2 * 2), cos_gamma = 1.7 / r;
  const double area = 0.36 * cos_gamma, lum = 1000 / area, omega = area / (r * r);
  const double direct = 1000 * (2 / r) / (r * r);
  EXPECT_NEAR(g["luminaire_direct_ev"].get<double>(), direct, 1e-3 * direct);
  const double lb = (g["ev"].get<double>() - direct) / kPi;
  EXPECT_NEAR(g["background_luminance"].get<double>(), lb, 1e-3 * lb);
  ASSERT_GT(lb, 1);  // the grey room's interreflection
  const double p = guth(std::acos(2 / r) * 180 / kPi, 0);
  const double ugr = 8 * std::log10(0.25 / lb * lum * lum * omega / (p * p));
  std::printf("[ measured ] UGR %.3f (by hand %.3f), L_b %.2f cd/m², P %.3f\n",
              g["ugr"].get<double>(), ugr, lb, p);
  EXPECT_NEAR(g["ugr"].get<double>(), ugr, 0.01);
  // The same through a state that dims it to a half: L falls by 2, L_b by 2, UGR by 8·log10 2.
  const fs::path half = dir.write("half.json", R"({"luminaires": {"panel": {"dimmer": 0.5}}})");
  const nlohmann::json dimmed =
      glare(rlt, "--state '" + half.string() + "' --observer 2,1.2,1 --view 0,0,1");
  EXPECT_NEAR(dimmed["ugr"].get<double>(), ugr - 8 * std::log10(2.0), 0.01);
}

// The CIE 190:2010 standard-condition UGR table's reference room: luminaires H = 2 m above the
// eye (1.2 m), a regular array at spacing-to-height 1:1 (S = H; rows at S/2 from the walls), the
// room 4H across the line of sight and 8H along it (X = 8 m, Y = 16 m: N = 4 × 8 = 32, room index
// k = XY / (H(X + Y)) = 2.67), ceiling / walls / floor reflectances 0.7 / 0.5 / 0.2, the eye at
// the middle of the short wall looking horizontally along the room. The luminaire: the tabulated
// LDT of a 50 × 40 mm opening (shared photometry files). CIE 190's value, computed here as the
// standard does: Σ L²ω/p² over the array from the luminaire's intensity table (L = I/A_p,
// ω = A_p/r², A_p = the opening's area · cos γ; Guth's p), and the background L_b = E_WID/π from
// the tabular method's flux transfer, E_WID = (Φ·N/A_w)·F_UWID with A_w = 2H(X + Y) the walls
// between the reference plane and the luminaires, F_UWID = F_DF·F_T,FW + F_DW·F_T,WW−1 +
// F_DC·F_T,CW: F_DF the fraction of the lamp flux falling directly on the reference plane
// (Σ F_GL,i·Φ_zL,i over the cumulative zonal fluxes to 41.4°, 60°, 75.5° and 90°, from 10° zones),
// F_DW the rest of the downward flux, F_DC the upward, and for k = 2.67 the geometry factors
// F_GL = 0.280, 0.165, 0.499, 0.006 (CIE 190:2010 Table 4) and the transfer factors at
// 0.7/0.5/0.2 F_T,FW = 0.115, F_T,WW−1 = 0.211, F_T,CW = 0.307 (Table 5). `relight glare` gets L_b
// from the room's own interreflection instead (precomputed transfer); the acceptance: within 1 UGR
// unit of the tabular value.
TEST(GlareCommand, UgrInTheCie190StandardRoomIsItsTabularValueWithinOneUnit) {
  const std::filesystem::path ldt = std::filesystem::path(RELIGHT_SHARED_DIR) / "data" /
                                    "photometry" / "photometric-viewer" / "ldt" /
                                    "rectangular_luminaire_rectangular_luminous_opening.ldt";
  if (!std::filesystem::exists(ldt)) GTEST_SKIP() << "shared photometry files not found";
  const double h = 2, eye = 1.2, x_size = 4 * h, y_size = 8 * h, top = eye + h + 0.05;
  const Vec3 ex{1, 0, 0}, ey{0, 1, 0}, ez{0, 0, 1};
  nlohmann::json geometry = nlohmann::json::array();
  using testing::quad;
  geometry.push_back(quad({0, 0, 0}, ez * y_size, ex * x_size, "floor"));
  geometry.push_back(quad({0, top, 0}, ex * x_size, ez * y_size, "ceiling"));
  geometry.push_back(quad({0, 0, 0}, ex * x_size, ey * top, "walls"));
  geometry.push_back(quad({0, 0, y_size}, ey * top, ex * x_size, "walls"));
  geometry.push_back(quad({0, 0, 0}, ey * top, ez * y_size, "walls"));
  geometry.push_back(quad({x_size, 0, 0}, ez * y_size, ey * top, "walls"));
  nlohmann::json luminaires = nlohmann::json::array();
  std::vector<Vec3> positions;
  for (double x = h / 2; x < x_size; x += h) {
    for (double z = h / 2; z < y_size; z += h) {
      positions.push_back({x, eye + h, z});
      std::string name = "L";
      name += std::to_string(luminaires.size());
      luminaires.push_back({{"name", name},
                            {"position", {x, eye + h, z}},
                            {"aim", {0, -1, 0}},
                            {"distribution", {{"type", "ldt"}, {"file", ldt.string()}}}});
    }
  }
  ASSERT_EQ(positions.size(), 32u);
  const nlohmann::json scene = {{"materials",
                                 {{"ceiling", {{"albedo", {0.7, 0.7, 0.7}}}},
                                  {"walls", {{"albedo", {0.5, 0.5, 0.5}}}},
                                  {"floor", {{"albedo", {0.2, 0.2, 0.2}}}}}},
                                {"geometry", geometry},
                                {"luminaires", luminaires},
                                {"precompute", {{"max_edge", 0.5}, {"gather_rays", 64}}}};
  const TempDir dir;
  // The eye 2 cm off the wall; the table's on it.
  const nlohmann::json g =
      glare(precompute(dir, scene, "cie190"), "--observer 4,1.2,0.02 --view 0,0,1");
  const Vec3 observer{x_size / 2, eye, 0};

  // The tabular value.
  const PhotometricWeb web = load_ldt(ldt);
  const LuminousOpening opening = ldt_luminous_opening(parse_ldt(testing::read_text(ldt), ldt));
  double sum = 0;
  for (const Vec3& p : positions) {
    const double t = p.x - observer.x, r = p.z - observer.z;  // across and along the sight
    const double d = std::sqrt(t * t + r * r + h * h), gamma = std::atan2(std::hypot(t, r), h);
    ASSERT_LE(std::abs(t) / r, 3.0);  // CIE 117's limits of the position index
    ASSERT_LE(gamma, radians(85.0));
    const double i = intensity(web, std::atan2(t, r), gamma);
    const double area = opening.width_m * opening.length_m * std::cos(gamma);
    const double sigma = std::acos(r / d) * 180 / kPi, tau = std::atan2(std::abs(t), h) * 180 / kPi;
    const double pos = guth(sigma, tau);
    sum += i * i / (area * d * d) / (pos * pos);
  }
  // Zonal fluxes of 10° zones from their mid-zone intensities (mean over C), scaled to the
  // luminaire's flux.
  std::vector<double> zone(18);
  double total = 0;
  for (int k = 0; k < 18; ++k) {
    const double g_mid = radians(10.0 * k + 5);
    double mean = 0;
    for (int c = 0; c < 24; ++c) mean += intensity(web, radians(15.0 * c), g_mid) / 24;
    zone[static_cast<std::size_t>(k)] = mean * 2 * kPi * std::sin(g_mid) * radians(10.0);
    total += zone[static_cast<std::size_t>(k)];
  }
  for (double& z : zone) z *= flux_lm(web) / total;
  const auto cumulative = [&](int zones) {
    double c = 0;
    for (int k = 0; k < zones; ++k) c += zone[static_cast<std::size_t>(k)];
    return c;
  };
  const double down = cumulative(9), up = cumulative(18) - down;
  const double on_floor = 0.280 * (cumulative(4) + 0.130 * zone[4]) + 0.165 * cumulative(6) +
                          0.499 * (cumulative(7) + 0.547 * zone[7]) + 0.006 * cumulative(9);
  const double walls_area = 2 * h * (x_size + y_size);
  const double e_wid = static_cast<double>(positions.size()) / walls_area *
                       (on_floor * 0.115 + (down - on_floor) * 0.211 + up * 0.307);
  const double lb = e_wid / kPi, ugr = 8 * std::log10(0.25 / lb * sum);
  std::printf(
      "[ measured ] CIE 190 standard room: UGR %.2f (tabular %.2f), L_b %.2f cd/m² "
      "(tabular %.2f)\n",
      g["ugr"].get<double>(), ugr, g["background_luminance"].get<double>(), lb);
  RecordProperty("ugr", std::to_string(g["ugr"].get<double>()));
  RecordProperty("tabular_ugr", std::to_string(ugr));
  EXPECT_NEAR(g["ugr"].get<double>(), ugr, 1.0);
}

TEST(GlareCommand, BadArgumentsExitTwo) {
  const TempDir dir;
  testing::WindowRoom room;
  room.south_window = testing::kWindow;
  nlohmann::json scene = testing::window_room_json(room);
  scene["precompute"] = {{"max_edge", 1.0}, {"gather_rays", 8}};
  const fs::path rlt = precompute(dir, scene, "bad");
  const std::string base = "glare '" + rlt.string() + "' ";
  testing::expect_input_error(run_relight(base + "--observer 1,2 --view 0,0,1"), "--observer");
  testing::expect_input_error(run_relight(base + "--observer 1,2,3 --view 0,0,0"), "--view");
  testing::expect_input_error(run_relight(base + "--observer 1,2,nan --view 0,0,1"), "--observer");
  testing::expect_input_error(run_relight(base + "--camera nowhere"), "--camera");
  testing::expect_input_error(run_relight(base + "--view 0,0,1"), "glare");
}

}  // namespace
}  // namespace relight

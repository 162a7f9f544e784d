// `relight glare` (issue 17): DGP of a bright window view and UGR of one luminaire against the
// formulas evaluated by hand (Wienold & Christoffersen 2006; CIE 117-1995, the Guth position
// index written out again here), and bad arguments.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "run_command.h"
#include "support/daylight_room.h"

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

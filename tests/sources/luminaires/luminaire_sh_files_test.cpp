// Every public IES / EULUMDAT file in shared/data/photometry projected onto order-8 SH
// (sources/luminaires/luminaire_sh.h) and aimed three ways: the flux of the series (sqrt(4π)·w_00)
// must match the web's exact flux. Files the loader refuses (type B, truncated tables) are skipped;
// the whole test skips when shared/ is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "common/input_error.h"
#include "light/ies_parser.h"
#include "light/ldt_parser.h"
#include "light/luminaire_frame.h"
#include "math/sh.h"
#include "sources/luminaires/luminaire_sh.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

TEST(LuminaireShFiles, EveryFileKeepsItsFluxWithinOnePercent) {
  const fs::path folder = fs::path(RELIGHT_SHARED_DIR) / "data" / "photometry";
  if (!fs::is_directory(folder)) GTEST_SKIP() << folder << " not present";
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (entry.is_regular_file() && (ext == ".ies" || ext == ".ldt")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());

  // Straight down with C0 along +x; tilted with a C0 that is neither an axis nor the
  // default; straight up with C0 along −z.
  struct Aim {
    Vec3 aim, c0;
  };
  const Vec3 tilted = normalize(Vec3{0.4, -0.8, 0.45});
  const std::vector<Aim> aims = {{{0, -1, 0}, {1, 0, 0}},
                                 {tilted, normalize(cross(tilted, Vec3{0.3, 0.5, -0.8}))},
                                 {{0, 1, 0}, {0, 0, -1}}};
  const bool verbose = std::getenv("RELIGHT_VERBOSE") != nullptr;
  int projected = 0, refused = 0, c_dependent = 0;
  double worst = 1.0, worst_brute = 0.0;
  std::string worst_file;
  // End-to-end check of the aimed coefficients of every C-dependent file: a brute-force
  // projection of I(to_photometric(ω)) over the world sphere (no windows, no rotation code).
  const SphereQuadrature brute_rule = sphere_quadrature(240, 480);
  for (const fs::path& file : files) {
    const std::string name = fs::relative(file, folder).generic_string();
    SCOPED_TRACE(name);
    PhotometricWeb web;
    try {
      const bool ies = file.extension() == ".ies" || file.extension() == ".IES";
      web = ies ? load_ies(file) : load_ldt(file);
    } catch (const InputError&) {
      ++refused;
      continue;
    }
    const Distribution d{std::move(web)};
    const double flux = d.flux_lm();
    ASSERT_GT(flux, 0.0);
    c_dependent += d.axisymmetric() ? 0 : 1;
    const LocalLuminaireSh local = project_luminaire_local(d, {.order = 8});
    double file_worst = 1.0;
    for (const Aim& a : aims) {
      const double ratio = sh_flux_lm(aim_luminaire_sh(local, a.aim, a.c0)) / flux;
      EXPECT_NEAR(ratio, 1.0, 0.01);
      if (std::abs(ratio - 1.0) > std::abs(file_worst - 1.0)) file_worst = ratio;
    }
    if (!d.axisymmetric()) {
      const Aim& a = aims[1];
      const PlacedLuminaire placed{{0, 0, 0}, photometric_frame(a.aim, a.c0), Rgb{1, 1, 1}, d};
      const auto ours = luminaire_world_sh(d, a.aim, a.c0, {.order = 8, .window = ShWindow::kNone});
      const auto brute = sh_project(
          8, [&](Vec3 w) { return d.intensity(placed.frame.to_photometric(w)); }, brute_rule);
      double diff = 0.0, scale = 0.0;
      for (std::size_t i = 0; i < ours.size(); ++i) {
        diff = std::max(diff, std::abs(ours[i] - brute[i]));
        scale = std::max(scale, std::abs(brute[i]));
      }
      EXPECT_LT(diff / scale, 2e-3);
      worst_brute = std::max(worst_brute, diff / scale);
    }
    if (std::abs(file_worst - 1.0) > std::abs(worst - 1.0)) {
      worst = file_worst;
      worst_file = name;
    }
    if (verbose) {
      std::cout << std::setprecision(15) << name << (d.axisymmetric() ? " (zonal)" : " (full)")
                << " flux " << flux << " lm, worst SH/web ratio " << file_worst << "\n";
    }
    ++projected;
  }
  EXPECT_GT(projected, 30);
  RecordProperty("files_projected", projected);
  RecordProperty("files_refused", refused);
  RecordProperty("worst_flux_ratio", std::to_string(worst));
  RecordProperty("worst_flux_file", worst_file);
  RecordProperty("worst_brute_force_difference", std::to_string(worst_brute));
  std::cout << std::setprecision(15) << projected << " files projected (" << c_dependent
            << " with C dependence), " << refused << " refused by the loader; worst flux ratio "
            << worst << " (" << worst_file << "); aimed C-dependent webs vs brute-force "
            << "projection: worst max|Δw| / max|w| = " << worst_brute << "\n";
}

}  // namespace
}  // namespace relight

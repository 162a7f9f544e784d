// A small bright source's shadow through the top-level environment (the cuts' first acceptance
// item; Iwasaki et al., Cyberworlds, §VI): a 0.5 × 0.5 × 2 m column on a floor under a map that
// holds one 0.5° source (∫L dω = 50,000 lx, 30° high in the west) and a dim uniform rest
// (1,000 cd/m²). The camera looks straight down at the side edge of the column's shadow 2 m from
// it, 512 × 512 pixels over 15 cm (0.29 mm a pixel). `relight render --direct pixel
// --max-bounces 1` against `relight reference --max-bounces 1` (16 samples a pixel): the
// luminance across the edge, averaged over every row, crosses 50 % of the way from the umbra
// to the lit floor within 1 pixel of where the reference's does, and its 10–90 % width is
// within 20 % of the reference's. The SH path blurs it: the same floor lit by the map projected
// to SH of l < 6 (the windows' shell order, scene portal_sh_order) with each point's transfer
// vector T_lm = ∫ V max(0, n·ω) Y_lm dω (the column's visibility, analytic) spreads the edge
// over tens of centimetres (printed next to the reference's width; asserted at least 10 times
// as wide).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_exr.h"
#include "light/environment.h"
#include "math/equirect.h"
#include "math/sh.h"
#include "run_command.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::run_relight;
using testing::TempDir;

constexpr int kMapWidth = 2048, kMapHeight = 1024;
constexpr double kSourceRadiusDeg = 0.25, kSourceLux = 50000, kRest = 1000;
constexpr double kAltitudeDeg = 30;
constexpr int kSize = 512;
constexpr double kView = 0.15;  // m across the image at the floor

Vec3 source_direction() {
  const double a = kAltitudeDeg * kPi / 180;
  return {-std::cos(a), std::sin(a), 0};  // from the west: the shadow runs east (+x)
}

// The map: the rest everywhere, the source's texels (centres within its radius) sharing its
// ∫L dω.
EquirectMap painted_map() {
  EquirectMap map{kMapWidth, kMapHeight, {}};
  map.texels.assign(static_cast<std::size_t>(kMapWidth) * kMapHeight, Rgb{kRest, kRest, kRest});
  const Vec3 s = source_direction();
  const double cos_r = std::cos(kSourceRadiusDeg * kPi / 180);
  std::vector<std::size_t> in;
  double omega = 0;
  for (int j = 0; j < kMapHeight; ++j) {
    for (int i = 0; i < kMapWidth; ++i) {
      if (dot(equirect_texel_direction(kMapWidth, kMapHeight, i, j), s) >= cos_r) {
        in.push_back(static_cast<std::size_t>(j) * kMapWidth + i);
        omega += equirect_row_solid_angle(kMapWidth, kMapHeight, j);
      }
    }
  }
  const double l = kSourceLux / omega;
  for (const std::size_t t : in) map.texels[t] = Rgb{l, l, l};
  return map;
}

struct Edge {
  double at10 = 0, at50 = 0, at90 = 0;  // columns (fractional) where the profile crosses
  double width() const { return std::abs(at90 - at10); }
};

// Where `profile` (dark at one end, lit at the other) crosses 10, 50 and 90 % of the way from
// its umbra to its lit level (each the mean of `m` values at its end), walking from the dark end.
Edge crossings(std::vector<double> profile, std::size_t m) {
  const std::size_t n = profile.size();
  double first = 0, last = 0;
  for (std::size_t i = 0; i < m; ++i) {
    first += profile[i] / m;
    last += profile[n - 1 - i] / m;
  }
  const bool flipped = first > last;
  if (flipped) std::reverse(profile.begin(), profile.end());
  const double dark = std::min(first, last), lit = std::max(first, last);
  const auto at = [&](double level) {
    const double y = dark + level * (lit - dark);
    for (std::size_t i = 1; i < n; ++i) {
      if (profile[i] >= y) {
        const double x =
            static_cast<double>(i - 1) + (y - profile[i - 1]) / (profile[i] - profile[i - 1]);
        return flipped ? static_cast<double>(n - 1) - x : x;
      }
    }
    return std::nan("");
  };
  return {at(0.1), at(0.5), at(0.9)};
}

// The mean luminance of every column of `image`.
std::vector<double> column_profile(const Image& image) {
  std::vector<double> out(static_cast<std::size_t>(image.width), 0.0);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      out[static_cast<std::size_t>(x)] += luminance(image.at(x, y)) / image.height;
    }
  }
  return out;
}

// Whether the ray from p along d meets the column (the box [-0.25, 0.25] × [0, 2] × [-0.25,
// 0.25]): the slab test.
bool column_blocks(Vec3 p, Vec3 d) {
  const double lo[3] = {-0.25, 0, -0.25}, hi[3] = {0.25, 2, 0.25};
  const double o[3] = {p.x, p.y, p.z}, v[3] = {d.x, d.y, d.z};
  double t0 = 0, t1 = 1e30;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(v[k]) < 1e-15) {
      if (o[k] < lo[k] || o[k] > hi[k]) return false;
      continue;
    }
    double a = (lo[k] - o[k]) / v[k], b = (hi[k] - o[k]) / v[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return false;
  }
  return true;
}

TEST(EnvironmentPenumbra, ASmallSourcesShadowEdgeAndPenumbraAreWhereTheReferencePutsThem) {
  TempDir dir;
  const fs::path map_file = dir.path() / "source.exr";
  const EquirectMap map = painted_map();
  {
    Image image = make_image(map.width, map.height);
    image.pixels = map.texels;
    write_exr(map_file, image, ExrChannels::kFloat);
  }
  const fs::path scene = dir.path() / "column.json", rlt = dir.path() / "column.rlt";
  std::ofstream(scene) << R"({
    "materials": {"floor": {"albedo": [0.5, 0.5, 0.5]}, "paint": {"albedo": [0.7, 0.7, 0.7]}},
    "geometry": [
      {"type": "quad", "corner": [-4, 0, -4], "u": [0, 0, 8], "v": [8, 0, 0], "material": "floor"},
      {"type": "box", "min": [-0.25, 0, -0.25], "max": [0.25, 2, 0.25], "material": "paint"}
    ],
    "environment": {"type": "map", "file": ")" +
                              map_file.string() + R"("},
    "precompute": {"max_edge": 0.2, "gather_rays": 64, "cuts": {"directions": 8192}},
    "cameras": [{"name": "edge", "eye": [2, 0.6, 0.25], "target": [2, 0, 0.25], "up": [1, 0, 0],
                 "fov_deg": )" +
                              std::to_string(2 * std::atan(0.5 * kView / 0.6) * 180 / kPi) +
                              R"(}]
  })";
  CommandResult r =
      run_relight("precompute '" + scene.string() + "' -o '" + rlt.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string size = " --width " + std::to_string(kSize) + " --height " +
                           std::to_string(kSize) + " --max-bounces 1 ";
  const fs::path fast = dir.path() / "fast.exr", truth = dir.path() / "reference.exr";
  r = run_relight("render '" + rlt.string() + "' --direct pixel" + size + "-o '" + fast.string() +
                  "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_relight("reference '" + scene.string() + "' --spp 16 --seed 7" + size + "-o '" +
                  truth.string() + "' --no-progress");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Edge ours = crossings(column_profile(read_exr(fast)), 32);
  const Edge ref = crossings(column_profile(read_exr(truth)), 32);
  const double mm = 1000 * kView / kSize;
  std::printf(
      "0.5° source's shadow edge (px): ours 10/50/90 %% at %.2f / %.2f / %.2f, reference "
      "%.2f / %.2f / %.2f\n",
      ours.at10, ours.at50, ours.at90, ref.at10, ref.at50, ref.at90);
  std::printf(
      "edge %.2f px from the reference's; penumbra (10-90 %%) %.1f mm against %.1f mm "
      "(%.1f %%)\n",
      ours.at50 - ref.at50, ours.width() * mm, ref.width() * mm,
      100 * (ours.width() / ref.width() - 1));
  ASSERT_TRUE(std::isfinite(ours.at50) && std::isfinite(ref.at50));
  EXPECT_GT(ref.width(), 10);  // the penumbra is resolved: tens of pixels
  EXPECT_LE(std::abs(ours.at50 - ref.at50), 1.0);
  EXPECT_LE(std::abs(ours.width() / ref.width() - 1), 0.2);

  // The SH path along the same line (x = 2 m on the floor), 1 cm apart from the shadow's middle
  // out to 1.75 m beyond its edge; the umbra its middle's value, the lit level the far end's.
  Environment env = make_map_environment(std::make_shared<const EquirectMap>(map), 0, 1);
  constexpr int kOrder = 6;
  const std::vector<Rgb> light = environment_sh(env, kOrder);
  const SphereQuadrature q = sphere_quadrature(256, 512);
  std::vector<double> sh_profile, y(static_cast<std::size_t>(sh_count(kOrder)));
  for (int k = -25; k <= 175; ++k) {
    const Vec3 p{2, 1e-6, 0.25 + 0.01 * k};
    std::vector<double> transfer(y.size(), 0.0);
    for (std::size_t d = 0; d < q.directions.size(); ++d) {
      const Vec3 w = q.directions[d];
      if (w.y <= 0 || column_blocks(p, w)) continue;
      sh_eval(kOrder, w, y);
      for (std::size_t c = 0; c < y.size(); ++c) transfer[c] += q.weights[d] * w.y * y[c];
    }
    double e = 0;
    for (std::size_t c = 0; c < y.size(); ++c) e += luminance(light[c]) * transfer[c];
    sh_profile.push_back(e);
  }
  const Edge sh = crossings(sh_profile, 1);
  std::printf("SH l < %d: penumbra (10-90 %%) %.0f mm (the reference's %.1f mm)\n", kOrder,
              10 * sh.width(), ref.width() * mm);
  EXPECT_GT(10 * sh.width(), 10 * ref.width() * mm);
}

}  // namespace
}  // namespace relight

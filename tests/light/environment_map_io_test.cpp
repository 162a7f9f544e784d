// Environment map files: OpenEXR and Radiance .hdr into equirectangular maps, Blender's DWAB
// studio-light worlds (Debian blender-data), and errors as "FILE: reason".
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>
#include "support/cubemap_integral.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <vector>

#include "common/input_error.h"
#include "image/image_exr.h"
#include "light/environment_map_io.h"
#include "math/cubemap.h"
#include "math/equirect.h"
#include "support/temp_dir.h"

namespace relight {
namespace {

namespace fs = std::filesystem;

std::string error_of(const fs::path& path) {
  try {
    read_environment_map(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

using testing::cube_integral;

TEST(EnvironmentMapIo, ReadsExr) {
  testing::TempDir dir;
  Image image = make_image(16, 8, {100, 200, 300});
  image.at(3, 1) = {5000, 6000, 7000};
  image.at(0, 7) = {-0.5, 1, 2};  // negative values read as 0
  write_exr(dir.path() / "env.exr", image);
  const EquirectMap map = read_environment_map(dir.path() / "env.exr");
  EXPECT_EQ(map.width, 16);
  EXPECT_EQ(map.height, 8);
  // Half floats: relative precision 2^-11.
  EXPECT_NEAR(map.texels[1 * 16 + 3].g, 6000, 6000 * 1e-3);
  EXPECT_NEAR(map.texels[0].b, 300, 300 * 1e-3);
  EXPECT_EQ(map.texels[7 * 16 + 0].r, 0.0);
}

TEST(EnvironmentMapIo, ReadsRadianceHdr) {
  testing::TempDir dir;
  const int w = 32, h = 16;
  std::vector<float> rgb(3 * w * h, 0.25f);
  rgb[3 * (2 * w + 5) + 0] = 1000.0f;  // texel (5, 2): red
  const fs::path file = dir.path() / "Env.HDR";
  ASSERT_NE(stbi_write_hdr(file.c_str(), w, h, 3, rgb.data()), 0);
  const EquirectMap map = read_environment_map(file);
  EXPECT_EQ(map.width, w);
  EXPECT_EQ(map.height, h);
  // RGBE keeps 8 mantissa bits per channel (relative error < 2^-8 of the largest channel).
  EXPECT_NEAR(map.texels[2 * w + 5].r, 1000.0, 1000.0 / 128);
  EXPECT_NEAR(map.texels[0].g, 0.25, 0.25 / 128);
  // Top row first: the texel is above the horizon, in the north-east quarter.
  const Vec3 d = equirect_texel_direction(w, h, 5, 2);
  EXPECT_GT(d.y, 0.5);
  EXPECT_GT(d.x, 0);
  EXPECT_LT(d.z, 0);
}

// A map declaring more pixels than the caller's bound is refused before decoding, EXR and .hdr.
TEST(EnvironmentMapIo, AMapOfMorePixelsThanTheBoundIsRefused) {
  testing::TempDir dir;
  const int w = 32, h = 16;
  write_exr(dir.path() / "env.exr", make_image(w, h, {1, 2, 3}));
  const std::vector<float> rgb(3 * w * h, 0.25f);
  const fs::path hdr = dir.path() / "env.hdr";
  ASSERT_NE(stbi_write_hdr(hdr.c_str(), w, h, 3, rgb.data()), 0);
  for (const fs::path& file : {dir.path() / "env.exr", hdr}) {
    EXPECT_EQ(read_environment_map(file, w * h).width, w) << file;
    try {
      read_environment_map(file, w * h - 1);
      ADD_FAILURE() << "no exception for " << file;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string() + ": ", 0), 0u) << what;
      EXPECT_TRUE(what.find("32x16") != std::string::npos ||
                  what.find("32 × 16 pixels, more than 511") != std::string::npos)
          << what;
    }
  }
}

TEST(EnvironmentMapIo, Errors) {
  testing::TempDir dir;
  EXPECT_EQ(error_of(dir.path() / "missing.exr"),
            (dir.path() / "missing.exr").string() + ": no such file");
  const fs::path png = dir.write("x.png", "not an image");
  EXPECT_NE(error_of(png).find(png.string() + ": unsupported environment map type \".png\""),
            std::string::npos);
  const fs::path fake_exr = dir.write("fake.exr", "not an exr");
  EXPECT_NE(error_of(fake_exr).find(fake_exr.string() + ": not an OpenEXR file"),
            std::string::npos);
  const fs::path fake_hdr = dir.write("fake.hdr", "not an hdr");
  EXPECT_NE(error_of(fake_hdr).find(fake_hdr.string() + ": not a Radiance HDR"), std::string::npos);
  write_exr(dir.path() / "square.exr", make_image(8, 8, {1, 1, 1}));
  EXPECT_NE(error_of(dir.path() / "square.exr").find("twice as wide as tall, got 8×8"),
            std::string::npos);
  Image nan = make_image(8, 4, {1, 1, 1});
  nan.at(2, 3) = {std::nan(""), 1, 1};
  write_exr(dir.path() / "nan.exr", nan);
  EXPECT_NE(error_of(dir.path() / "nan.exr").find("texel (2, 3) is not finite"), std::string::npos);
}

// stb decodes the bytes a flat .hdr lacks as zeros; relight refuses a file whose pixel data is
// shorter than its resolution needs (4 bytes a pixel flat; 4 + 8⌈W/127⌉ bytes a run-length
// scanline), naming the sizes, before decoding.
TEST(EnvironmentMapIo, TruncatedRadianceHdrIsRefusedBeforeDecoding) {
  testing::TempDir dir;
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";
  // Flat (W < 8): 4 × 2 pixels need 32 bytes; 31 are there.
  const fs::path flat = dir.write("flat.hdr", header + "-Y 2 +X 4\n" + std::string(31, '\x80'));
  EXPECT_NE(error_of(flat).find(flat.string() +
                                ": declares 4 × 2 pixels but holds 31 bytes of them (at least 32 "
                                "needed): truncated"),
            std::string::npos)
      << error_of(flat);
  // 32 bytes are enough for the check (stb then decodes them).
  const fs::path whole = dir.write("whole.hdr", header + "-Y 2 +X 4\n" + std::string(32, '\x80'));
  EXPECT_EQ(error_of(whole), "");
  // A few bytes declaring 2^24 × 2^23 pixels: refused at once, not decoded from zeros.
  const fs::path huge = dir.write(
      "huge.hdr", header + "-Y 8388608 +X 16777216\n" + std::string("\x02\x02\x00\x10", 4));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NE(error_of(huge).find("declares 16777216 × 8388608 pixels but holds 4 bytes"),
            std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  // A run-length file (stb writes runs for 8 ≤ W < 32768): a constant row is 4 + 4 runs of 2
  // bytes, the minimum, so one byte less is refused.
  const int w = 64, h = 32;
  const std::vector<float> rgb(3 * w * h, 0.5f);
  const fs::path rle = dir.path() / "rle.hdr";
  ASSERT_NE(stbi_write_hdr(rle.c_str(), w, h, 3, rgb.data()), 0);
  EXPECT_EQ(error_of(rle), "");
  fs::resize_file(rle, fs::file_size(rle) - 1);
  EXPECT_NE(error_of(rle).find("declares 64 × 32 pixels but holds 383 bytes of them (at least "
                               "384 needed)"),
            std::string::npos)
      << error_of(rle);
}

// Debian's stb loops forever on a run of length 0 in a run-length .hdr (make fuzz found a
// 93-byte file hanging relight); relight refuses such runs, naming the scanline, and a file
// that ends inside its runs.
TEST(EnvironmentMapIo, ARunOfZeroOrTheFileEndingInsideTheRunsIsRefused) {
  testing::TempDir dir;
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n";
  // A scanline of width 8: each component one run of 8 (0x88) of one byte value.
  const std::string row("\x02\x02\x00\x08\x88\x80\x88\x40\x88\x20\x88\x82", 12);
  EXPECT_EQ(error_of(dir.write("good.hdr", header + row + row + row + row)), "");
  std::string zero = row;
  zero[8] = 0;  // the third component's run: a literal of length 0
  const fs::path bad = dir.write("zero.hdr", header + row + zero + row + row);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NE(error_of(bad).find(bad.string() +
                               ": bad run-length data in scanline 1: a run of 0 where 8 values "
                               "are left"),
            std::string::npos)
      << error_of(bad);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  std::string longer = row;
  longer[4] = '\x89';  // a run of 9 in a scanline of 8
  EXPECT_NE(error_of(dir.write("long.hdr", header + longer + row + row + row))
                .find("scanline 0: a run of 9 where 8 values are left"),
            std::string::npos);
  const fs::path cut =
      dir.write("cut.hdr", header + row + row.substr(0, 9) + std::string(40, '\0'));
  EXPECT_NE(error_of(cut).find("bad run-length data in scanline 1"), std::string::npos)
      << error_of(cut);
}

TEST(EnvironmentMapIo, LoadEnvironmentFromSpec) {
  testing::TempDir dir;
  write_exr(dir.path() / "env.exr", make_image(16, 8, {10, 10, 10}));
  EnvironmentSpec spec;
  spec.type = EnvironmentType::kMap;
  spec.file = dir.path() / "env.exr";
  spec.scale = 3;
  const Environment env = load_environment(spec);
  EXPECT_EQ(env.kind, EnvironmentKind::kMap);
  EXPECT_NEAR(env.radiance({0, 1, 0}).g, 30, 1e-9);
  EXPECT_NEAR(luminance(environment_integral(env)), 4 * kPi * 30, 1e-9);
  spec.type = EnvironmentType::kUniform;
  spec.luminance = 7;
  EXPECT_NEAR(load_environment(spec).radiance({1, 0, 0}).g, 7, 1e-12);
}

// Blender's studio-light worlds are DWAB-compressed OpenEXR panoramas.
TEST(EnvironmentMapIo, BlenderStudioLightWorlds) {
  const fs::path folder = "/usr/share/blender/datafiles/studiolights/world";
  if (!fs::is_directory(folder)) GTEST_SKIP() << "blender-data is not installed";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".exr") continue;
    const auto start = std::chrono::steady_clock::now();
    EnvironmentSpec spec;
    spec.type = EnvironmentType::kMap;
    spec.file = entry.path();
    const Environment env = load_environment(spec);
    const double loaded =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(env.map->width, 2 * env.map->height) << entry.path();
    const double total = luminance(environment_integral(env));
    EXPECT_TRUE(std::isfinite(total) && total > 0) << entry.path();
    const auto cube_start = std::chrono::steady_clock::now();
    const std::vector<Rgb> cube = environment_cubemap(env, 32);
    const double cubed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - cube_start).count();
    const double cube_total = cube_integral(cube, 32);
    EXPECT_NEAR(cube_total, total, 1e-6 * total) << entry.path();
    const std::vector<Rgb> sh = environment_sh(env, 6);
    EXPECT_NEAR(luminance(sh[0]) * std::sqrt(4 * kPi), total, 1e-9 * total);
    std::cout << "[ measured ] " << entry.path().filename().string() << ": " << env.map->width
              << "×" << env.map->height << ", ∫L dω = " << total << " (Y), load " << loaded
              << " s, cubemap 32 " << cubed << " s, Σ LΩ/∫ - 1 = " << cube_total / total - 1
              << "\n";
    ++files;
  }
  EXPECT_GT(files, 0);
}

}  // namespace
}  // namespace relight

// Base colour textures (scene/surface_texture.h): the pyramid's levels are box means of the
// sRGB-decoded texels, wrap modes follow glTF's samplers, the footprint picks the level, and a
// prepared vertex takes the texture's mean over its footprint — exact for a uniform texture,
// the mean of a fine checker when the vertex spacing spans many of its periods.
#include "scene/surface_texture.h"

#include <gtest/gtest.h>

#include "image/photo.h"
#include "math/srgb.h"
#include "scene/mesh_preparation.h"
#include "scene/triangle_soup.h"

namespace relight {
namespace {

// A width × height photo whose texel (x, y) has code `code(x, y)` in every channel.
template <typename Code>
Photo grey_photo(int width, int height, Code code) {
  Photo p;
  p.width = width;
  p.height = height;
  p.rgb.resize(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t at = p.offset(x, y);
      p.rgb[at] = p.rgb[at + 1] = p.rgb[at + 2] = static_cast<std::uint16_t>(code(x, y));
    }
  }
  return p;
}

TEST(SurfaceTexture, LevelsAreBoxMeansOfDecodedTexelsDownToOneTexel) {
  const Photo photo = grey_photo(4, 2, [](int x, int) { return x * 60; });
  const SurfaceTexture t = make_surface_texture(photo, TextureWrap::kRepeat, TextureWrap::kRepeat);
  ASSERT_EQ(t.levels.size(), 3u);
  EXPECT_EQ(t.levels[1].width, 2);
  EXPECT_EQ(t.levels[1].height, 1);
  EXPECT_EQ(t.levels[2].width, 1);
  double mean = 0;
  for (int x = 0; x < 4; ++x) mean += srgb_decode(x * 60 / 255.0) / 4;
  EXPECT_NEAR(t.levels[2].rgb[0], mean, 1e-6);
  EXPECT_NEAR(t.levels[0].rgb[3], srgb_decode(60 / 255.0), 1e-6);
}

TEST(SurfaceTexture, TexelCentresAndWrapModesWithin1e6) {
  const Photo photo = grey_photo(4, 1, [](int x, int) { return 50 * (x + 1); });
  const auto code = [](int x) { return srgb_decode(50.0 * (x + 1) / 255.0); };
  const SurfaceTexture repeat =
      make_surface_texture(photo, TextureWrap::kRepeat, TextureWrap::kRepeat);
  EXPECT_NEAR(sample_surface_texture(repeat, 0.375, 0.5, 1).r, code(1), 1e-6);
  EXPECT_NEAR(sample_surface_texture(repeat, 1.375, 0.5, 1).r, code(1), 1e-6);
  EXPECT_NEAR(sample_surface_texture(repeat, -0.625, 0.5, 1).r, code(1), 1e-6);
  // Halfway between the last texel and the first one, across the seam.
  EXPECT_NEAR(sample_surface_texture(repeat, 1.0, 0.5, 1).r, 0.5 * (code(3) + code(0)), 1e-6);
  const SurfaceTexture clamp =
      make_surface_texture(photo, TextureWrap::kClampToEdge, TextureWrap::kClampToEdge);
  EXPECT_NEAR(sample_surface_texture(clamp, 1.0, 0.5, 1).r, code(3), 1e-6);
  EXPECT_NEAR(sample_surface_texture(clamp, 7.0, 0.5, 1).r, code(3), 1e-6);
  const SurfaceTexture mirror =
      make_surface_texture(photo, TextureWrap::kMirroredRepeat, TextureWrap::kRepeat);
  EXPECT_NEAR(sample_surface_texture(mirror, 1.125, 0.5, 1).r, code(3), 1e-6);
  EXPECT_NEAR(sample_surface_texture(mirror, 1.375, 0.5, 1).r, code(2), 1e-6);
  // A footprint of the whole image reads its mean, anywhere.
  const double mean = (code(0) + code(1) + code(2) + code(3)) / 4;
  EXPECT_NEAR(sample_surface_texture(repeat, 0.1, 0.3, 4).r, mean, 1e-6);
  EXPECT_NEAR(sample_surface_texture(repeat, 0.1, 0.3, 1e9).r, mean, 1e-6);
}

// A 2 m square floor of two triangles, UVs (0, 0)..(repeats, repeats), texture index 0.
TriangleSoup textured_floor(std::shared_ptr<const SurfaceTexture> texture, float repeats) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}};
  soup.triangle_material = {0, 0};
  soup.textures.textures = {std::move(texture)};
  soup.textures.triangle_texture = {0, 0};
  soup.textures.corner_uv = {{0, 0}, {repeats, 0},       {repeats, repeats},
                             {0, 0}, {repeats, repeats}, {0, repeats}};
  return soup;
}

TEST(SurfaceTexture, UniformTextureGivesEveryVertexItsValueWithin1e6) {
  const auto texture = std::make_shared<const SurfaceTexture>(make_surface_texture(
      grey_photo(8, 8, [](int, int) { return 90; }), TextureWrap::kRepeat, TextureWrap::kRepeat));
  PreparationSettings settings;
  settings.max_edge = 0.3;
  const PreparedMesh mesh = prepare_mesh(textured_floor(texture, 3), settings);
  ASSERT_EQ(mesh.vertex_texture.size(), mesh.positions.size());
  for (const Rgb& t : mesh.vertex_texture) EXPECT_NEAR(t.g, srgb_decode(90 / 255.0), 1e-6);
}

// A checker of 1-texel squares repeated 64 times over 2 m (period 3 cm) under vertices some
// 0.3 m apart: every vertex reads the checker's mean within 2%, where a point sample would
// read black or white.
TEST(SurfaceTexture, FineCheckerAveragesOverTheVertexFootprintWithin2Percent) {
  const auto texture = std::make_shared<const SurfaceTexture>(
      make_surface_texture(grey_photo(2, 2, [](int x, int y) { return (x + y) % 2 ? 255 : 0; }),
                           TextureWrap::kRepeat, TextureWrap::kRepeat));
  PreparationSettings settings;
  settings.max_edge = 0.3;
  const PreparedMesh mesh = prepare_mesh(textured_floor(texture, 64), settings);
  ASSERT_GT(mesh.positions.size(), 50u);
  for (const Rgb& t : mesh.vertex_texture) EXPECT_NEAR(t.r, 0.5, 0.01);
}

TEST(SurfaceTexture, AppendingGivesUntexturedTrianglesMinusOneAndOffsetsIndices) {
  const auto texture = std::make_shared<const SurfaceTexture>(make_surface_texture(
      grey_photo(1, 1, [](int, int) { return 255; }), TextureWrap::kRepeat, TextureWrap::kRepeat));
  TriangleSoup all;
  TriangleSoup plain;
  plain.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  plain.triangles = {{0, 1, 2}};
  plain.triangle_material = {0};
  all.append(plain);
  EXPECT_TRUE(all.textures.empty());
  all.append(textured_floor(texture, 1));
  all.append(textured_floor(texture, 1));
  all.append(plain);
  EXPECT_EQ(all.textures.triangle_texture, (std::vector<std::int32_t>{-1, 0, 0, 1, 1, -1}));
  EXPECT_EQ(all.textures.corner_uv.size(), 18u);
  EXPECT_EQ(all.textures.textures.size(), 2u);
  // The untextured vertex of the first triangle reads 1, the floor's the texture's 1.
  const PreparedMesh mesh = prepare_mesh(all, {});
  for (const Rgb& t : mesh.vertex_texture) EXPECT_NEAR(t.b, 1.0, 1e-6);
}

}  // namespace
}  // namespace relight

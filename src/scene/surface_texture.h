// Base colour textures (Khronos, glTF 2.0 specification, 2021, §3.9.2
// "pbrMetallicRoughness.baseColorTexture" and §3.8.4 "Samplers"): what relight keeps of a glTF
// material's texture, and how surfaces sample it. The albedo is the material's base colour times
// the texture (glTF: baseColorFactor × texture), linear (the file's sRGB decoded, math/srgb.h).
// Transfer is per vertex, so the fast path takes the texture as the albedo of the vertices
// ("sampled at the vertices"): each vertex the texture's mean over its footprint (a square as wide
// as its incident edges' mean length), read trilinearly from a box-filtered pyramid — a point
// sample would alias a wood grain or a tiled floor whose period is finer than the vertex spacing.
// The reference tracer samples the texture at each hit point at full resolution (texture_at), so it
// checks what the vertex sampling loses. Odd sizes lose their last row or column in the next level
// (a bias of at most one texel's share). Pinned by tests/scene/surface_texture_test.cpp and
// tests/cli/textured_room_test.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/triangle.h"

namespace relight {

struct Photo;

enum class TextureWrap { kRepeat, kClampToEdge, kMirroredRepeat };

struct TextureLevel {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 per texel, row-major, top row first; linear
};

struct SurfaceTexture {
  std::vector<TextureLevel> levels;  // [0] the image; each next one half the size, to 1 × 1
  TextureWrap wrap_u = TextureWrap::kRepeat, wrap_v = TextureWrap::kRepeat;
};

// The texture of a decoded image (sRGB 8 or 16 bits per channel).
SurfaceTexture make_surface_texture(const Photo& image, TextureWrap wrap_u, TextureWrap wrap_v);

// The texture's mean over a square of `footprint` level-0 texels (its side) centred at
// texture coordinates (u, v) — glTF's: (0, 0) the image's top-left corner, u to the right.
Rgb sample_surface_texture(const SurfaceTexture& texture, double u, double v, double footprint);

// Texture coordinates (u, v).
using TextureCoord = std::array<float, 2>;

// The base colour textures of a set of triangles: per triangle an index into `textures` or −1
// (none), and the texture coordinates of its three corners. All empty when no triangle has one.
struct TriangleTextures {
  std::vector<std::shared_ptr<const SurfaceTexture>> textures;
  std::vector<std::int32_t> triangle_texture;
  std::vector<TextureCoord> corner_uv;  // 3 per triangle, alongside triangle_texture

  bool empty() const { return triangle_texture.empty(); }
  // Appends `other`'s, for `triangles` triangles before and `other_triangles` after; a side
  // without textures takes −1.
  void append(const TriangleTextures& other, std::size_t triangles, std::size_t other_triangles);
};

// The textures of a prepared mesh's triangles (`positions`, `triangles`): each takes its soup
// triangle's texture (`source[t]`: the soup triangle prepared triangle t lies in) and the UVs
// of its corners interpolated there. Empty when `soup_textures` is.
TriangleTextures prepared_triangle_textures(const TriangleTextures& soup_textures,
                                            std::span<const Vec3> soup_positions,
                                            std::span<const Triangle> soup_triangles,
                                            std::span<const Vec3> positions,
                                            std::span<const Triangle> triangles,
                                            std::span<const std::uint32_t> source);

// Per vertex: the mean of its triangles' textures over its footprint (1 where none has one);
// `textures` per triangle (prepared_triangle_textures). Empty when `textures` is.
std::vector<Rgb> sample_vertex_textures(const TriangleTextures& textures,
                                        std::span<const Vec3> positions,
                                        std::span<const Triangle> triangles);

// The texture at barycentric (u, v) of triangle t (corner 0 weighs 1 − u − v), at full
// resolution (a point on a surface, as the reference tracer sees it); 1 without a texture.
Rgb texture_at(const TriangleTextures& textures, std::size_t t, double u, double v);

}  // namespace relight

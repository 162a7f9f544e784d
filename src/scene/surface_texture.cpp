#include "scene/surface_texture.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/photo.h"
#include "math/srgb.h"

namespace relight {
namespace {

// A texel coordinate wrapped into [0, n) by the sampler's mode.
int wrap(int i, int n, TextureWrap mode) {
  switch (mode) {
    case TextureWrap::kClampToEdge:
      return std::clamp(i, 0, n - 1);
    case TextureWrap::kMirroredRepeat: {
      const int period = 2 * n;
      const int k = ((i % period) + period) % period;
      return k < n ? k : period - 1 - k;
    }
    case TextureWrap::kRepeat:
      break;
  }
  return ((i % n) + n) % n;
}

// Half the size, each texel the mean of the 2 × 2 below it (clamped at an odd edge).
TextureLevel halve(const TextureLevel& fine) {
  TextureLevel coarse;
  coarse.width = std::max(1, fine.width / 2);
  coarse.height = std::max(1, fine.height / 2);
  coarse.rgb.assign(3 * static_cast<std::size_t>(coarse.width) * coarse.height, 0.0f);
  for (int y = 0; y < coarse.height; ++y) {
    for (int x = 0; x < coarse.width; ++x) {
      float* out = &coarse.rgb[3 * (static_cast<std::size_t>(y) * coarse.width + x)];
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          const int fx = std::min(2 * x + dx, fine.width - 1);
          const int fy = std::min(2 * y + dy, fine.height - 1);
          const float* in = &fine.rgb[3 * (static_cast<std::size_t>(fy) * fine.width + fx)];
          for (int c = 0; c < 3; ++c) out[c] += 0.25f * in[c];
        }
      }
    }
  }
  return coarse;
}

Rgb texel(const TextureLevel& level, int x, int y) {
  const float* p = &level.rgb[3 * (static_cast<std::size_t>(y) * level.width + x)];
  return {p[0], p[1], p[2]};
}

// Bilinear at (u, v) in one level, texel centres at half-integers.
Rgb bilinear(const SurfaceTexture& t, const TextureLevel& level, double u, double v) {
  const double x = u * level.width - 0.5, y = v * level.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  // Far-out coordinates (a mesh's UVs of 1e12) would overflow int: wrap them first.
  const auto cell = [](double c, int n) {
    const double period = 2.0 * n;
    return static_cast<int>(c - period * std::floor(c / period));
  };
  const int ix = cell(x0, level.width), iy = cell(y0, level.height);
  const int xa = wrap(ix, level.width, t.wrap_u), xb = wrap(ix + 1, level.width, t.wrap_u);
  const int ya = wrap(iy, level.height, t.wrap_v), yb = wrap(iy + 1, level.height, t.wrap_v);
  return (texel(level, xa, ya) * (1 - fx) + texel(level, xb, ya) * fx) * (1 - fy) +
         (texel(level, xa, yb) * (1 - fx) + texel(level, xb, yb) * fx) * fy;
}

}  // namespace

SurfaceTexture make_surface_texture(const Photo& image, TextureWrap wrap_u, TextureWrap wrap_v) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != 3 * static_cast<std::size_t>(image.width) * image.height) {
    throw std::invalid_argument("make_surface_texture: an image without its pixels");
  }
  // sRGB decoded once per code value.
  std::vector<float> decoded(static_cast<std::size_t>(image.max_value()) + 1);
  for (std::size_t i = 0; i < decoded.size(); ++i) {
    decoded[i] = static_cast<float>(srgb_decode(static_cast<double>(i) / image.max_value()));
  }
  SurfaceTexture t;
  t.wrap_u = wrap_u;
  t.wrap_v = wrap_v;
  TextureLevel base{image.width, image.height, {}};
  base.rgb.reserve(image.rgb.size());
  for (const std::uint16_t value : image.rgb) base.rgb.push_back(decoded[value]);
  t.levels.push_back(std::move(base));
  while (t.levels.back().width > 1 || t.levels.back().height > 1) {
    t.levels.push_back(halve(t.levels.back()));
  }
  return t;
}

Rgb sample_surface_texture(const SurfaceTexture& t, double u, double v, double footprint) {
  if (!std::isfinite(u) || !std::isfinite(v)) return bilinear(t, t.levels.back(), 0, 0);
  // Level L averages 2^L texels a side; between two levels, linearly in log2 of the footprint.
  const double level = std::clamp(std::log2(std::max(footprint, 1.0)), 0.0,
                                  static_cast<double>(t.levels.size() - 1));
  const auto fine = static_cast<std::size_t>(std::floor(level));
  const double f = level - static_cast<double>(fine);
  const Rgb a = bilinear(t, t.levels[fine], u, v);
  if (f == 0 || fine + 1 >= t.levels.size()) return a;
  return a * (1 - f) + bilinear(t, t.levels[fine + 1], u, v) * f;
}

void TriangleTextures::append(const TriangleTextures& other, std::size_t triangles,
                              std::size_t other_triangles) {
  if (other.empty()) {
    if (!empty()) {
      triangle_texture.resize(triangles + other_triangles, -1);
      corner_uv.resize(3 * (triangles + other_triangles), TextureCoord{0, 0});
    }
    return;
  }
  if (empty()) {
    triangle_texture.assign(triangles, -1);
    corner_uv.assign(3 * triangles, TextureCoord{0, 0});
  }
  const auto offset = static_cast<std::int32_t>(textures.size());
  textures.insert(textures.end(), other.textures.begin(), other.textures.end());
  for (const std::int32_t k : other.triangle_texture) {
    triangle_texture.push_back(k < 0 ? -1 : k + offset);
  }
  corner_uv.insert(corner_uv.end(), other.corner_uv.begin(), other.corner_uv.end());
}

TriangleTextures prepared_triangle_textures(const TriangleTextures& soup_textures,
                                            std::span<const Vec3> soup_positions,
                                            std::span<const Triangle> soup_triangles,
                                            std::span<const Vec3> positions,
                                            std::span<const Triangle> triangles,
                                            std::span<const std::uint32_t> source) {
  if (soup_textures.empty()) return {};
  if (source.size() != triangles.size() ||
      soup_textures.triangle_texture.size() != soup_triangles.size() ||
      soup_textures.corner_uv.size() != 3 * soup_triangles.size()) {
    throw std::invalid_argument("prepared_triangle_textures: sizes disagree");
  }
  TriangleTextures out;
  out.textures = soup_textures.textures;
  out.triangle_texture.reserve(triangles.size());
  out.corner_uv.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::size_t s = source[t];
    out.triangle_texture.push_back(soup_textures.triangle_texture[s]);
    const Triangle& st = soup_triangles[s];
    const Vec3 a = soup_positions[st[0]], b = soup_positions[st[1]], c = soup_positions[st[2]];
    const Vec3 n = cross(b - a, c - a);
    const double nn = dot(n, n);
    const TextureCoord ta = soup_textures.corner_uv[3 * s], tb = soup_textures.corner_uv[3 * s + 1],
                       tc = soup_textures.corner_uv[3 * s + 2];
    for (const std::uint32_t v : triangles[t]) {
      // Barycentrics of the corner in its soup triangle (it lies in it, or on its boundary).
      const Vec3 p = positions[v];
      const double wb = nn > 0 ? dot(cross(p - a, c - a), n) / nn : 0.0;
      const double wc = nn > 0 ? dot(cross(b - a, p - a), n) / nn : 0.0;
      const double wa = 1 - wb - wc;
      out.corner_uv.push_back({static_cast<float>(wa * ta[0] + wb * tb[0] + wc * tc[0]),
                               static_cast<float>(wa * ta[1] + wb * tb[1] + wc * tc[1])});
    }
  }
  return out;
}

std::vector<Rgb> sample_vertex_textures(const TriangleTextures& textures,
                                        std::span<const Vec3> positions,
                                        std::span<const Triangle> triangles) {
  if (textures.empty()) return {};
  if (textures.triangle_texture.size() != triangles.size() ||
      textures.corner_uv.size() != 3 * triangles.size()) {
    throw std::invalid_argument("sample_vertex_textures: sizes disagree");
  }
  // Footprint radius: half the mean length of the edges at the vertex.
  std::vector<double> edge_sum(positions.size(), 0.0);
  std::vector<int> edges(positions.size(), 0);
  for (const Triangle& t : triangles) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      const double l = length(positions[a] - positions[b]);
      edge_sum[a] += l;
      edge_sum[b] += l;
      ++edges[a];
      ++edges[b];
    }
  }
  std::vector<Rgb> sum(positions.size());
  std::vector<int> count(positions.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::int32_t k = textures.triangle_texture[t];
    if (k < 0) continue;
    const SurfaceTexture& texture = *textures.textures[static_cast<std::size_t>(k)];
    const Triangle& tri = triangles[t];
    const Vec3 a = positions[tri[0]], b = positions[tri[1]], c = positions[tri[2]];
    const TextureCoord ta = textures.corner_uv[3 * t], tb = textures.corner_uv[3 * t + 1],
                       tc = textures.corner_uv[3 * t + 2];
    // Texels per metre on this triangle: √(texel area / world area).
    const double world_area = 0.5 * length(cross(b - a, c - a));
    const double uv_area =
        0.5 * std::abs((tb[0] - ta[0]) * (tc[1] - ta[1]) - (tc[0] - ta[0]) * (tb[1] - ta[1]));
    const TextureLevel& base = texture.levels.front();
    const double density =
        world_area > 0 ? std::sqrt(uv_area * base.width * base.height / world_area) : 0.0;
    for (std::size_t corner = 0; corner < 3; ++corner) {
      const std::uint32_t v = tri[corner];
      const TextureCoord uv = textures.corner_uv[3 * t + corner];
      const double radius = edges[v] > 0 ? 0.5 * edge_sum[v] / edges[v] : 0.0;
      sum[v] += sample_surface_texture(texture, uv[0], uv[1], 2 * radius * density);
      ++count[v];
    }
  }
  std::vector<Rgb> out(positions.size(), Rgb{1, 1, 1});
  for (std::size_t v = 0; v < out.size(); ++v) {
    if (count[v] > 0) out[v] = sum[v] / count[v];
  }
  return out;
}

Rgb texture_at(const TriangleTextures& textures, std::size_t t, double u, double v) {
  if (textures.empty() || textures.triangle_texture[t] < 0) return {1, 1, 1};
  const TextureCoord a = textures.corner_uv[3 * t], b = textures.corner_uv[3 * t + 1],
                     c = textures.corner_uv[3 * t + 2];
  return sample_surface_texture(
      *textures.textures[static_cast<std::size_t>(textures.triangle_texture[t])],
      (1 - u - v) * a[0] + u * b[0] + v * c[0], (1 - u - v) * a[1] + u * b[1] + v * c[1], 1.0);
}

}  // namespace relight

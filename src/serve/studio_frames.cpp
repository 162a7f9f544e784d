#include "serve/studio_frames.h"

#include <algorithm>
#include <cmath>

#include <bit>
#include <cstring>
#include <stdexcept>

#include "material/lambert.h"
#include "math/cubemap.h"
#include "math/vec3.h"
#include "serve/half_float.h"

namespace relight {

static_assert(std::endian::native == std::endian::little,
              "the studio protocol is little-endian; this encoder writes native order");

namespace {

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

void put_tag(std::string& out, const char (&tag)[5]) {
  out.append(tag, 4);
}

double photometric(const float* rgb) {
  return luminance(Rgb{rgb[0], rgb[1], rgb[2]});
}

}  // namespace

std::string encode_geometry(const TransferFile& t) {
  const auto v = static_cast<std::uint32_t>(t.vertex_count);
  const auto n = static_cast<std::uint32_t>(t.triangles.size());
  std::string out;
  out.reserve(16 + 24 * std::size_t{v} + 16 * std::size_t{n});
  put_tag(out, "RLGE");
  put(out, kStudioProtocolVersion);
  put(out, v);
  put(out, n);
  for (std::size_t i = 0; i < v; ++i) {
    const Vec3 p = t.positions[i];
    put(out, static_cast<float>(p.x));
    put(out, static_cast<float>(p.y));
    put(out, static_cast<float>(p.z));
  }
  for (std::size_t i = 0; i < 3 * std::size_t{v}; ++i) put(out, t.vertex_albedo[i]);
  for (const Triangle& tri : t.triangles) {
    for (const std::uint32_t index : tri) put(out, index);
  }
  std::vector<std::uint32_t> code(n, 0);
  for (std::size_t k = 0; k < t.portal_triangles.size(); ++k) {
    code[t.portal_triangles[k]] = t.portal_of_triangle[k] + 1;
  }
  for (const std::uint32_t c : code) put(out, c);
  return out;
}

std::string encode_objects(std::span<const ObjectMesh> objects) {
  std::size_t bytes = 12;
  for (const ObjectMesh& o : objects)
    bytes += 8 + 24 * o.positions.size() + 12 * o.triangles.size();
  std::string out;
  out.reserve(bytes);
  put_tag(out, "RLOB");
  put(out, kStudioProtocolVersion);
  put(out, static_cast<std::uint32_t>(objects.size()));
  for (const ObjectMesh& o : objects) {
    const std::size_t v = o.positions.size();
    if (o.albedo.size() != 3 * v) {
      throw std::invalid_argument("encode_objects: object \"" + o.name +
                                  "\" has no albedo per vertex");
    }
    put(out, static_cast<std::uint32_t>(v));
    put(out, static_cast<std::uint32_t>(o.triangles.size()));
    for (const Vec3 p : o.positions) {
      put(out, static_cast<float>(p.x));
      put(out, static_cast<float>(p.y));
      put(out, static_cast<float>(p.z));
    }
    for (const float a : o.albedo) put(out, a);
    for (const Triangle& tri : o.triangles) {
      for (const std::uint32_t index : tri) put(out, index);
    }
  }
  return out;
}

std::vector<int> vertex_portals(const TransferFile& t) {
  std::vector<int> portal(t.vertex_count, -1);
  std::vector<bool> opaque(t.vertex_count, false);
  for (const std::uint32_t i : t.opaque_triangles) {
    for (const std::uint32_t v : t.triangles[i]) opaque[v] = true;
  }
  for (std::size_t k = 0; k < t.portal_triangles.size(); ++k) {
    for (const std::uint32_t v : t.triangles[t.portal_triangles[k]]) {
      if (!opaque[v]) portal[v] = static_cast<int>(t.portal_of_triangle[k]);
    }
  }
  return portal;
}

void compute_frame_values(const TransferFile& t, std::span<const int> vertex_portal,
                          std::span<const float> irradiance, std::span<const Rgb> glass_radiance,
                          std::span<const float> vertex_albedo, FrameValues& out) {
  if (vertex_albedo.size() != 3 * t.vertex_count) {
    throw std::invalid_argument("compute_frame_values: one albedo per vertex expected");
  }
  out.radiance.resize(3 * t.vertex_count);
  out.illuminance.resize(t.vertex_count);
  out.sensors.resize(t.sensor_count);
  for (std::size_t v = 0; v < t.vertex_count; ++v) {
    const float* e = &irradiance[3 * v];
    float* l = &out.radiance[3 * v];
    if (vertex_portal[v] >= 0) {
      const Rgb g = glass_radiance[static_cast<std::size_t>(vertex_portal[v])];
      l[0] = static_cast<float>(g.r);
      l[1] = static_cast<float>(g.g);
      l[2] = static_cast<float>(g.b);
      out.illuminance[v] = 0;
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      l[c] = static_cast<float>(lambertian_radiance(vertex_albedo[3 * v + c], e[c]));
    }
    out.illuminance[v] = static_cast<float>(photometric(e));
  }
  const std::span<const float> sensors = irradiance.subspan(3 * t.vertex_count);
  for (std::size_t s = 0; s < t.sensor_count; ++s) {
    out.sensors[s] = static_cast<float>(photometric(&sensors[3 * s]));
  }
}

void compute_object_values(std::span<const float> albedo, std::span<const float> irradiance,
                           FrameValues& out) {
  if (albedo.size() != irradiance.size() || albedo.size() % 3 != 0) {
    throw std::invalid_argument("compute_object_values: " + std::to_string(albedo.size()) +
                                " albedo values for " + std::to_string(irradiance.size()) +
                                " irradiance values");
  }
  const std::size_t q = albedo.size() / 3;
  out.object_radiance.resize(3 * q);
  out.object_illuminance.resize(q);
  for (std::size_t v = 0; v < q; ++v) {
    const float* e = &irradiance[3 * v];
    for (std::size_t c = 0; c < 3; ++c) {
      out.object_radiance[3 * v + c] =
          static_cast<float>(lambertian_radiance(albedo[3 * v + c], e[c]));
    }
    out.object_illuminance[v] = static_cast<float>(photometric(e));
  }
}

std::string encode_frame(std::uint32_t frame_number, std::optional<std::uint32_t> seq,
                         float milliseconds, const FrameValues& values) {
  const auto v = static_cast<std::uint32_t>(values.illuminance.size());
  const auto s = static_cast<std::uint32_t>(values.sensors.size());
  const std::size_t q = values.object_illuminance.size();
  std::string out;
  out.reserve(24 + 8 * std::size_t{v} + 4 * std::size_t{s} + 8 * q);
  put_tag(out, "RLFR");
  put(out, frame_number);
  put(out, seq.value_or(kNoSeq));
  put(out, v);
  put(out, s);
  put(out, milliseconds);
  for (std::size_t i = 0; i < v; ++i) {
    put(out, float_to_half(values.radiance[3 * i]));
    put(out, float_to_half(values.radiance[3 * i + 1]));
    put(out, float_to_half(values.radiance[3 * i + 2]));
    put(out, float_to_half(values.illuminance[i]));
  }
  for (const float e : values.sensors) put(out, e);
  // After the sensors, so that parsers of frames without objects read them unchanged.
  for (std::size_t i = 0; i < q; ++i) {
    put(out, float_to_half(values.object_radiance[3 * i]));
    put(out, float_to_half(values.object_radiance[3 * i + 1]));
    put(out, float_to_half(values.object_radiance[3 * i + 2]));
    put(out, float_to_half(values.object_illuminance[i]));
  }
  return out;
}

std::string encode_glossy_view(std::uint32_t frame_number, Vec3 eye, float milliseconds,
                               std::span<const float> luminance) {
  std::vector<std::uint32_t> glossy;
  for (std::size_t v = 0; 3 * v + 2 < luminance.size(); ++v) {
    if (!std::isnan(luminance[3 * v])) glossy.push_back(static_cast<std::uint32_t>(v));
  }
  std::string out;
  out.reserve(28 + 10 * glossy.size());
  put_tag(out, "RLGV");
  put(out, frame_number);
  put(out, static_cast<std::uint32_t>(glossy.size()));
  put(out, milliseconds);
  put(out, static_cast<float>(eye.x));
  put(out, static_cast<float>(eye.y));
  put(out, static_cast<float>(eye.z));
  for (const std::uint32_t v : glossy) put(out, v);
  for (const std::uint32_t v : glossy) {
    for (std::size_t c = 0; c < 3; ++c) put(out, float_to_half(luminance[3 * std::size_t{v} + c]));
  }
  return out;
}

std::string encode_window_views(std::uint32_t frame_number, std::span<const WindowView> views) {
  const int n = views.empty() ? 0 : views.front().shell->face_size;
  std::string out;
  out.reserve(16 + views.size() * (40 + 6 * cubemap_texel_count(n)));
  put_tag(out, "RLWV");
  put(out, frame_number);
  put(out, static_cast<std::uint32_t>(views.size()));
  put(out, static_cast<std::uint32_t>(n));
  for (const WindowView& v : views) {
    if (v.shell->face_size != n || v.shell->cubemap.size() != cubemap_texel_count(n))
      throw std::invalid_argument("encode_window_views: the shells' face sizes differ");
    for (const double x : {v.centre.x, v.centre.y, v.centre.z}) put(out, static_cast<float>(x));
    const Vec3 d = v.sun ? v.sun->direction : Vec3{0, 1, 0};
    for (const double x : {d.x, d.y, d.z}) put(out, static_cast<float>(x));
    // cos of the disc's angular radius; −2 (no direction has it) without a sun.
    put(out, static_cast<float>(v.sun ? v.sun->cos_angular_radius : -2.0));
    for (const double x : {v.sun_luminance.r, v.sun_luminance.g, v.sun_luminance.b})
      put(out, static_cast<float>(v.sun ? x : 0.0));
  }
  constexpr double kHalfMax = 65504;  // brighter texels (a frosted sun) saturate
  for (const WindowView& v : views) {
    for (const Rgb& l : v.shell->cubemap) {
      for (const double x : {l.r, l.g, l.b}) {
        put(out, float_to_half(static_cast<float>(std::min(std::max(x, 0.0), kHalfMax))));
      }
    }
  }
  return out;
}

}  // namespace relight

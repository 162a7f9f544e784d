// serve/studio_frames.h: the RLGE, RLOB and RLFR layouts of docs/studio-protocol.md, byte for
// byte, and the values a frame carries (L = ρ·E/π, Y(E), the sensors' own readings, window
// glass, the movable objects' vertices as the relighter lights them).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <stdexcept>
#include <tuple>

#include <gtest/gtest.h>

#include "light/sky_model.h"
#include "math/cubemap.h"
#include "math/rgb.h"
#include "runtime/lighting_state.h"
#include "runtime/relit_scene.h"
#include "serve/half_float.h"
#include "serve/studio_frames.h"
#include "tiny_studio_room.h"

namespace relight {
namespace {

template <typename T>
T read(const std::string& bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

const testing::TinyStudioRoom& room() {
  static const testing::TinyStudioRoom r;
  return r;
}

// The room with the cabinet (tests/serve/tiny_studio_room.h).
const testing::TinyStudioRoom& furnished() {
  static const testing::TinyStudioRoom r(testing::tiny_studio_room_with_object_json());
  return r;
}

TEST(StudioFrames, GeometryLayout) {
  const TransferFile& t = room().transfer;
  const std::string g = encode_geometry(t);
  const std::size_t v = t.vertex_count, n = t.triangles.size();
  ASSERT_EQ(g.size(), 16 + 24 * v + 16 * n);
  EXPECT_EQ(g.substr(0, 4), "RLGE");
  EXPECT_EQ(read<std::uint32_t>(g, 4), 1u);
  EXPECT_EQ(read<std::uint32_t>(g, 8), v);
  EXPECT_EQ(read<std::uint32_t>(g, 12), n);
  EXPECT_EQ(read<float>(g, 16 + 12 * (v - 1) + 4), static_cast<float>(t.positions[v - 1].y));
  EXPECT_EQ(read<float>(g, 16 + 12 * v + 4), t.vertex_albedo[1]);
  EXPECT_EQ(read<std::uint32_t>(g, 16 + 24 * v + 12 * (n - 1) + 8), t.triangles[n - 1][2]);
  std::size_t glass = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t code = read<std::uint32_t>(g, 16 + 24 * v + 12 * n + 4 * i);
    EXPECT_LE(code, 1u);
    glass += code;
  }
  EXPECT_EQ(glass, t.portal_triangles.size());
  EXPECT_GT(glass, 0u);
}

TEST(StudioFrames, FrameCarriesRadianceIlluminanceAndSensors) {
  const TransferFile& t = room().transfer;
  const std::vector<int> portal = vertex_portals(t);
  std::vector<float> irradiance(3 * (t.vertex_count + t.sensor_count));
  for (std::size_t i = 0; i < irradiance.size(); ++i) irradiance[i] = 10.0f + i % 7;
  const Rgb sky{100, 200, 300};
  FrameValues values;
  compute_frame_values(t, portal, irradiance, std::span(&sky, 1), t.vertex_albedo, values);
  const std::string f = encode_frame(42, 7, 1.5f, values);
  const std::size_t v = t.vertex_count, s = t.sensor_count;
  ASSERT_EQ(f.size(), 24 + 8 * v + 4 * s);
  EXPECT_EQ(f.substr(0, 4), "RLFR");
  EXPECT_EQ(read<std::uint32_t>(f, 4), 42u);
  EXPECT_EQ(read<std::uint32_t>(f, 8), 7u);
  EXPECT_EQ(read<std::uint32_t>(f, 12), v);
  EXPECT_EQ(read<std::uint32_t>(f, 16), s);
  EXPECT_EQ(read<float>(f, 20), 1.5f);
  std::size_t glass = 0;
  for (std::size_t i = 0; i < v; ++i) {
    const float* e = &irradiance[3 * i];
    for (int c = 0; c < 3; ++c) {
      const float l = half_to_float(read<std::uint16_t>(f, 24 + 8 * i + 2 * c));
      const double expected = portal[i] >= 0 ? (c == 0   ? 100
                                                : c == 1 ? 200
                                                         : 300)
                                             : t.vertex_albedo[3 * i + c] * e[c] / kPi;
      EXPECT_NEAR(l, expected, expected * 1e-3) << i;
    }
    const float lux = half_to_float(read<std::uint16_t>(f, 24 + 8 * i + 6));
    const double y = portal[i] >= 0 ? 0 : luminance(Rgb{e[0], e[1], e[2]});
    EXPECT_NEAR(lux, y, y * 1e-3) << i;
    glass += portal[i] >= 0;
  }
  EXPECT_GT(glass, 0u);
  for (std::size_t k = 0; k < s; ++k) {
    const float* e = &irradiance[3 * (v + k)];
    EXPECT_FLOAT_EQ(read<float>(f, 24 + 8 * v + 4 * k),
                    static_cast<float>(luminance(Rgb{e[0], e[1], e[2]})));
  }
  EXPECT_EQ(read<std::uint32_t>(encode_frame(1, std::nullopt, 0, values), 8), kNoSeq);
}

TEST(StudioFrames, ObjectsLayoutIsTheBoxAsTheScenePlacesIt) {
  const TransferFile& t = furnished().transfer;
  ASSERT_EQ(t.view.objects.size(), 1u);
  const ObjectMesh& o = t.view.objects[0];
  const std::size_t v = o.positions.size(), n = o.triangles.size();
  const std::string m = encode_objects(t.view.objects);
  ASSERT_EQ(m.size(), 12 + 8 + 24 * v + 12 * n);
  EXPECT_EQ(m.substr(0, 4), "RLOB");
  EXPECT_EQ(read<std::uint32_t>(m, 4), 1u);
  EXPECT_EQ(read<std::uint32_t>(m, 8), 1u);
  EXPECT_EQ(read<std::uint32_t>(m, 12), v);
  EXPECT_EQ(read<std::uint32_t>(m, 16), n);
  // Every position lies on the box's surface where the scene put it, and its 8 corners are there.
  const auto& lo = testing::kCabinetMin;
  const auto& hi = testing::kCabinetMax;
  std::set<std::tuple<bool, bool, bool>> corners;
  std::vector<Vec3> p(v);
  for (std::size_t i = 0; i < v; ++i) {
    float x[3];
    for (std::size_t k = 0; k < 3; ++k) x[k] = read<float>(m, 20 + 12 * i + 4 * k);
    p[i] = {x[0], x[1], x[2]};
    int at_max = 0, at_min = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_GE(x[k], static_cast<float>(lo[k])) << i;
      EXPECT_LE(x[k], static_cast<float>(hi[k])) << i;
      at_min += x[k] == static_cast<float>(lo[k]);
      at_max += x[k] == static_cast<float>(hi[k]);
    }
    const int on_face = at_min + at_max;
    EXPECT_GE(on_face, 1) << "vertex " << i << " inside the box";
    if (on_face == 3) {
      corners.insert({x[0] == static_cast<float>(hi[0]), x[1] == static_cast<float>(hi[1]),
                      x[2] == static_cast<float>(hi[2])});
    }
  }
  EXPECT_EQ(corners.size(), 8u);
  for (std::size_t i = 0; i < 3 * v; ++i) EXPECT_EQ(read<float>(m, 20 + 12 * v + 4 * i), 0.5f);
  // Indices local to the object, counter-clockwise seen from outside (the front).
  const Vec3 pivot{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  for (std::size_t j = 0; j < n; ++j) {
    std::uint32_t idx[3];
    for (std::size_t k = 0; k < 3; ++k) {
      idx[k] = read<std::uint32_t>(m, 20 + 24 * v + 12 * j + 4 * k);
      ASSERT_LT(idx[k], v);
      EXPECT_EQ(idx[k], o.triangles[j][k]);
    }
    const Vec3 a = p[idx[0]], b = p[idx[1]], c = p[idx[2]];
    EXPECT_GT(dot(cross(b - a, c - a), (a + b + c) * (1.0 / 3) - pivot), 0) << "triangle " << j;
  }
  EXPECT_THROW(
      {
        ObjectMesh broken = o;
        broken.albedo.pop_back();
        encode_objects(std::span(&broken, 1));
      },
      std::invalid_argument);
}

TEST(StudioFrames, ObjectVerticesFollowTheSensors) {
  const TransferFile& t = room().transfer;
  const std::vector<int> portal = vertex_portals(t);
  std::vector<float> irradiance(3 * (t.vertex_count + t.sensor_count), 20.0f);
  const Rgb sky{100, 200, 300};
  FrameValues values;
  compute_frame_values(t, portal, irradiance, std::span(&sky, 1), t.vertex_albedo, values);
  const std::string plain = encode_frame(3, 4, 2.0f, values);
  // Three object vertices: albedo (0.5, 0.25, 1), (1, 1, 1), (0, 0, 0).
  const std::vector<float> albedo = {0.5f, 0.25f, 1, 1, 1, 1, 0, 0, 0};
  const std::vector<float> e = {100, 200, 400, 10, 20, 30, 50, 50, 50};
  compute_object_values(albedo, e, values);
  const std::string f = encode_frame(3, 4, 2.0f, values);
  const std::size_t v = t.vertex_count, s = t.sensor_count, base = 24 + 8 * v + 4 * s;
  ASSERT_EQ(f.size(), base + 8 * 3);
  EXPECT_EQ(f.substr(0, base), plain) << "the room's and the sensors' bytes are unchanged";
  for (std::size_t q = 0; q < 3; ++q) {
    for (std::size_t c = 0; c < 3; ++c) {
      const double expected = albedo[3 * q + c] * e[3 * q + c] / kPi;
      EXPECT_NEAR(half_to_float(read<std::uint16_t>(f, base + 8 * q + 2 * c)), expected,
                  expected * 1e-3 + 1e-6)
          << q << " " << c;
    }
    const double y = luminance(Rgb{e[3 * q], e[3 * q + 1], e[3 * q + 2]});
    EXPECT_NEAR(half_to_float(read<std::uint16_t>(f, base + 8 * q + 6)), y, y * 1e-3);
  }
  EXPECT_THROW(compute_object_values(albedo, std::span(e).first(6), values), std::invalid_argument);
}

// What the server sends for the cabinet: the relighter's light at its vertices, L = ρ·E/π; a
// hidden cabinet's vertices are dark and it no longer shadows the floor.
TEST(StudioFrames, ObjectValuesAreTheRelighterLight) {
  RelitScene relit(furnished().rlt, std::nullopt);
  const TransferFile& t = relit.transfer();
  const ObjectLighting* objects = relit.relighter().objects();
  ASSERT_NE(objects, nullptr);
  const auto floor_lux = [&](const FrameValues& f) {
    double sum = 0;
    for (std::size_t v = 0; v < t.vertex_count; ++v) {
      if (t.positions[v].y < 0.01) sum += f.illuminance[v];
    }
    return sum;
  };
  const auto frame = [&](const char* state_text) {
    LightingState state = default_lighting_state(t.scene);
    apply_lighting_state(state, t.scene, nlohmann::json::parse(state_text), "test", ".");
    relit.apply(state);
    std::vector<Rgb> glass(t.scene.portals.size(), Rgb{});
    FrameValues f;
    compute_frame_values(t, vertex_portals(t), relit.irradiance(), glass, t.vertex_albedo, f);
    compute_object_values(objects->placed().albedo, objects->irradiance(true), f);
    return f;
  };
  const FrameValues shown = frame("{}");
  const std::span<const float> e = objects->irradiance(true);
  const std::size_t q = objects->placed().vertex_count();
  ASSERT_EQ(q, t.view.objects[0].positions.size());
  ASSERT_EQ(shown.object_illuminance.size(), q);
  double top = 0;
  for (std::size_t i = 0; i < q; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_FLOAT_EQ(shown.object_radiance[3 * i + c], 0.5f * e[3 * i + c] / kPi);
    }
    EXPECT_FLOAT_EQ(shown.object_illuminance[i],
                    static_cast<float>(luminance(Rgb{e[3 * i], e[3 * i + 1], e[3 * i + 2]})));
    if (objects->placed().positions[i].y > 1.19) top = std::max<double>(top, e[3 * i + 1]);
  }
  EXPECT_GT(top, 10) << "the downlight lights the cabinet's top";
  const FrameValues hidden = frame(R"({"objects":{"cabinet":{"visible":false}}})");
  for (std::size_t i = 0; i < q; ++i) {
    EXPECT_EQ(hidden.object_illuminance[i], 0) << i;
    EXPECT_EQ(hidden.object_radiance[3 * i], 0) << i;
  }
  EXPECT_GT(floor_lux(hidden), floor_lux(shown)) << "the cabinet shadows the floor";
}

// RLGV: only the vertices with a luminance (not NaN) are listed, ascending, with their three
// half floats after the indices; the header carries the frame, the count and the eye.
TEST(StudioFrames, GlossyViewListsTheGlossyVerticesAndTheirLuminance) {
  const float nan = std::nanf("");
  const std::vector<float> luminance{nan, nan, nan, 1.5f,  2.0f, 4.0f,
                                     nan, nan, nan, 0.25f, 0.5f, 0.75f};
  const std::string bytes = encode_glossy_view(7, {1, 2, 3}, 3.5f, luminance);
  ASSERT_EQ(bytes.size(), 28u + 2 * 4 + 2 * 6);
  EXPECT_EQ(bytes.substr(0, 4), "RLGV");
  EXPECT_EQ(read<std::uint32_t>(bytes, 4), 7u);
  EXPECT_EQ(read<std::uint32_t>(bytes, 8), 2u);
  EXPECT_EQ(read<float>(bytes, 12), 3.5f);
  EXPECT_EQ(read<float>(bytes, 16), 1.0f);
  EXPECT_EQ(read<float>(bytes, 24), 3.0f);
  EXPECT_EQ(read<std::uint32_t>(bytes, 28), 1u);
  EXPECT_EQ(read<std::uint32_t>(bytes, 32), 3u);
  EXPECT_EQ(half_to_float(read<std::uint16_t>(bytes, 36)), 1.5f);
  EXPECT_EQ(half_to_float(read<std::uint16_t>(bytes, 40)), 4.0f);
  EXPECT_EQ(half_to_float(read<std::uint16_t>(bytes, 42)), 0.25f);
  EXPECT_EQ(half_to_float(read<std::uint16_t>(bytes, 46)), 0.75f);
  // Nothing glossy: the header alone.
  EXPECT_EQ(encode_glossy_view(1, {}, 0, std::vector<float>(6, nan)).size(), 28u);
}

TEST(StudioFrames, WindowViewsCarryEachPortalsShellAndSunAsTheProtocolLaysOut) {
  const int n = 2;
  Shell a, b;
  for (Shell* s : {&a, &b}) {
    s->face_size = n;
    s->cubemap.resize(cubemap_texel_count(n));
  }
  for (std::size_t i = 0; i < a.cubemap.size(); ++i) {
    a.cubemap[i] = Rgb{static_cast<double>(i), 0.5, 1e6};  // 1e6 saturates at half's 65504
    b.cubemap[i] = Rgb{2, 3, -1};                          // negative: 0
  }
  const SunDisc disc = make_sun_disc(Vec3{0, 1, 0}, 1e5);
  std::vector<WindowView> views{{&a, {1, 2, 3}, std::nullopt, Rgb{}},
                                {&b, {4, 5, 6}, disc, Rgb{7, 8, 9}}};
  const std::string m = encode_window_views(42, views);
  const std::size_t texels = cubemap_texel_count(n);
  ASSERT_EQ(m.size(), 16 + 40 * 2 + 6 * texels * 2);
  EXPECT_EQ(m.substr(0, 4), "RLWV");
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, m.data() + at, 4);
    return v;
  };
  const auto f32 = [&](std::size_t at) {
    float v;
    std::memcpy(&v, m.data() + at, 4);
    return v;
  };
  const auto half = [&](std::size_t k) {
    std::uint16_t h;
    std::memcpy(&h, m.data() + 16 + 80 + 2 * k, 2);
    return half_to_float(h);
  };
  EXPECT_EQ(u32(4), 42U);
  EXPECT_EQ(u32(8), 2U);
  EXPECT_EQ(u32(12), static_cast<std::uint32_t>(n));
  EXPECT_EQ(f32(16), 1.0F);        // portal 0's centre
  EXPECT_EQ(f32(16 + 24), -2.0F);  // no sun
  EXPECT_EQ(f32(16 + 28), 0.0F);
  EXPECT_EQ(f32(56 + 12 + 4), 1.0F);  // portal 1's sun direction y
  EXPECT_NEAR(f32(56 + 24), std::cos(disc.angular_radius), 1e-7);
  EXPECT_EQ(f32(56 + 36), 9.0F);
  EXPECT_EQ(half(3 * 5), 5.0F);  // portal 0, texel 5, red
  EXPECT_EQ(half(3 * 5 + 2), 65504.0F);
  EXPECT_EQ(half(3 * texels + 1), 3.0F);  // portal 1, texel 0, green
  EXPECT_EQ(half(3 * texels + 2), 0.0F);
  b.face_size = 4;
  EXPECT_THROW((void)encode_window_views(1, views), std::invalid_argument);
}

}  // namespace
}  // namespace relight

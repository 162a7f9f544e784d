// serve/studio_frames.h: the RLGE and RLFR layouts of docs/studio-protocol.md, byte for byte,
// and the values a frame carries (L = ρ·E/π, Y(E), the sensors' own readings, window glass).
#include <cstring>

#include <gtest/gtest.h>

#include "math/rgb.h"
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
  compute_frame_values(t, portal, irradiance, std::span(&sky, 1), values);
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

}  // namespace
}  // namespace relight

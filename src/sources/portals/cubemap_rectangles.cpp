// The encoder of face-rectangle records (cubemap_encoding.h): the bounding rectangle of a
// receiver's kept cells on each face, then the record. Their reading and sums are
// cubemap_rectangles_sum.h's.
#include "sources/portals/cubemap_rectangles.h"

#include <algorithm>

#include "sources/portals/cubemap_encoding.h"

namespace relight::cubemap_detail {

std::size_t find_rectangles(int n, std::span<const double> cells, const Quantiser& quantise,
                            FaceRectangles& rectangles, std::size_t& count) {
  for (std::array<int, 4>& r : rectangles) r = {n, n, -1, -1};
  const std::size_t nn = std::size_t(n) * n;
  for_each_kept(cells, quantise, [&](std::size_t k, long) {
    std::array<int, 4>& r = rectangles[k / nn];
    const auto x = static_cast<int>(k % n), y = static_cast<int>(k % nn / n);
    r = {std::min(r[0], x), std::min(r[1], y), std::max(r[2], x), std::max(r[3], y)};
  });
  std::size_t levels = 0;
  count = 0;
  for (const std::array<int, 4>& r : rectangles) {
    if (r[0] > r[2]) continue;
    levels += static_cast<std::size_t>(r[2] - r[0] + 1) * static_cast<std::size_t>(r[3] - r[1] + 1);
    ++count;
  }
  return levels;
}

void write_rectangles_record(int n, const Quantiser& quantise, std::span<const double> cells,
                             const FaceRectangles& rectangles, std::size_t count,
                             std::vector<std::uint8_t>& out) {
  out.push_back(static_cast<std::uint8_t>(CubemapCodeKind::kRectangles));
  put_float(out, static_cast<float>(quantise.scale));
  out.push_back(static_cast<std::uint8_t>(count));
  for (std::size_t face = 0; face < 6; ++face) {
    const std::array<int, 4>& r = rectangles[face];
    if (r[0] > r[2]) continue;
    for (const int v : {static_cast<int>(face), r[0], r[1], r[2] - r[0], r[3] - r[1]})
      out.push_back(static_cast<std::uint8_t>(v));
  }
  const std::size_t nn = std::size_t(n) * n;
  for (std::size_t face = 0; face < 6; ++face) {
    const std::array<int, 4>& r = rectangles[face];
    for (int y = r[1]; r[0] <= r[2] && y <= r[3]; ++y)
      for (int x = r[0]; x <= r[2]; ++x) {
        const std::size_t k = face * nn + static_cast<std::size_t>(y) * n + x;
        out.push_back(static_cast<std::uint8_t>(quantise(k, cells[k])));
      }
  }
}

}  // namespace relight::cubemap_detail

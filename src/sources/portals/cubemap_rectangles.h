// The encoder of face-rectangle records (cubemap_encoding.h), in two steps defined in
// cubemap_rectangles.cpp. Their reading and sums are cubemap_rectangles_sum.h's. Internal to
// src/sources/portals/cubemap_*.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "sources/portals/cubemap_common.h"

namespace relight::cubemap_detail {

using FaceRectangles = std::array<std::array<int, 4>, 6>;

// The bounding rectangle of the pulse record's kept cells on each face, x0, y0, x1, y1
// inclusive (x0 > x1 on a face with none). Returns the levels they hold; `count` the faces
// that have one.
std::size_t find_rectangles(int n, std::span<const double> cells, const Quantiser& quantise,
                            FaceRectangles& rectangles, std::size_t& count);

// Appends the rectangle record of `rectangles` (find_rectangles's; `count` of them not empty).
void write_rectangles_record(int n, const Quantiser& quantise, std::span<const double> cells,
                             const FaceRectangles& rectangles, std::size_t count,
                             std::vector<std::uint8_t>& out);

}  // namespace relight::cubemap_detail

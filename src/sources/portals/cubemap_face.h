// The face size check and the cell count of a cubemap record (cubemap_encoding.h), for the three
// files that use both: the encoder (cubemap_encoding.cpp), the shell (cubemap_shell.cpp) and the
// readers and sums (cubemap_sum.cpp). Internal linkage and not `inline`, on purpose: the block
// loop of add_receiver_cubemaps calls them, and GCC makes different inlining decisions for that
// loop, and its object code changes, when a helper it calls has external linkage (see
// cubemap_sum_common.h).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "math/haar.h"

namespace relight::cubemap_detail {
namespace {

void check_face_size(int n) {
  if (!is_power_of_two(n))
    throw std::invalid_argument("cubemap encoding: face size " + std::to_string(n) +
                                " is not a power of two");
}

std::size_t cell_count(int n) {
  return std::size_t{6} * n * n;
}

}  // namespace
}  // namespace relight::cubemap_detail

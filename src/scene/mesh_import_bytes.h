// Reading little- or big-endian scalars from raw file bytes (binary PLY, glTF buffers)
// without alignment assumptions.
#pragma once

#include <algorithm>
#include <bit>
#include <cstring>

namespace relight {

template <typename T>
T load_scalar(const unsigned char* bytes, bool little_endian) {
  unsigned char copy[sizeof(T)];
  std::memcpy(copy, bytes, sizeof(T));
  if (little_endian != (std::endian::native == std::endian::little)) {
    std::reverse(copy, copy + sizeof(T));
  }
  T value;
  std::memcpy(&value, copy, sizeof(T));
  return value;
}

}  // namespace relight

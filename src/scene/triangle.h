// A triangle: three vertex indices, counter-clockwise seen from its front.
#pragma once

#include <array>
#include <cstdint>

namespace relight {

using Triangle = std::array<std::uint32_t, 3>;

}  // namespace relight

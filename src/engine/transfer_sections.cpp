#include "engine/transfer_sections.h"

#include <cmath>

#include "common/input_error.h"

namespace relight {

namespace {
constexpr int kExponentBias = 128;
}  // namespace

void add_transfer_section(RltWriter& w, std::uint32_t type, const std::string& name,
                          const PackedTransfer& t) {
  if (t.f16.empty()) {
    w.add_f32(type, name, t.f32);
    return;
  }
  const auto flags = static_cast<std::uint32_t>(std::ilogb(t.scale) + kExponentBias);
  w.add_f16(type, name, t.f16, flags);
}

BlockedTransfer transfer_section(const RltFile& file, std::uint32_t type) {
  const RltSectionInfo& info = file.info(type);
  BlockedTransfer t;
  if (info.element != RltElement::f16) {
    t.f32 = file.view<float>(type);
    return t;
  }
  t.f16 = file.view<RltHalf>(type);
  const auto exponent = static_cast<int>(info.flags & 0xFF) - kExponentBias;
  t.scale = std::ldexp(1.0f, exponent);
  if (t.f16.empty()) t.scale = 1;
  return t;
}

}  // namespace relight

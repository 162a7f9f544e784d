// Fuzz target: an inverse-design TARGETS.json (docs/optimize.md) read against a small scene with a
// sensor set and a luminaire, as `relight optimize --targets` and the studio's optimise panel read
// it (design/design_targets.h). Bad input must end in InputError; anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/input_error.h"
#include "design/design_targets.h"
#include "fuzz_room.h"
#include "scene/json_node.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    (void)relight::parse_design_targets(relight::parse_json_text(text, "targets.json"),
                                        relight::fuzz::fuzz_room(), "targets.json");
  } catch (const relight::InputError&) {
  }
  return 0;
}

// Fuzz target: a lighting state document (docs/lighting-state.md) applied to a small scene with a
// luminaire, a window, an emitter and a movable object, as `relight probe --state` and the studio
// read it (runtime/lighting_state.h). Bad input must end in InputError; anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/input_error.h"
#include "fuzz_room.h"
#include "runtime/lighting_state.h"
#include "scene/json_node.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    relight::LightingState state = relight::default_lighting_state(relight::fuzz::fuzz_room());
    relight::apply_lighting_state(state, relight::fuzz::fuzz_room(),
                                  relight::parse_json_text(text, "state.json"), "state.json",
                                  "/nonexistent");
  } catch (const relight::InputError&) {
  }
  return 0;
}

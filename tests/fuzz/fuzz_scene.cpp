// Fuzz target: a scene document (docs/scene-format.md) parsed and validated as `relight precompute`
// reads it (scene/scene_loader.h), files resolved against an empty folder. Bad input must end in
// InputError; anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/input_error.h"
#include "scene/json_node.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    relight::scene_from_json(relight::parse_json_text(text, "fuzz.json"), "/nonexistent/fuzz.json");
  } catch (const relight::InputError&) {
  }
  return 0;
}

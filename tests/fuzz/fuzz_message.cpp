// Fuzz target: a studio client's text message (serve/studio_messages.h: state, pick, distribution,
// ping, annual with a weather file's text) against a small scene with a luminaire, a window, an
// emitter and a movable object. Bad input must end in InputError; anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "common/input_error.h"
#include "fuzz_room.h"
#include "serve/studio_messages.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::optional<std::uint32_t> seq;
  try {
    relight::parse_client_message(std::string(reinterpret_cast<const char*>(data), size),
                                  relight::fuzz::fuzz_room(), seq);
  } catch (const relight::InputError&) {
  }
  return 0;
}

// Fuzz target: EULUMDAT text (light/ldt_parser.h). Bad input must end in InputError; anything else
// is a defect.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/input_error.h"
#include "light/ldt_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relight::parse_ldt(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ldt");
  } catch (const relight::InputError&) {
  }
  return 0;
}

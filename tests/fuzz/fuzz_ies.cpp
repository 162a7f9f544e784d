// Fuzz target: IES LM-63 text (light/ies_parser.h). Bad input must end in InputError (exit 2 in the
// product); anything else — a crash, a sanitizer report, another exception — is a defect.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/input_error.h"
#include "light/ies_parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relight::parse_ies(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.ies");
  } catch (const relight::InputError&) {
  }
  return 0;
}

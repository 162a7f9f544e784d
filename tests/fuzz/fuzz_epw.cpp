// Fuzz target: EnergyPlus weather text (light/epw_weather.h). Bad input must end in InputError;
// anything else is a defect.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/input_error.h"
#include "light/epw_weather.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relight::parse_epw(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.epw");
  } catch (const relight::InputError&) {
  }
  return 0;
}

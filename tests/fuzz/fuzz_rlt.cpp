// Fuzz target: a precomputed `.rlt` file as every command opens it (sources/transfer_file.h:
// header, section table, checksums, then each source's sections). Bad input must end in InputError;
// anything else is a defect.
#include <cstddef>
#include <cstdint>

#include "common/input_error.h"
#include "fuzz_file.h"
#include "sources/transfer_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relight::open_transfer_file(relight::fuzz::write_input(data, size, ".rlt"));
  } catch (const relight::InputError&) {
  }
  return 0;
}

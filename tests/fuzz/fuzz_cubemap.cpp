// Fuzz target: one receiver's direct portal cubemap record (sources/portals/cubemap_encoding.h:
// empty, pulse, Haar, pulse runs, face rectangles) as the run time reads it from a `.rlt` — parsed,
// decoded, summed alone and summed in a block (the AVX2 loops that read eight levels and eight
// cells at a time). The `rlt` target cannot reach these: a changed record fails its section's
// checksum first. Byte 0 picks the face size N = 2^(1 + byte % 7) (2 to 128: 2-byte indices up to
// 64, 4-byte at 128), the rest is the record. Bad input must end in InputError; anything else — a
// crash, a sanitizer report, a read past the record or the shell's planes — is a defect.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/input_error.h"
#include "math/rgb.h"
#include "sources/portals/cubemap_encoding.h"

namespace {

// A shell of face size n with distinct finite radiance in every cell, made once per size.
const relight::ShellCubemap& shell_of(int n) {
  static std::array<relight::ShellCubemap, 8> shells;
  relight::ShellCubemap& shell =
      shells[static_cast<std::size_t>(std::countr_zero(static_cast<unsigned>(n)))];
  if (shell.n != n) {
    std::vector<relight::Rgb> radiance(std::size_t{6} * n * n);
    for (std::size_t k = 0; k < radiance.size(); ++k)
      radiance[k] = {1.0 + static_cast<double>(k % 7), 2.0 + static_cast<double>(k % 5), 0.5};
    relight::prepare_shell_cubemap(n, radiance, shell);
  }
  return shell;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const int n = 2 << (data[0] % 7);
  const std::span<const std::uint8_t> record(data + 1, size - 1);
  const relight::ShellCubemap& shell = shell_of(n);
  try {
    (void)relight::parse_cubemap_record(n, record);
  } catch (const relight::InputError&) {
  }
  try {
    (void)relight::decode_receiver_cubemap(n, record);
  } catch (const relight::InputError&) {
  }
  try {
    (void)relight::dot_receiver_cubemap(record, shell);
  } catch (const relight::InputError&) {
  }
  try {
    const std::array<std::uint64_t, 2> offsets = {0, record.size()};
    float red = 0, green = 0, blue = 0;
    relight::add_receiver_cubemaps(record, offsets, shell, std::span(&red, 1), std::span(&green, 1),
                                   std::span(&blue, 1));
  } catch (const relight::InputError&) {
  }
  return 0;
}

// What this processor can run, checked once, for the hot loops that have an AVX2 clone beside
// their portable one (engine/transfer_blocks.h's binary16 sum, sources/portals's pulse sum). The
// product never requires these: each loop falls back to its portable form.
#pragma once

namespace relight {

// AVX2 and FMA (AVX2's check includes the OS saving the YMM registers).
bool has_avx2_fma();

// AVX2, FMA and F16C (binary16 conversions in registers).
bool has_f16c();

}  // namespace relight

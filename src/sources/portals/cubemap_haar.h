// Per-face Haar records (cubemap_encoding.h, math/haar.h): the encoder's amplitudes and quantiser
// (cubemap_haar.cpp). A Haar record has the pulse record's layout with a second scale and int8
// details, so its writer is the pulse record's (cubemap_pulse.h), and so are its entries and sum
// (cubemap_pulse_sum.h). Internal to src/sources/portals/cubemap_*.
#pragma once

#include <span>

#include "sources/portals/cubemap_common.h"
#include "sources/portals/cubemap_encoding.h"

namespace relight::cubemap_detail {

// The per-face Haar amplitudes a_k = T_k / S_k of a receiver's 6·N² cells, into
// scratch.coefficients, and the quantiser of its Haar record: S₀ the largest face mean, S_d the
// largest |detail| amplitude, dropping values below `threshold` × their scale.
Quantiser haar_amplitudes(int n, std::span<const double> cells, double threshold,
                          CubemapEncodeScratch& scratch);

}  // namespace relight::cubemap_detail

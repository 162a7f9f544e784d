// A source kind's term of the run-time weighted sum (light is linear: every change is a weight on
// precomputed responses): from its current weights, its irradiance at one block of receivers. The
// Relighter (runtime/relighter.h) keeps a partial sum per term and sums a term again only after its
// state changed.
#pragma once

#include <cstddef>

#include "engine/transfer_blocks.h"

namespace relight {

class SourceTerm {
 public:
  virtual ~SourceTerm() = default;
  // acc_c[i] += the term's irradiance (lx, RGB) at receivers [block · kBlock, …). Without
  // direct light: only what renderers that evaluate direct light per pixel still need
  // (Relighter::relight).
  virtual void add_block(std::size_t block, bool include_direct, float (&acc)[3][kBlock]) const = 0;
  // Bytes of stored transfer (and per-receiver run-time fields) one full sum reads.
  virtual std::size_t transfer_bytes() const = 0;
};

}  // namespace relight

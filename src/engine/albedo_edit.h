// Live albedo edits: the light a change of the surfaces' reflectance adds to a room lit with the
// reflectance its transfer was precomputed with — at run time, from the stored gather operator G
// alone, for light of every source at once.
//
// With the precompute's albedo ρ the vertices' irradiance E solves E = E_d + G ρ E (direct
// light E_d, engine/bounce_solver.h); with the edited ρ' it is E' = E_d + G ρ' E'. Their
// difference ΔE = E' − E needs neither E_d nor the sources, only E:
//
//   ΔE = s + G ρ' ΔE,   s = G (ρ' − ρ) E,
//
// the light the edit reflects once (s), bounced through the edited room. With X = ΔE − s that
// is X = G ρ' (s + X): the bounce solver's own iteration with s as its direct light, so
// ΔE = s + X at every receiver (the sensor rows of G gather it too). Exact to the solver's
// tolerance for the E it is given; E is what the run time sums (direct and stored
// interreflected light), so ΔE carries the stored transfer's own errors, no more.
//
// Cost: one pass over G for s, then one per bounce of X (a handful: X starts from the last
// edit's solution when the light changed a little). An approximation in between is s with
// `max_bounces` bounces — s alone is a first frame that is right where the edited surface
// lights others directly. Pinned by tests/engine/albedo_edit_test.cpp (against a solve of the
// edited room from its direct light) and tests/cli/material_edit_test.cpp (against a new
// precompute of the edited scene).
#pragma once

#include <span>
#include <vector>

#include "engine/bounce_solver.h"
#include "engine/gather_operator.h"

namespace relight {

class AlbedoEdit {
 public:
  // `gather`: receivers × vertices (kept alive by the caller); `original`: 3 per vertex, the
  // albedo the light it will be given was bounced with.
  AlbedoEdit(const GatherOperator& gather, std::span<const float> original,
             BounceSettings settings);

  // The edited albedo, 3 per vertex. Returns whether it differs from the last one set.
  bool set_albedo(std::span<const float> edited);
  // Whether any vertex's albedo differs from the original.
  bool active() const { return active_; }

  // delta (3 per receiver) = ΔE for the light `total` (3 per receiver; vertex rows with
  // direct light). max_bounces < 0: converged (the settings' tolerance); otherwise at most
  // that many bounces of X (0: s alone). `warm` starts X from the last solve's. Returns the
  // bounces computed.
  int solve(std::span<const float> total, std::span<float> delta, int max_bounces, bool warm);

 private:
  const GatherOperator& gather_;
  std::vector<float> original_, edited_, change_;  // 3 per vertex; change_ = ρ' − ρ
  BounceSettings settings_;
  bool active_ = false;
  std::vector<float> reflected_, once_, bounced_;  // Δρ ⊙ E per vertex; s and X per receiver
};

}  // namespace relight

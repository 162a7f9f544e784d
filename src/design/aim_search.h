// Aims within cones ("aim_cone_deg"): the light a luminaire sends to the sensors is not linear in
// its aim, so the aims are found by a local pattern search from the dimmer solution (compass
// search: Kolda, Lewis & Torczon 2003, SIAM Review 45(3), §3), each trial aim scored by solving the
// dimmers again. An aim is an offset in the cone's tangent plane — the exponential map about the
// cone's axis, so |offset| is the angle from the axis (radians) — which keeps the search's steps
// the same size everywhere in the cone. Tests: tests/design/aim_search_test.cpp (an analytic score;
// the optimiser against a grid of aims).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "math/vec3.h"

namespace relight {

using AimOffset = std::array<double, 2>;  // radians, in the cone's tangent plane

struct AimCone {
  Vec3 axis{0, -1, 0};  // unit: the scene's aim
  double radius_rad = 0;
};

// The unit aim at `offset` from the cone's axis.
Vec3 aim_in_cone(const AimCone& cone, AimOffset offset);
// The offset of a unit aim, pulled back onto the cone's rim when it lies outside.
AimOffset offset_in_cone(const AimCone& cone, Vec3 aim);

struct AimSearchSettings {
  double first_step_fraction = 0.5;                            // of each cone's radius
  double last_step_rad = 0.25 * 3.14159265358979323846 / 180;  // stop below a quarter degree
  int max_trials = 2000;
};

// Compass search over every cone's offset in turn: `try_offset(i, offset)` scores luminaire i at
// `offset` (the others where they are) and returns true when that is an improvement, which
// the caller keeps. Steps of ±step along each tangent axis, clipped to the cone; the step
// halves after a sweep without improvement. `offsets` (one per cone) are updated; returns the
// number of trials.
int search_aims(std::span<const AimCone> cones, std::vector<AimOffset>& offsets,
                const std::function<bool(std::size_t, AimOffset)>& try_offset,
                const AimSearchSettings& settings = {});

}  // namespace relight

// The compact sources of a top-level environment (light/compact_sources.h: a sky's sun, a map's
// small bright spots) lit exactly at a point: a direction of a source's disc counts when its ray
// from the point meets nothing of `occluders` — the static scene, and the placed objects where they
// are included — on its way to infinity, and
//     E = Σ_s E_s,n · f_s · max(0, n · s),
// f_s the fraction of the disc seen that way (light/disc_visibility.h: 9 directions, 80 in a
// penumbra). The run time evaluates it at receivers and object vertices
// (sources/environment/environment_lighting.h, environment_objects.h), `render --direct pixel` at
// every pixel's hit. Pinned by tests/cli/environment_cuts_test.cpp (the shadow's edge and penumbra
// of a 0.5° source against the reference).
#pragma once

#include <span>

#include "light/compact_sources.h"
#include "light/seen_light.h"
#include "math/rgb.h"
#include "math/vec3.h"
#include "trace/ray_tracer.h"

namespace relight {

// f_s from `origin` (already off its surface), in [0, 1].
double compact_fraction(const Occluders& occluders, const CompactSource& source, Vec3 origin,
                        bool penumbra = true);

// E_s,n · f_s · max(0, n · s) summed over `sources`, at `origin` (already off the surface of
// unit normal n).
Rgb compact_irradiance(const Occluders& occluders, std::span<const CompactSource> sources,
                       Vec3 origin, Vec3 n, bool penumbra = true);

// `source` as seen from `origin` (already off its surface of unit normal n): its E_s,n · f_s ·
// max(0, n · s), and with `with_luminance` its disc's luminance times f_s
// (light/disc_visibility.h disc_seen_from).
SeenLight compact_seen_from(const Occluders& occluders, const CompactSource& source, Vec3 origin,
                            Vec3 n, bool with_luminance);

}  // namespace relight

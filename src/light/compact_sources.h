// The compact bright sources of an environment, lit exactly rather than through the visibility
// cuts. A cut resolves directions to its leaves' spacing (1.1° at 32,768 directions): a 0.5° sun or
// lamp lands in one or two leaves, so its shadow's edge could move by half a leaf and its penumbra
// would be a step between receivers. Such a source is taken out of the environment's moments
// (light/environment_clusters.h) and its disc traced from every point that needs it
// (sources/environment/compact_light.h; pixels in `render --direct pixel`), as the window's sun is
// (sources/portals/portal_sun.h); the rest of the environment stays in the cuts.
//
//  * sky: its sun disc (light/sky_model.h), when above the horizon.
//  * map: every 8-connected region (wrapping in azimuth) of texels at least kCompactContrast
//    times the map's mean luminance over the sphere, whose texels all lie within
//    kCompactMaxRadiusDeg of the region's luminance centroid, and which carries at least
//    kCompactMinShare of the map's ∫ Y dω; the kMaxCompactSources brightest. It becomes a
//    uniform disc about that centroid of the region's solid angle and ∫ L dω per channel —
//    exact in position (a straight shadow edge's middle is the source's centroid) and in energy;
//    its shape a disc's (a painted or photographed sun is one). Its texels leave the moments.
//  * uniform: none.
// A region larger than kCompactMaxRadiusDeg stays in the cuts, whose leaves resolve a penumbra
// that wide. Pinned by tests/light/compact_sources_test.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "light/disc_visibility.h"
#include "light/environment.h"
#include "light/sky_model.h"
#include "math/rgb.h"

namespace relight {

inline constexpr double kCompactContrast = 50;
inline constexpr double kCompactMaxRadiusDeg = 2;
inline constexpr double kCompactMinShare = 0.01;
inline constexpr int kMaxCompactSources = 4;

struct CompactSource {
  SunDisc disc;               // world frame; its normal_illuminance the luminance channel's
  Rgb illuminance;            // lx per channel on a plane facing it, at any point that sees it all
  DiscDirections directions;  // where its visibility is traced
};

struct CompactSources {
  std::vector<CompactSource> sources;
  bool sky_sun = false;  // a sky's sun disc is sources[0]
  // A map's texels whose light the sources carry (1), width · height; empty for other kinds.
  std::vector<std::uint8_t> map_texels;
};

CompactSources find_compact_sources(const Environment& env);

}  // namespace relight

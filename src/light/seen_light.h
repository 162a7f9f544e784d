// One light as a point sees it, exactly: what it gives the plane of a normal there, where it
// is, and, for a light of finite luminance, what an eye at the point sees of it. Each kind of
// light computes it in one place (its *_seen_from beside its exact direct irradiance); the
// per-pixel renderer weighs `irradiance` by a BRDF toward `direction`, glare takes `luminance`
// and `solid_angle` as a glare source (runtime/direct_light.h gathers every kind).
#pragma once

#include <string_view>

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

// Which kind of light a point sees: a luminaire, a sun behind a window's clear glass, a
// near-field emitter, a top-level environment's compact source (its sun).
enum class LightKind { kLuminaire, kSun, kEmitter, kEnvironment };

// "luminaire", "sun", "emitter", "environment": the words of the scene format.
constexpr std::string_view light_kind_name(LightKind kind) {
  switch (kind) {
    case LightKind::kLuminaire:
      return "luminaire";
    case LightKind::kSun:
      return "sun";
    case LightKind::kEmitter:
      return "emitter";
    case LightKind::kEnvironment:
      return "environment";
  }
  return "";
}

struct SeenLight {
  Rgb irradiance;        // lx per channel on the plane of the normal, shadowed
  Vec3 direction;        // unit, toward the light (an area light: its visible part's mean, set
                         // only with the luminance)
  bool area = false;     // an area light: a BRDF sees it as a diffuse surface would
  bool in_view = false;  // some of it is visible in front of the normal's plane
  // Photometric Y seen, averaged over `solid_angle` (cd/m²), and the solid angle its visible
  // part subtends (sr); both 0 for a light without a luminous area (a point source) and for
  // a light not in view, and unless asked for.
  double luminance = 0;
  double solid_angle = 0;
};

}  // namespace relight

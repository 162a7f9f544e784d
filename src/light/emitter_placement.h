// Emitters where the lighting state puts them: each emitter's triangles turned by
// rotate_deg about the vertical axis through its pivot, then moved by translate (as exterior
// placements, docs/lighting-state.md), with its radiance luminance · colour, emitted on the
// front side of each triangle (the side its winding faces, as surfaces in the scene format).
// An emitter that is off or at zero luminance is left out.
#pragma once

#include <cstdint>
#include <vector>

#include "light/emitter_state.h"
#include "math/rgb.h"
#include "scene/scene.h"

namespace relight {

struct PlacedEmitters {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> emitter_of_triangle;  // index into `radiance`
  std::vector<Vec3> normals;                       // per triangle, unit: the emitting side
  std::vector<Rgb> triangle_radiance;              // per triangle, cd/m² per channel
  std::vector<Rgb> radiance;                       // per scene emitter, cd/m² per channel
};

PlacedEmitters place_emitters(const std::vector<Emitter>& emitters,
                              const std::vector<EmitterState>& states);

}  // namespace relight

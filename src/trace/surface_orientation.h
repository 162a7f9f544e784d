// Which way a scene's surfaces face. Surfaces are one-sided (docs/scene-format.md, "Geometry"):
// a room shell exported with its normals out (a common mistake of modelling tools) reflects
// nothing into the room and renders black, while its sensors still read plausible direct light.
// The air of the scene is found by flooding it with rays: from its seeds (the luminaires, the
// sensors along their normals) to the sides of the triangles they see, and from every side
// reached on to the sides it sees. A triangle reached only from behind, where that side is
// enclosed (few of its rays escape to infinity), bounds a closed space with its front turned
// away from it: it is turned. One reached only from behind in the open (a floor seen from
// above with nothing around) is reported, not turned: nothing says which side is meant.
// Window glass stops the flood (a window is part of the room's enclosure) and is never turned:
// its side is found from the light that passes. A scene with no seeds is seeded at the points of
// a lattice over its bounds that rays find enclosed and room-sized (at least 1.5 m across and
// 2 m high), so that an imported model without luminaires or sensors is checked too.
// Pinned by tests/trace/surface_orientation_test.cpp (a room turned inside out is found and
// turned whole; a correct room, a furniture box and an open floor are left alone).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "math/vec3.h"
#include "scene/scene.h"
#include "scene/triangle_soup.h"

namespace relight {

// A point in the air of the scene, and the hemisphere it looks into (a zero `facing`: every
// direction).
struct AirSeed {
  Vec3 point;
  Vec3 facing{0, 0, 0};
};

struct SurfaceOrientation {
  std::vector<std::uint32_t> turned;  // triangles whose front faced out of the space they bound
  std::size_t open_back_facing = 0;   // reached only from behind, in the open: not turned
  std::size_t unreached = 0;          // neither side reached from the seeds
  std::size_t checked = 0;            // the triangles looked at (window glass is not)
  bool lattice_seeds = false;         // no seeds given: seeded by the enclosed lattice points
};

// Finds the triangles of `soup` to turn. `glass[m]` is true for the materials that are window
// glass. Deterministic for a given soup and seeds.
SurfaceOrientation find_turned_surfaces(const TriangleSoup& soup, const std::vector<bool>& glass,
                                        std::span<const AirSeed> seeds);

// Reverses the winding of the given triangles.
void turn_triangles(TriangleSoup& soup, std::span<const std::uint32_t> triangles);

// The scene's seeds: its luminaires and its sensors (find_turned_surfaces uses at most 1,024 of
// them, spread evenly).
std::vector<AirSeed> air_seeds(const Scene& scene);

// Finds and turns the scene's static triangles that face out of the space they bound.
SurfaceOrientation orient_scene_surfaces(Scene& scene);

// One line for the user when something was turned or left facing away ("" otherwise).
std::string orientation_warning(const SurfaceOrientation& orientation);

}  // namespace relight

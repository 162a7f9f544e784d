// Geometry entries of a scene document (docs/scene-format.md), for tests that build scenes in
// code: one spelling of a box, a quad and a wall with a window.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "math/vec3.h"

namespace relight::testing {

// An axis-aligned box from `lo` to `hi` (normals outward).
inline nlohmann::json box(Vec3 lo, Vec3 hi, const std::string& material) {
  return {{"type", "box"},
          {"min", {lo.x, lo.y, lo.z}},
          {"max", {hi.x, hi.y, hi.z}},
          {"material", material}};
}

// A quad whose front side is u × v.
inline nlohmann::json quad(Vec3 corner, Vec3 u, Vec3 v, const std::string& material) {
  return {{"type", "quad"},
          {"corner", {corner.x, corner.y, corner.z}},
          {"u", {u.x, u.y, u.z}},
          {"v", {v.x, v.y, v.z}},
          {"material", material}};
}

// The wall z = `z` of a room 0..width × 0..height seen from inside (facing −z), in pieces
// around a window x0..x1 × y0..y1 of material `glass`: below, above, left, right, the glass.
inline std::vector<nlohmann::json> wall_around_window(double z, double width, double height,
                                                      double x0, double x1, double y0, double y1,
                                                      const std::string& wall,
                                                      const std::string& glass) {
  const auto piece = [&](double x, double y, double w, double h, const std::string& material) {
    return quad({x, y, z}, {0, h, 0}, {w, 0, 0}, material);
  };
  return {piece(0, 0, width, y0, wall), piece(0, y1, width, height - y1, wall),
          piece(0, y0, x0, y1 - y0, wall), piece(x1, y0, width - x1, y1 - y0, wall),
          piece(x0, y0, x1 - x0, y1 - y0, glass)};
}

}  // namespace relight::testing

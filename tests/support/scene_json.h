// Geometry entries of a scene document (docs/scene-format.md), for tests that build scenes in
// code: one spelling of a box and a quad.
#pragma once

#include <string>

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

}  // namespace relight::testing

// Geometry entries of a scene document (docs/scene-format.md), for tests that build scenes in
// code: one spelling of a box, a quad, a room of quads, a closed sphere, a wall with a window
// and a sunny south window.
#pragma once

#include <algorithm>
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

// A room 0..width × 0..height × 0..depth of six quads facing in: the floor, the ceiling, and
// the walls x = 0, x = width, z = depth, z = 0.
inline std::vector<nlohmann::json> quad_room(double width, double height, double depth,
                                             const std::string& floor, const std::string& ceiling,
                                             const std::string& walls) {
  return {quad({0, 0, 0}, {0, 0, depth}, {width, 0, 0}, floor),
          quad({0, height, 0}, {width, 0, 0}, {0, 0, depth}, ceiling),
          quad({0, 0, 0}, {0, height, 0}, {0, 0, depth}, walls),
          quad({width, 0, 0}, {0, 0, depth}, {0, height, 0}, walls),
          quad({0, 0, depth}, {0, height, 0}, {width, 0, 0}, walls),
          quad({0, 0, 0}, {width, 0, 0}, {0, height, 0}, walls)};
}

// A closed sphere of albedo `rho` (normals inward) with an isotropic luminaire of `candela`
// at its centre, the origin, and the sensor sets `sensors`: every point of its wall gets
// E_d = I / R² directly and E_d / (1 − ρ) in all.
inline nlohmann::json closed_sphere(double rho, double radius, double candela,
                                    const nlohmann::json& sensors) {
  return {{"materials", {{"wall", {{"albedo", {rho, rho, rho}}}}}},
          {"geometry",
           {{{"type", "sphere"},
             {"center", {0, 0, 0}},
             {"radius", radius},
             {"normals", "inward"},
             {"material", "wall"}}}},
          {"luminaires",
           {{{"name", "centre"},
             {"position", {0, 0, 0}},
             {"distribution", {{"type", "isotropic"}, {"candela", candela}}}}}},
          {"sensors", sensors}};
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

// A sunny south window in `scene`: its full wall z = `z` (a quad of `wall` from (0, 0, z), up
// `height`, across `width`) replaced by the wall around a window x0..x1 × y0..y1 of material
// "glass", the portal "south" to a CIE clear sky (type 12) of `sky_lux` horizontal
// illuminance with a sun due south at `altitude_deg` of `sun_lux` normal illuminance.
struct SouthWindow {
  double z = 4, width = 4, height = 2.8, x0 = 1, x1 = 3, y0 = 0.8, y1 = 2.2;
  std::string wall;
  double sky_lux = 12000, altitude_deg = 35, sun_lux = 60000;
};

inline void open_south_window(nlohmann::json& scene, const SouthWindow& w) {
  scene["materials"]["glass"] = {{"portal", true}};
  nlohmann::json& geometry = scene["geometry"];
  const nlohmann::json whole = quad({0, 0, w.z}, {0, w.height, 0}, {w.width, 0, 0}, w.wall);
  geometry.erase(std::remove(geometry.begin(), geometry.end(), whole), geometry.end());
  for (const nlohmann::json& piece :
       wall_around_window(w.z, w.width, w.height, w.x0, w.x1, w.y0, w.y1, w.wall, "glass")) {
    geometry.push_back(piece);
  }
  scene["portals"] = {{{"name", "south"},
                       {"material", "glass"},
                       {"environment",
                        {{"type", "cie_sky"},
                         {"sky_type", 12},
                         {"horizontal_illuminance", w.sky_lux},
                         {"sun", {{"azimuth_deg", 180}, {"altitude_deg", w.altitude_deg}}},
                         {"sun_illuminance", w.sun_lux}}}}};
}

}  // namespace relight::testing

// Daylight test cases with closed forms: a black room (albedo 0 everywhere unless asked)
// with a skylight in the ceiling and/or a window in the south wall, as scene JSON, and the
// configuration factors F from a point to a rectangle, so that a sensor lit through an
// opening of uniform luminance L reads E = L·π·F (shared/notes/photometry.md; the
// perpendicular case from Howell's catalogue of configuration factors, checked against the
// area integral ∫ cos θ₁ cos θ₂ / (π d²) dA).
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "math/vec3.h"
#include "support/scene_json.h"

namespace relight::testing {

// Receiver under one corner of an a×b rectangle in a parallel plane at distance h.
inline double parallel_corner_factor(double a, double b, double h) {
  const double x = a / h, y = b / h;
  const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
  return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2 * kPi);
}

// Rectangle [x0, x1] × [z0, z1] (coordinates relative to the receiver's foot point) in a
// parallel plane at distance h, by superposition of signed corner rectangles.
inline double parallel_rect_factor(double x0, double x1, double z0, double z1, double h) {
  const auto corner = [h](double a, double b) {
    const double sign = (a < 0 ? -1.0 : 1.0) * (b < 0 ? -1.0 : 1.0);
    return sign * parallel_corner_factor(std::abs(a), std::abs(b), h);
  };
  return corner(x1, z1) - corner(x0, z1) - corner(x1, z0) + corner(x0, z0);
}

// Receiver at distance c from a perpendicular plane, facing along it (toward +height);
// the rectangle spans [0, a] sideways from the receiver's foot point on that plane and
// [0, b] in height above the receiver's plane.
inline double perpendicular_corner_factor(double a, double b, double c) {
  const double r = std::hypot(b, c);
  return (std::atan(a / c) - c / r * std::atan(a / r)) / (2 * kPi);
}

// Rectangle [x0, x1] sideways × [y0, y1] in height (0 <= y0 <= y1) in a perpendicular plane at
// distance c, by superposition.
inline double perpendicular_rect_factor(double x0, double x1, double y0, double y1, double c) {
  const auto corner = [c](double a, double b) {
    return (a < 0 ? -1.0 : 1.0) * perpendicular_corner_factor(std::abs(a), b, c);
  };
  return corner(x1, y1) - corner(x0, y1) - corner(x1, y0) + corner(x0, y0);
}

struct Rect {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

struct WindowRoom {
  double width = 4, height = 3, depth = 5;  // along x, y, z; the room is [0,w]×[0,h]×[0,d]
  std::optional<Rect> skylight;             // ceiling opening: x in [u0,u1], z in [v0,v1]
  std::optional<Rect> south_window;         // opening of the wall z = depth: x, then y
  double albedo = 0;                        // of every opaque surface
};

// The default 4 × 3 × 5 m room's standard openings, shared by the daylight tests: a skylight
// x ∈ [1.5, 2.5], z ∈ [2, 3.5], and a south window (wall z = 5) x ∈ [1, 3], y ∈ [0.9, 2.1];
// their configuration factors from a receiver at p facing up.
inline constexpr Rect kSkylight{1.5, 2.5, 2, 3.5};
inline constexpr Rect kWindow{1, 3, 0.9, 2.1};

inline double skylight_factor(Vec3 p) {
  return parallel_rect_factor(kSkylight.u0 - p.x, kSkylight.u1 - p.x, kSkylight.v0 - p.z,
                              kSkylight.v1 - p.z, 3 - p.y);
}

inline double window_factor(Vec3 p) {
  return perpendicular_rect_factor(kWindow.u0 - p.x, kWindow.u1 - p.x, kWindow.v0 - p.y,
                                   kWindow.v1 - p.y, 5 - p.z);
}

// The rectangle corner + s·U + t·V (U, V unit; s in [0, lu], t in [0, lv]) as quads whose
// normal is U × V (or V × U when flipped), with `hole` cut out and filled with `glass`.
inline void add_pierced_rect(nlohmann::json& geometry, Vec3 corner, Vec3 U, double lu, Vec3 V,
                             double lv, const std::optional<Rect>& hole, bool flip,
                             const std::string& wall, const std::string& glass) {
  const auto add = [&](double s0, double s1, double t0, double t1, const std::string& m) {
    if (s1 <= s0 || t1 <= t0) return;
    const Vec3 c = corner + U * s0 + V * t0, u = U * (s1 - s0), v = V * (t1 - t0);
    geometry.push_back(flip ? quad(c, v, u, m) : quad(c, u, v, m));
  };
  if (!hole) {
    add(0, lu, 0, lv, wall);
    return;
  }
  const Rect& h = *hole;
  add(0, lu, 0, h.v0, wall);
  add(0, lu, h.v1, lv, wall);
  add(0, h.u0, h.v0, h.v1, wall);
  add(h.u1, lu, h.v0, h.v1, wall);
  add(h.u0, h.u1, h.v0, h.v1, glass);
}

// Materials "room", "skylight glass", "window glass"; portals "skylight" and "south window"
// (for the openings present) with placeholder uniform environments of 1000 cd/m²; inward
// normals. Tests add "sensors" (and may replace environments).
inline nlohmann::json window_room_json(const WindowRoom& room) {
  const double w = room.width, h = room.height, d = room.depth;
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  nlohmann::json geometry = nlohmann::json::array();
  const std::optional<Rect> none;
  add_pierced_rect(geometry, {0, 0, 0}, z, d, x, w, none, false, "room", "");  // floor, up
  add_pierced_rect(geometry, {0, h, 0}, x, w, z, d, room.skylight, false, "room",
                   "skylight glass");                                          // ceiling
  add_pierced_rect(geometry, {0, 0, 0}, x, w, y, h, none, false, "room", "");  // north
  add_pierced_rect(geometry, {0, 0, d}, x, w, y, h, room.south_window, true, "room",
                   "window glass");                                            // south
  add_pierced_rect(geometry, {0, 0, 0}, y, h, z, d, none, false, "room", "");  // west
  add_pierced_rect(geometry, {w, 0, 0}, z, d, y, h, none, false, "room", "");  // east
  const nlohmann::json uniform = {{"type", "uniform"}, {"luminance", 1000}};
  nlohmann::json portals = nlohmann::json::array();
  if (room.skylight) {
    portals.push_back(
        {{"name", "skylight"}, {"material", "skylight glass"}, {"environment", uniform}});
  }
  if (room.south_window) {
    portals.push_back(
        {{"name", "south window"}, {"material", "window glass"}, {"environment", uniform}});
  }
  const double a = room.albedo;
  return {{"materials",
           {{"room", {{"albedo", {a, a, a}}}},
            {"skylight glass", {{"albedo", {0, 0, 0}}, {"portal", true}}},
            {"window glass", {{"albedo", {0, 0, 0}}, {"portal", true}}}}},
          {"geometry", geometry},
          {"portals", portals}};
}

// The default room with its south window, grey (albedo 0.5), a 3 × 4 grid "floor" of
// sensors at `sensor_height` (x 0.5..3.5, z 0.5..4.5), and a small precompute.
inline nlohmann::json south_window_room(double sensor_height) {
  WindowRoom room;
  room.south_window = kWindow;
  room.albedo = 0.5;
  nlohmann::json scene = window_room_json(room);
  scene["sensors"] = {{{"name", "floor"},
                       {"grid",
                        {{"corner", {0.5, sensor_height, 0.5}},
                         {"u", {3, 0, 0}},
                         {"v", {0, 0, 4}},
                         {"nu", 3},
                         {"nv", 4}}}}};
  scene["precompute"] = {{"max_edge", 0.5}, {"gather_rays", 64}, {"sensor_gather_rays", 256}};
  return scene;
}

// Adds to a window room a 1 × 0.3 m strip emitter of 2,000 cd/m² under its ceiling and an oak
// cabinet (a movable object) in a corner: the near-field and movable-object sources beside its own.
inline void add_strip_and_cabinet(nlohmann::json& scene) {
  scene["emitters"] = {{{"name", "strip"},
                        {"geometry", quad({1.5, 2.5, 1}, {1, 0, 0}, {0, 0, 0.3}, "")},
                        {"luminance", 2000}}};
  scene["emitters"][0]["geometry"].erase("material");
  scene["materials"]["oak"] = {{"albedo", {0.6, 0.4, 0.2}}};
  scene["objects"] = {
      {{"name", "cabinet"}, {"geometry", {box({0.3, 0, 0.3}, {0.9, 1.6, 0.8}, "oak")}}}};
}

// A 0.6 × 0.6 m isotropic 1000 cd luminaire at (2, 2.9, 3) aimed down (its luminous area
// from "size"), for glare and task checks with closed forms.
inline nlohmann::json panel_luminaire(const std::string& name) {
  return {{"name", name},
          {"position", {2, 2.9, 3}},
          {"aim", {0, -1, 0}},
          {"size", {0.6, 0.6, 0}},
          {"distribution", {{"type", "isotropic"}, {"candela", 1000}}}};
}

}  // namespace relight::testing

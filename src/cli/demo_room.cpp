#include "cli/demo_room.h"

namespace relight {

namespace {

using nlohmann::json;

json quad(json corner, json u, json v, const char* material) {
  return {{"type", "quad"}, {"corner", corner}, {"u", u}, {"v", v}, {"material", material}};
}

json box(json lo, json hi, const char* material) {
  return {
      {"type", "box"}, {"min", lo}, {"max", hi}, {"normals", "outward"}, {"material", material}};
}

}  // namespace

json demo_room_scene() {
  constexpr double W = 6.0, H = 2.8, D = 4.5;  // room width (x), height (y), depth (z)
  constexpr double kLeft = 1.5, kRight = 4.5, kSill = 0.8, kHead = 2.3;  // the window
  json geometry = json::array({
      // Room shell, normals facing the interior.
      quad({0, 0, 0}, {0, 0, D}, {W, 0, 0}, "oak floor"),
      quad({0, H, 0}, {W, 0, 0}, {0, 0, D}, "ceiling"),
      quad({0, 0, 0}, {0, H, 0}, {0, 0, D}, "plaster"),
      quad({W, 0, 0}, {0, 0, D}, {0, H, 0}, "plaster"),
      quad({0, 0, 0}, {W, 0, 0}, {0, H, 0}, "blue accent"),
      // South wall (z = D) around a 3 × 1.5 m window, and the window glass (a portal).
      quad({0, 0, D}, {0, kSill, 0}, {W, 0, 0}, "plaster"),
      quad({0, kHead, D}, {0, H - kHead, 0}, {W, 0, 0}, "plaster"),
      quad({0, kSill, D}, {0, kHead - kSill, 0}, {kLeft, 0, 0}, "plaster"),
      quad({kRight, kSill, D}, {0, kHead - kSill, 0}, {W - kRight, 0, 0}, "plaster"),
      quad({kLeft, kSill, D}, {0, kHead - kSill, 0}, {kRight - kLeft, 0, 0}, "window glass"),
      // Rug.
      quad({1.5, 0.005, 1.0}, {0, 0, 2.4}, {3.0, 0, 0}, "wool rug"),
      // Dining table: top and four legs.
      box({2.0, 0.72, 1.5}, {3.6, 0.76, 2.4}, "walnut"),
      box({2.05, 0, 1.55}, {2.11, 0.72, 1.61}, "walnut"),
      box({3.49, 0, 1.55}, {3.55, 0.72, 1.61}, "walnut"),
      box({2.05, 0, 2.29}, {2.11, 0.72, 2.35}, "walnut"),
      box({3.49, 0, 2.29}, {3.55, 0.72, 2.35}, "walnut"),
      // Sofa against the left wall: seat, back, arms.
      box({0.1, 0, 1.0}, {1.0, 0.45, 3.2}, "red fabric"),
      box({0.1, 0.45, 1.0}, {0.3, 0.9, 3.2}, "red fabric"),
      box({0.1, 0.45, 0.85}, {1.0, 0.65, 1.0}, "red fabric"),
      box({0.1, 0.45, 3.2}, {1.0, 0.65, 3.35}, "red fabric"),
      // Bookshelf against the back wall.
      box({4.2, 0, 0.05}, {5.6, 2.0, 0.4}, "graphite"),
      // A white ball on the bookshelf (above the work plane's sensors).
      {{"type", "sphere"},
       {"center", {4.6, 2.15, 0.22}},
       {"radius", 0.15},
       {"normals", "outward"},
       {"subdivisions", 3},
       {"material", "white paint"}},
  });
  json materials = {
      {"oak floor", {{"albedo", {0.45, 0.32, 0.22}}}},
      {"ceiling", {{"albedo", {0.85, 0.85, 0.85}}}},
      {"plaster", {{"albedo", {0.75, 0.72, 0.66}}}},
      {"blue accent", {{"albedo", {0.25, 0.42, 0.55}}}},
      {"wool rug", {{"albedo", {0.70, 0.62, 0.48}}}},
      {"walnut", {{"albedo", {0.30, 0.20, 0.13}}}},
      {"red fabric", {{"albedo", {0.55, 0.14, 0.11}}}},
      {"graphite", {{"albedo", {0.22, 0.22, 0.24}}}},
      {"white paint", {{"albedo", {0.80, 0.80, 0.80}}}},
      {"window glass", {{"albedo", {0, 0, 0}}, {"portal", true}}},
  };
  // An overcast day by default; the demo's states set clear days with the sun.
  json portals = json::array({
      {{"name", "south window"},
       {"material", "window glass"},
       {"environment",
        {{"type", "cie_sky"}, {"sky_type", "overcast"}, {"horizontal_illuminance", 10000}}}},
  });
  json luminaires = json::array({
      {{"name", "downlight left"},
       {"position", {2.0, 2.75, 2.0}},
       {"aim", {0, -1, 0}},
       {"color", {1.0, 0.86, 0.70}},
       {"distribution",
        {{"type", "cosine_power"}, {"candela", 900}, {"exponent", 4}, {"cutoff_deg", 60}}}},
      {{"name", "downlight right"},
       {"position", {4.0, 2.75, 2.0}},
       {"aim", {0, -1, 0}},
       {"color", {1.0, 0.86, 0.70}},
       {"distribution",
        {{"type", "cosine_power"}, {"candela", 900}, {"exponent", 4}, {"cutoff_deg", 60}}}},
      {{"name", "wall washer"},
       {"position", {5.5, 2.7, 1.2}},
       {"aim", {-0.35, -0.75, -0.55}},
       {"distribution",
        {{"type", "curve"},
         {"gamma_deg", {0, 15, 30, 45, 60, 90}},
         {"candela", {1400, 1300, 850, 300, 60, 0}}}}},
      {{"name", "pendant"},
       {"position", {2.8, 1.9, 1.95}},
       {"color", {1.0, 0.78, 0.55}},
       {"dimmer", 0.8},
       {"distribution", {{"type", "isotropic"}, {"candela", 120}}}},
  });
  json sensors = json::array({
      {{"name", "work plane"},
       {"grid",
        {{"corner", {1.1, 0.8, 0.5}},
         {"u", {4.6, 0, 0}},
         {"v", {0, 0, 3.7}},
         {"nu", 23},
         {"nv", 18}}},
       {"normal", {0, 1, 0}}},
  });
  json cameras = json::array({
      {{"name", "overview"},
       {"eye", {3.0, 1.7, 4.35}},
       {"target", {2.6, 0.9, 0.0}},
       {"fov_deg", 68}},
      {{"name", "sofa"}, {"eye", {5.6, 1.5, 3.9}}, {"target", {0.5, 0.7, 2.0}}, {"fov_deg", 60}},
      {{"name", "window"}, {"eye", {3.0, 1.5, 0.6}}, {"target", {3.0, 1.1, 4.5}}, {"fov_deg", 70}},
  });
  // Munich: the site of every sun given by date and time alone.
  json site = {{"latitude", 48.14},
               {"longitude", 11.58},
               {"utc_offset", 1},
               {"elevation_m", 520},
               {"north_deg", 0}};
  return {{"description", "relight demo: a furnished living room with a south window"},
          {"site", site},
          {"materials", materials},
          {"geometry", geometry},
          {"luminaires", luminaires},
          {"sensors", sensors},
          {"cameras", cameras},
          {"portals", portals},
          {"precompute", {{"max_edge", 0.3}}}};
}

}  // namespace relight

// The built-in demo: a furnished 6 × 4.5 m living room with coloured walls, furniture,
// analytic luminaires (downlights, a wall washer, a pendant), a work-plane sensor grid
// and a camera. Built in code so `relight demo` needs no files.
#pragma once

#include <nlohmann/json.hpp>

namespace relight {

nlohmann::json demo_room_scene();

}  // namespace relight

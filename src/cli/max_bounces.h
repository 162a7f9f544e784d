// `--max-bounces N` of `relight render` and `relight probe`: 1 shows the top-level environment's
// direct light alone, as `relight reference --max-bounces 1` traces it (the like-for-like
// comparison of the visibility cuts, Iwasaki et al., Cyberworlds, §VI, who render direct light
// only); 0, the default, every bounce. The stored transfer of luminaires, windows and emitters
// holds their interreflection summed with their direct light, so a scene with any of them
// refuses 1.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "runtime/relighter.h"
#include "scene/scene.h"

namespace relight {

void add_max_bounces_option(CLI::App& cmd, int& max_bounces);

// The Relighter's settings for `max_bounces`.
RelighterSettings max_bounces_settings(int max_bounces);
// InputError naming `where` when max_bounces is 1 and the scene has light other than its
// top-level environment, or none.
void check_max_bounces(const Scene& scene, int max_bounces, const std::string& where);

}  // namespace relight

#include "cli/max_bounces.h"

#include "common/input_error.h"

namespace relight {

void add_max_bounces_option(CLI::App& cmd, int& max_bounces) {
  cmd.add_option("--max-bounces", max_bounces,
                 "1 = the top-level environment's direct light alone (as relight reference "
                 "--max-bounces 1); 0 (default) = every bounce")
      ->check(CLI::Range(0, 1));
}

RelighterSettings max_bounces_settings(int max_bounces) {
  RelighterSettings settings;
  settings.environment_bounce = max_bounces != 1;
  return settings;
}

void check_max_bounces(const Scene& scene, int max_bounces, const std::string& where) {
  if (max_bounces != 1) return;
  if (!scene.environment || !scene.luminaires.empty() || !scene.portals.empty() ||
      !scene.emitters.empty()) {
    fail_input(where,
               "--max-bounces 1 needs a scene lit by its top-level environment alone: "
               "the stored light of luminaires, windows and emitters holds their "
               "interreflection");
  }
}

}  // namespace relight

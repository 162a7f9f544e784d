#include "light/lighting_state.h"

namespace relight {

LightingState default_lighting_state(const Scene& scene) {
  LightingState s;
  for (const Luminaire& l : scene.luminaires) {
    s.luminaires.push_back(luminaire_state(l));
  }
  for (const Portal& p : scene.portals) {
    s.portals.push_back(portal_state(p, scene.exterior.size()));
  }
  for (const Emitter& e : scene.emitters) s.emitters.push_back(emitter_state(e));
  s.objects.resize(scene.objects.size());
  s.materials = scene.materials;
  s.environment = scene.environment;
  s.site = scene.site;
  return s;
}

}  // namespace relight

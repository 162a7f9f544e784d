#include "render/pixel_direct.h"

namespace relight {

std::vector<LuminaireLight> pixel_lights(const Scene& scene, const Relighter& relighter,
                                         int opening_samples) {
  return relighter.luminaires().lights(scene.luminaires, opening_samples);
}

}  // namespace relight

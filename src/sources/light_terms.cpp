#include "sources/light_terms.h"

#include <stdexcept>

namespace relight {

LightTerms::LightTerms(const TransferView& transfer, const RuntimeScene* runtime,
                       const Scene& scene, const LightTermSettings& settings)
    : luminaires_(std::make_unique<LuminaireLighting>(
          LuminaireTransferSet{transfer.luminaires, transfer.receivers, transfer.sh_order,
                               transfer.direct_sh_mode},
          scene, settings.window)),
      portals_(std::make_unique<PortalSetLighting>(
          PortalTransferSet{transfer.portals, transfer.receivers, transfer.portal_sh_order},
          runtime, scene, settings.sun_bounce)) {
  all_ = {luminaires_.get(), portals_.get()};
  if ((!scene.emitters.empty() || scene.environment) && runtime == nullptr) {
    throw std::invalid_argument("LightTerms: emitters and an environment need the run-time scene");
  }
  if (!scene.emitters.empty()) {
    emitters_ =
        std::make_unique<EmitterLighting>(transfer.nearfield, *runtime, scene, settings.emitters);
    all_.push_back(emitters_.get());
  }
  if (scene.environment) {
    if (transfer.cuts.directions.empty()) {
      throw std::invalid_argument(
          "Relighter: a scene with a top-level environment needs visibility cuts in its "
          "transfer (run relight precompute again)");
    }
    environment_ = std::make_unique<EnvironmentLighting>(transfer.cuts, *runtime, transfer.objects);
    environment_->set_bounce(settings.environment_bounce);
    environment_->set_environment(scene.environment);
    all_.push_back(environment_.get());
  }
}

}  // namespace relight

#include "cli/relit_scene.h"

namespace relight {

RelitScene relight_transfer_file(const std::filesystem::path& rlt,
                                 const std::optional<std::filesystem::path>& state_file) {
  RelitScene r;
  r.transfer = std::make_unique<TransferFile>(open_transfer_file(rlt));
  r.relighter = std::make_unique<Relighter>(r.transfer->view, r.transfer->scene);
  if (state_file) r.relighter->set_state(load_lighting_state(r.transfer->scene, *state_file));
  r.irradiance.resize(3 * r.relighter->receivers());
  r.relighter->relight(r.irradiance);
  return r;
}

std::vector<Rgb> RelitScene::sensor_irradiance() const {
  std::vector<Rgb> out;
  for (std::size_t s = 0; s < transfer->sensor_count; ++s) {
    const std::size_t r = 3 * (transfer->vertex_count + s);
    out.push_back({irradiance[r], irradiance[r + 1], irradiance[r + 2]});
  }
  return out;
}

}  // namespace relight

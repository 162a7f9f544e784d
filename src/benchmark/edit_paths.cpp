#include "benchmark/edit_paths.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace relight {

std::size_t most_used_material(const TransferFile& t) {
  std::vector<std::size_t> count(t.scene.materials.size(), 0);
  for (const std::uint32_t m : t.view.scene.vertex_material) {
    if (m < count.size() && !t.scene.materials[m].portal) ++count[m];
  }
  return static_cast<std::size_t>(std::max_element(count.begin(), count.end()) - count.begin());
}

void advance_sky(EnvironmentSpec& e, int frame) {
  switch (e.type) {
    case EnvironmentType::kUniform:
      e.luminance *= frame % 2 == 0 ? 1.01 : 1 / 1.01;
      break;
    case EnvironmentType::kMap:
      e.rotate_deg += 1;
      break;
    case EnvironmentType::kCieSky:
    case EnvironmentType::kPerezSky:
      if (e.sun.placement == SunPlacement::kPlaceAndTime) {
        CivilDateTime& t = e.sun.local_time;
        t.minute = (t.minute + 1) % 60;
        if (t.minute == 0) t.hour = (t.hour + 1) % 24;
      } else if (e.sun.placement == SunPlacement::kAngles) {
        e.sun.azimuth_deg = std::fmod(e.sun.azimuth_deg + 0.25, 360.0);
      } else {
        e.scaling_value *= frame % 2 == 0 ? 1.01 : 1 / 1.01;
      }
      break;
  }
}

}  // namespace relight

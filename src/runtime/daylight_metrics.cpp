// Climate-based daylight metrics; definitions in daylight_metrics.h.
#include "runtime/daylight_metrics.h"

#include <algorithm>

namespace relight {

namespace {

constexpr double kDaTarget = 300, kUdiLow = 100, kUdiHigh = 2000, kAseLux = 1000;
constexpr int kAseHours = 250;

struct ProvisionLevel {
  DaylightProvision level;
  double target, minimum;  // E_T over 50 % of the points, E_TM over 95 %
};
constexpr ProvisionLevel kLevels[] = {{DaylightProvision::kHigh, 750, 500},
                                      {DaylightProvision::kMedium, 500, 300},
                                      {DaylightProvision::kMinimum, 300, 100}};

}  // namespace

std::vector<SensorDaylight> sensor_daylight(std::span<const float> lux,
                                            std::span<const float> direct_sun_lux,
                                            std::size_t sensors) {
  std::vector<SensorDaylight> out(sensors);
  if (sensors == 0) return out;
  const std::size_t hours = lux.size() / sensors;
  for (std::size_t h = 0; h < hours; ++h) {
    for (std::size_t s = 0; s < sensors; ++s) {
      const double e = lux[h * sensors + s];
      SensorDaylight& d = out[s];
      if (e >= kDaTarget) d.da300 += 1;
      if (e < kUdiLow) {
        d.udi_fell_short += 1;
      } else if (e <= kUdiHigh) {
        d.udi_useful += 1;
      } else {
        d.udi_exceeded += 1;
      }
      if (direct_sun_lux[h * sensors + s] >= kAseLux) ++d.ase_hours;
    }
  }
  if (hours > 0) {
    const double n = static_cast<double>(hours);
    for (SensorDaylight& d : out) {
      d.da300 /= n;
      d.udi_fell_short /= n;
      d.udi_useful /= n;
      d.udi_exceeded /= n;
    }
  }
  return out;
}

const char* daylight_provision_name(DaylightProvision level) {
  switch (level) {
    case DaylightProvision::kHigh:
      return "high";
    case DaylightProvision::kMedium:
      return "medium";
    case DaylightProvision::kMinimum:
      return "minimum";
    case DaylightProvision::kNone:
      break;
  }
  return "none";
}

SetDaylight set_daylight(std::span<const float> lux, std::size_t sensors,
                         std::span<const SensorDaylight> per_sensor, std::size_t first,
                         std::size_t count) {
  SetDaylight out;
  if (count == 0 || sensors == 0) return out;
  for (std::size_t s = first; s < first + count; ++s) {
    const SensorDaylight& d = per_sensor[s];
    if (d.da300 >= 0.5) out.sda300 += 1;
    if (d.ase_hours > kAseHours) out.ase += 1;
    out.mean_da300 += d.da300;
  }
  const double n = static_cast<double>(count);
  out.sda300 /= n;
  out.ase /= n;
  out.mean_da300 /= n;
  const std::size_t hours = lux.size() / sensors;
  if (hours == 0) return out;
  for (const ProvisionLevel& level : kLevels) {
    std::size_t met = 0;
    for (std::size_t h = 0; h < hours; ++h) {
      std::size_t at_target = 0, at_minimum = 0;
      for (std::size_t s = first; s < first + count; ++s) {
        const double e = lux[h * sensors + s];
        at_target += e >= level.target ? 1 : 0;
        at_minimum += e >= level.minimum ? 1 : 0;
      }
      if (at_target >= 0.5 * n && at_minimum >= 0.95 * n) ++met;
    }
    if (met >= 0.5 * static_cast<double>(hours)) {
      out.en17037 = level.level;
      break;
    }
  }
  return out;
}

std::vector<SetDaylight> sets_daylight(std::span<const float> lux, std::size_t sensors,
                                       std::span<const SensorDaylight> per_sensor,
                                       std::span<const std::size_t> counts) {
  std::vector<SetDaylight> out;
  std::size_t first = 0;
  for (const std::size_t count : counts) {
    out.push_back(set_daylight(lux, sensors, per_sensor, first, count));
    first += count;
  }
  return out;
}

}  // namespace relight

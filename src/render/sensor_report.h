// Sensor output as lighting designers read it: the CSV of the contract
// (sensor,index,x,y,z,nx,ny,nz,lux,r,g,b — lux = Y of r,g,b, Rec.709 weights) and per-set
// statistics Eavg, Emin, Emax and uniformity U0 = Emin / Eavg.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "math/rgb.h"
#include "scene/scene.h"

namespace relight {

struct SensorStatistics {
  std::string name;
  std::size_t count = 0;
  double e_avg = 0, e_min = 0, e_max = 0, u0 = 0;  // lux; U0 dimensionless
};

// A sensor set's name as a CSV field: quoted (with doubled quotes) when it holds a comma, a
// quote or a newline.
std::string csv_name(const std::string& name);

// `illuminance` holds one value per sensor point in scene order (set by set).
std::string sensor_csv(const Scene& scene, const std::vector<Rgb>& illuminance);
void write_sensor_csv(const std::filesystem::path& file, const Scene& scene,
                      const std::vector<Rgb>& illuminance);
std::vector<SensorStatistics> sensor_statistics(const Scene& scene,
                                                const std::vector<Rgb>& illuminance);
void print_sensor_statistics(std::ostream& out, const std::vector<SensorStatistics>& stats);

}  // namespace relight

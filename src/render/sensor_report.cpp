#include "render/sensor_report.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <ostream>

#include "common/atomic_file.h"

namespace relight {

std::string csv_name(const std::string& name) {
  // Sensor names are free text: quote them when they contain CSV metacharacters.
  if (name.find_first_of(",\"\n") == std::string::npos) return name;
  std::string quoted = "\"";
  for (const char ch : name) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

std::string sensor_csv(const Scene& scene, const std::vector<Rgb>& e) {
  std::string csv = "sensor,index,x,y,z,nx,ny,nz,lux,r,g,b\n";
  std::size_t k = 0;
  char line[512];
  for (const SensorSet& s : scene.sensors) {
    for (std::size_t i = 0; i < s.points.size(); ++i, ++k) {
      const Vec3& p = s.points[i];
      const Rgb& c = e.at(k);
      std::snprintf(line, sizeof line, ",%zu,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                    i, p.x, p.y, p.z, s.normal.x, s.normal.y, s.normal.z, luminance(c), c.r, c.g,
                    c.b);
      csv += csv_name(s.name);
      csv += line;
    }
  }
  return csv;
}

void write_sensor_csv(const std::filesystem::path& file, const Scene& scene,
                      const std::vector<Rgb>& illuminance) {
  write_text_atomically(file, sensor_csv(scene, illuminance));
}

std::vector<SensorStatistics> sensor_statistics(const Scene& scene, const std::vector<Rgb>& e) {
  std::vector<SensorStatistics> out;
  std::size_t k = 0;
  for (const SensorSet& s : scene.sensors) {
    SensorStatistics st;
    st.name = s.name;
    st.count = s.points.size();
    double sum = 0;
    st.e_min = std::numeric_limits<double>::infinity();
    st.e_max = -st.e_min;
    for (std::size_t i = 0; i < s.points.size(); ++i, ++k) {
      const double lux = luminance(e.at(k));
      sum += lux;
      st.e_min = std::min(st.e_min, lux);
      st.e_max = std::max(st.e_max, lux);
    }
    st.e_avg = sum / static_cast<double>(st.count);
    st.u0 = st.e_avg > 0 ? st.e_min / st.e_avg : 0;
    out.push_back(st);
  }
  return out;
}

void print_sensor_statistics(std::ostream& out, const std::vector<SensorStatistics>& stats) {
  char line[512];
  for (const SensorStatistics& s : stats) {
    std::snprintf(line, sizeof line,
                  "%s: %zu points  Eavg %.4g lx  Emin %.4g lx  Emax %.4g lx  U0 %.3f\n",
                  s.name.c_str(), s.count, s.e_avg, s.e_min, s.e_max, s.u0);
    out << line;
  }
}

}  // namespace relight

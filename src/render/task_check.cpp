// EN 12464-1 task checks; see task_check.h.
#include "render/task_check.h"

#include <algorithm>
#include <limits>

#include "math/rgb.h"
#include "render/glare.h"

namespace relight {

TaskChecks check_tasks(RelitScene& scene) {
  const Scene& s = scene.scene();
  TaskChecks out;
  out.declared = s.maintenance_factor.has_value();
  out.maintenance_factor = s.maintenance_factor.value_or(1.0);
  const LightingState initial = scene.state();
  scene.apply(maintained_state(initial, out.maintenance_factor));
  const std::vector<Rgb> e = scene.sensor_irradiance();
  std::size_t first = 0;
  for (const SensorSet& set : s.sensors) {
    const std::size_t count = set.points.size();
    if (set.task) {
      TaskCheck check;
      check.name = set.name;
      check.required = *set.task;
      double sum = 0;
      check.e_min = std::numeric_limits<double>::infinity();
      for (std::size_t i = first; i < first + count; ++i) {
        const double lux = luminance(e[i]);
        sum += lux;
        check.e_min = std::min(check.e_min, lux);
      }
      check.e_avg = sum / static_cast<double>(count);
      check.u0 = check.e_avg > 0 ? check.e_min / check.e_avg : 0;
      if (check.required.em) check.em_pass = check.e_avg >= *check.required.em;
      if (check.required.u0) check.u0_pass = check.u0 >= *check.required.u0;
      for (const TaskObserver& o : check.required.observers) {
        ObserverCheck c{o, evaluate_glare(scene, o.position, o.view).ugr, true};
        if (check.required.ugr_l && c.ugr) c.pass = *c.ugr <= *check.required.ugr_l;
        check.observers.push_back(c);
      }
      out.tasks.push_back(std::move(check));
    }
    first += count;
  }
  scene.apply(initial);
  return out;
}

}  // namespace relight

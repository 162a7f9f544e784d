// `relight probe SCENE.rlt [--state STATE.json] [-o SENSORS.csv] [--check]`: sensor
// illuminance of the precomputed scene under a lighting state, in the reference's CSV format,
// with Eavg, Emin, Emax and U0 per sensor set on stdout; with --check, each task area's
// requirements against its maintained values (render/task_check.h), exit 0 either way.
#include <cstdio>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/max_bounces.h"
#include "common/input_error.h"
#include "render/sensor_report.h"
#include "render/task_check.h"
#include "runtime/relit_scene.h"

namespace relight {

namespace {

struct ProbeArgs {
  std::string rlt, state, output;
  bool check = false;
  int max_bounces = 0;
};

const char* verdict(bool pass) {
  return pass ? "pass" : "FAIL";
}

void print_checks(RelitScene& relit) {
  const TaskChecks checks = check_tasks(relit);
  if (checks.tasks.empty()) {
    std::printf("check: no sensor set has a \"task\" (docs/scene-format.md)\n");
    return;
  }
  if (!checks.declared) {
    std::fprintf(stderr,
                 "warning: the scene declares no \"maintenance_factor\": taken as 1 (EN 12464-1 "
                 "asks for it to be declared)\n");
  }
  for (const TaskCheck& t : checks.tasks) {
    std::printf("task \"%s\" (maintained values, maintenance factor %.2f):\n", t.name.c_str(),
                checks.maintenance_factor);
    if (t.required.em) {
      std::printf("  Em   %8.1f lx  required >= %.1f lx  %s\n", t.e_avg, *t.required.em,
                  verdict(t.em_pass));
    }
    if (t.required.u0) {
      std::printf("  U0   %8.3f     required >= %.2f     %s\n", t.u0, *t.required.u0,
                  verdict(t.u0_pass));
    }
    for (std::size_t k = 0; k < t.observers.size(); ++k) {
      const ObserverCheck& o = t.observers[k];
      const Vec3 p = o.observer.position, v = o.observer.view;
      char value[32];
      if (o.ugr) {
        std::snprintf(value, sizeof value, "%8.1f", *o.ugr);
      } else {
        std::snprintf(value, sizeof value, "%8s", "none");
      }
      std::printf("  UGR  %s     ", value);
      if (t.required.ugr_l) {
        std::printf("required <= %.1f  %s", *t.required.ugr_l, verdict(o.pass));
      }
      std::printf("  observer %zu at (%.2f, %.2f, %.2f) looking (%.2f, %.2f, %.2f)%s\n", k + 1, p.x,
                  p.y, p.z, v.x, v.y, v.z, o.ugr ? "" : " (no luminaire in view)");
    }
  }
}

int run_probe(const ProbeArgs& args) {
  RelitScene relit(
      args.rlt,
      args.state.empty() ? std::nullopt : std::optional<std::filesystem::path>(args.state),
      max_bounces_settings(args.max_bounces));
  check_max_bounces(relit.scene(), args.max_bounces, args.rlt);
  const Scene& scene = relit.scene();
  if (scene.sensor_count() == 0) fail_input(args.rlt, "the scene has no sensors");
  const std::vector<Rgb> e = relit.sensor_irradiance();
  print_sensor_statistics(std::cout, sensor_statistics(scene, e));
  if (!args.output.empty()) {
    write_sensor_csv(args.output, scene, e);
    std::cout << "wrote " << args.output << "\n";
  }
  if (args.check) {
    std::cout.flush();
    print_checks(relit);
  }
  return 0;
}

}  // namespace

void add_probe_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ProbeArgs>();
  CLI::App* cmd = app.add_subcommand("probe", "Sensor illuminance of a precomputed scene");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_option("--state", args->state, "lighting state JSON (default: the scene's own)");
  add_max_bounces_option(*cmd, args->max_bounces);
  cmd->add_option("-o,--output", args->output, "sensor CSV to write");
  cmd->add_flag("--check", args->check,
                "check each task area's Em, U0 and UGR (maintained values; EN 12464-1)");
  cmd->callback([args, &action] { action = [args] { return run_probe(*args); }; });
}

}  // namespace relight

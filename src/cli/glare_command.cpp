// `relight glare SCENE.rlt [--state STATE.json] --observer X,Y,Z --view DX,DY,DZ
// [--camera NAME]`: UGR, DGP and the vertical illuminance at an observer's eye
// (render/glare.h), as one JSON line.
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "common/input_error.h"
#include "render/glare.h"

namespace relight {

namespace {

struct GlareArgs {
  std::string rlt, state, observer, view, camera;
};

Vec3 parse_triple(const std::string& option, const std::string& text) {
  std::stringstream in(text);
  double v[3];
  char comma = 0;
  if (!(in >> v[0] >> comma) || comma != ',' || !(in >> v[1] >> comma) || comma != ',' ||
      !(in >> v[2]) || !in.eof() || !std::isfinite(v[0]) || !std::isfinite(v[1]) ||
      !std::isfinite(v[2])) {
    fail_input(option, "expected three numbers X,Y,Z, got \"" + text + "\"");
  }
  return {v[0], v[1], v[2]};
}

nlohmann::json vec(Vec3 v) {
  return {v.x, v.y, v.z};
}

int run_glare(const GlareArgs& args) {
  RelitScene relit(args.rlt, args.state.empty() ? std::nullopt
                                                : std::optional<std::filesystem::path>(args.state));
  Vec3 eye, view;
  if (!args.camera.empty()) {
    if (!args.observer.empty() || !args.view.empty()) {
      fail_input("--camera", "give either --camera or --observer and --view");
    }
    const Camera* camera = relit.scene().find_camera(args.camera);
    if (camera == nullptr)
      fail_input("--camera", "the scene has no camera \"" + args.camera + "\"");
    eye = camera->eye;
    view = camera->target - camera->eye;
  } else {
    if (args.observer.empty() || args.view.empty()) {
      fail_input("glare", "give --observer X,Y,Z and --view DX,DY,DZ (or --camera NAME)");
    }
    eye = parse_triple("--observer", args.observer);
    view = parse_triple("--view", args.view);
  }
  if (!(length(view) > 0)) fail_input("--view", "the view direction must not be zero");
  const GlareResult g = evaluate_glare(relit, eye, view);
  nlohmann::json sources = nlohmann::json::array();
  for (const GlareSource& s : g.sources) {
    sources.push_back({{"kind", s.kind},
                       {"name", s.name},
                       {"direction", vec(s.direction)},
                       {"luminance", s.luminance},
                       {"solid_angle", s.solid_angle},
                       {"position_index", s.position_index}});
  }
  const nlohmann::json out = {{"ugr", g.ugr ? nlohmann::json(*g.ugr) : nlohmann::json(nullptr)},
                              {"dgp", g.dgp},
                              {"ev", g.ev},
                              {"luminaire_direct_ev", g.luminaire_direct_ev},
                              {"background_luminance", g.background_luminance},
                              {"observer", vec(eye)},
                              {"view", vec(normalize(view))},
                              {"sources", sources},
                              {"unrated", g.unrated}};
  for (const std::string& name : g.unrated) {
    std::fprintf(stderr,
                 "warning: luminaire \"%s\" has no luminous area (give it a \"size\"): left out "
                 "of UGR and DGP\n",
                 name.c_str());
  }
  std::cout << out.dump() << "\n";
  return 0;
}

}  // namespace

void add_glare_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<GlareArgs>();
  CLI::App* cmd = app.add_subcommand("glare", "UGR and DGP at an observer's eye, as JSON");
  cmd->add_option("scene", args->rlt, "precomputed .rlt file")->required();
  cmd->add_option("--state", args->state, "lighting state JSON (default: the scene's own)");
  cmd->add_option("--observer", args->observer, "eye position X,Y,Z (m)");
  cmd->add_option("--view", args->view, "view direction DX,DY,DZ");
  cmd->add_option("--camera", args->camera, "a scene camera's eye and view instead");
  cmd->callback([args, &action] { action = [args] { return run_glare(*args); }; });
}

}  // namespace relight

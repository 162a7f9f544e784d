// `relight import MODEL -o SCENE.json [--storey NAME|N] [--space NAME]... [--work-plane M]
// [--border M] [--max-edge M] [--furniture static|objects] [--window-material PATTERN]...
// [--photometry-map F]`:
// an IFC, glTF or OBJ model made a scene (src/import/imported_scene.h); prints one JSON line of
// what it found.
#include <CLI/CLI.hpp>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "common/input_error.h"
#include "import/ifc_model.h"
#include "import/imported_scene.h"
#include "import/mesh_model.h"

namespace relight {

namespace {

struct ImportArgs {
  std::filesystem::path model, output, photometry_map;
  std::string storey, furniture = "static";
  std::vector<std::string> spaces, window_materials;
  double work_plane = 0.8, border = 0.5, max_edge = 0;
};

int run_import(const ImportArgs& args) {
  std::string ext = args.model.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (!std::filesystem::is_regular_file(args.model))
    fail_input(args.model.string(), "no such file");
  if (args.output.extension() != ".json")
    fail_input(args.output.string(), "the scene file must end in .json");
  ImportOptions options;
  if (!args.storey.empty()) options.storey = args.storey;
  options.spaces = args.spaces;
  options.work_plane = args.work_plane;
  options.border = args.border;
  options.furniture_objects = args.furniture == "objects";
  if (args.max_edge > 0) options.max_edge = args.max_edge;
  if (!args.photometry_map.empty()) options.photometry = read_photometry_map(args.photometry_map);
  BuildingModel model;
  if (ext == ".ifc") {
    model = read_ifc_model(args.model);
  } else if (ext == ".gltf" || ext == ".glb" || ext == ".obj") {
    model = read_mesh_model(args.model, args.window_materials);
  } else {
    fail_input(args.model.string(), "not a model relight imports (.ifc, .gltf, .glb, .obj)");
  }
  const ImportSummary summary = write_imported_scene(model, options, args.model, args.output);
  std::printf("%s\n", summary_json(summary).c_str());
  return 0;
}

}  // namespace

void add_import_command(CLI::App& app, Action& action) {
  auto args = std::make_shared<ImportArgs>();
  CLI::App* cmd = app.add_subcommand(
      "import", "make a scene of a building model (IFC, glTF, OBJ): portals, sensor grids, site");
  cmd->add_option("model", args->model, "the model: .ifc, .gltf, .glb or .obj")->required();
  cmd->add_option("-o,--output", args->output, "the scene JSON to write (meshes go beside it)")
      ->required();
  cmd->add_option("--storey", args->storey,
                  "one storey: its name, or its number from 1 by elevation");
  cmd->add_option("--space", args->spaces, "a space that gets sensors (repeatable; default: all)");
  cmd->add_option("--work-plane", args->work_plane, "sensor height above the floor, m")
      ->check(CLI::Range(0.0, 3.0));
  cmd->add_option("--border", args->border, "band kept free along the walls, m")
      ->check(CLI::Range(0.0, 5.0));
  cmd->add_option("--max-edge", args->max_edge,
                  "longest edge of the receivers' mesh, m (precompute.max_edge; default 0.25)")
      ->check(CLI::Range(0.02, 10.0));
  cmd->add_option("--furniture", args->furniture, "furniture static or movable objects")
      ->check(CLI::IsMember({"static", "objects"}));
  cmd->add_option("--window-material", args->window_materials,
                  "glTF/OBJ material names that are window glass (wildcards * ?; repeatable)");
  cmd->add_option("--photometry-map", args->photometry_map,
                  "JSON object: light fixture type name -> IES/LDT file");
  cmd->callback([args, &action] { action = [args] { return run_import(*args); }; });
}

}  // namespace relight

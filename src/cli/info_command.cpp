// `relight info SCENE.json [--ranks K]`: counts (triangles, vertices after preparation, luminaires,
// sensors) and the bounding box, after full validation of the scene and its files, and the
// precompute's predicted peak memory ("memory estimate: N MB (its parts)", and a rank's of K).
// `relight info FILE.ies|FILE.ldt`: the photometric file's summary as one JSON line
// (light/photometry_summary.h).
#include <cstdio>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "engine/receivers.h"
#include "light/luminaire_frame.h"
#include "light/photometry_summary.h"
#include "scene/scene_loader.h"
#include "sources/objects/object_mesh.h"
#include "sources/portals/portal_geometry.h"
#include "sources/precompute.h"
#include "trace/traced_scene.h"

namespace relight {

namespace {

// The precompute's predicted peak (sources/precompute_memory.h), measured as `relight precompute`
// would measure it: this process holds the same scene, mesh, receivers and Embree scenes.
void print_memory_estimate(const Scene& scene, const PreparedMesh& mesh, int ranks) {
  const Receivers receivers = make_receivers(scene, mesh);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  const std::vector<Vec3> ray_points = receiver_ray_points(receivers, mesh);
  std::vector<ObjectMesh> objects;
  for (const MovableObject& o : scene.objects) objects.push_back(prepare_object(scene, o));
  const PrecomputePrediction predicted =
      predict_precompute(scene, mesh, receivers, ray_points, objects, traced, 1);
  std::cout << "memory estimate: " << memory_summary(predicted.memory) << "\n";
  if (ranks > 1) {
    const PrecomputeMemory rank =
        predict_precompute_memory(scene, receivers, predicted.gather, predicted.cuts.held(),
                                  predicted.memory.resident, ranks);
    std::cout << "memory estimate: " << memory_summary(rank) << " a rank of " << ranks << "\n";
  }
}

}  // namespace

void add_info_command(CLI::App& app, Action& action) {
  auto scene_file = std::make_shared<std::string>();
  auto ranks = std::make_shared<int>(1);
  CLI::App* cmd = app.add_subcommand(
      "info", "Validate a scene and print its counts and bounds, or summarize an IES/LDT file");
  cmd->add_option("file", *scene_file, "scene JSON file, or a photometric file (.ies, .ldt)")
      ->required();
  cmd->add_option("--ranks", *ranks,
                  "also predict the memory of each of this many ranks of an MPI precompute")
      ->check(CLI::Range(1, 1 << 20));
  cmd->callback([scene_file, ranks, &action] {
    action = [scene_file, ranks] {
      if (is_photometry_file(*scene_file)) {
        std::cout << to_json(summarize_photometry_file(*scene_file)).dump() << "\n";
        return 0;
      }
      const Scene scene = load_scene(*scene_file);
      const std::vector<PlacedLuminaire> luminaires = place_luminaires(scene);  // validates files
      const PreparedMesh mesh = prepare_scene_mesh(scene);
      std::size_t portals = 0;
      for (const Material& m : scene.materials) portals += m.portal ? 1 : 0;
      const Bounds b = scene.bounds();
      char box[256];
      std::snprintf(box, sizeof box, "[%.4g, %.4g, %.4g] .. [%.4g, %.4g, %.4g] m", b.min.x, b.min.y,
                    b.min.z, b.max.x, b.max.y, b.max.z);
      std::cout << "scene: " << scene.file.string() << "\n"
                << "materials: " << scene.materials.size() << " (" << portals << " portal)\n"
                << "triangles: " << scene.geometry.triangles.size() << "\n"
                << "vertices after preparation: " << mesh.positions.size() << " ("
                << mesh.triangles.size() << " triangles, max_edge " << scene.precompute.max_edge
                << " m)\n"
                << "luminaires: " << luminaires.size() << "\n"
                << "sensors: " << scene.sensor_count() << " in " << scene.sensors.size()
                << " sets\n"
                << "cameras: " << scene.cameras.size() << "\n"
                << "portals: " << scene.portals.size() << "\n"
                << "bounds: " << box << "\n";
      const std::vector<PortalGeometry> geometry = portal_geometry(scene, mesh);
      for (std::size_t i = 0; i < scene.portals.size(); ++i) {
        const Portal& p = scene.portals[i];
        const PortalGeometry& g = geometry[i];
        std::cout << "  portal " << p.name << ":";
        for (std::uint32_t m : p.materials) std::cout << " " << scene.materials[m].name;
        char line[256];
        std::snprintf(line, sizeof line, " (%.3g m², %.3g m across, centre [%.4g, %.4g, %.4g])\n",
                      g.area, g.diameter, g.centre.x, g.centre.y, g.centre.z);
        std::cout << line;
      }
      if (!scene.exterior.empty()) {
        std::cout << "exterior objects: " << scene.exterior.size() << "\n";
      }
      for (const MovableObject& o : scene.objects) {
        char line[256];
        std::snprintf(line, sizeof line,
                      "  movable object %s: %zu triangles, pivot [%.4g, %.4g, %.4g]\n",
                      o.name.c_str(), o.geometry.triangles.size(), o.pivot.x, o.pivot.y, o.pivot.z);
        std::cout << line;
      }
      for (const std::string& w : shell_size_warnings(scene, geometry)) {
        std::cerr << "warning: " << w << "\n";
      }
      for (std::size_t i = 0; i < luminaires.size(); ++i) {
        char line[256];
        std::snprintf(line, sizeof line, "  luminaire %s: %.1f lm\n",
                      scene.luminaires[i].name.c_str(),
                      luminaires[i].distribution.flux_lm() * scene.luminaires[i].dimmer);
        std::cout << line;
      }
      print_memory_estimate(scene, mesh, *ranks);
      return 0;
    };
  });
}

}  // namespace relight

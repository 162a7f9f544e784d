// A building model made a relight scene (`relight import`, docs/scene-format.md "Importing a
// model"): the chosen storey's elements and the slab above it as its ceiling; window and door
// glazing as portals, one a window, under the CIE overcast sky; each space a sensor set on its
// floor at the work plane, the border kept free; the site; light fixtures as luminaires where the
// model or --photometry-map gives their photometry, else named in the warnings; furniture static
// or movable. Surfaces take the model's colours, else a default reflectance by element class (and,
// for slabs and unclassed meshes, by the way a face points: floor 0.2, ceiling 0.7, wall 0.5).
// Faces that point out of the space they bound are turned (trace/surface_orientation.h). The
// geometry goes to OBJ files in SCENE.meshes/ beside the scene, every file written atomically.
// Pinned by tests/import/imported_scene_test.cpp and tests/cli/import_command_test.cpp.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "import/building_model.h"

namespace relight {

struct ImportOptions {
  std::optional<std::string> storey;  // a storey's name, or its number from 1 by elevation
  std::vector<std::string> spaces;    // the spaces that get sensors (Name or LongName); all if none
  double work_plane = 0.8;            // m above the floor
  double border = 0.5;                // m kept free along the walls
  double spacing = 0.25;              // m between sensors
  bool furniture_objects = false;     // furniture as movable objects (else static)
  // The receivers' mesh: `precompute.max_edge` of the scene (else the format's default), for
  // a storey too large to precompute at the default density.
  std::optional<double> max_edge;
  // Light fixture type name → photometric file (IES or LDT), from --photometry-map.
  std::map<std::string, std::filesystem::path> photometry;
};

struct ImportSummary {
  int storeys = 0, spaces = 0, windows = 0, doors = 0, portals = 0, luminaires = 0, objects = 0;
  std::size_t triangles = 0;
  std::vector<std::string> warnings;
};

// Default reflectances by element class (no colour in the model).
inline constexpr double kCeilingReflectance = 0.7, kWallReflectance = 0.5, kFloorReflectance = 0.2,
                        kFurnitureReflectance = 0.4;
// The most a model's colour may reflect: no paint reflects more.
inline constexpr double kMostReflectance = 0.9;

// Writes `scene_file` and its meshes. `model_file` names the model in the description and in
// messages. InputError for an option the model cannot meet (no such storey or space), a model
// without geometry, or a photometric file that is missing.
ImportSummary write_imported_scene(const BuildingModel& model, const ImportOptions& options,
                                   const std::filesystem::path& model_file,
                                   const std::filesystem::path& scene_file);

// The summary as the one JSON line `relight import` prints.
std::string summary_json(const ImportSummary& summary);

// Reads a --photometry-map file: a JSON object of type name → IES/LDT path (relative to the map).
std::map<std::string, std::filesystem::path> read_photometry_map(const std::filesystem::path& file);

}  // namespace relight

// An architect's model as `relight import` reads it, whatever its format: elements (an IFC
// product, or a mesh file's material) made of coloured parts, placed in relight's world (metres,
// y up, north −z), with the storeys and the site of an IFC file. ifc_model.h fills it from IFC,
// mesh_model.h from glTF and OBJ; imported_scene.h turns it into a scene.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"
#include "scene/triangle.h"

namespace relight {

// A part of an element with one surface style.
struct ModelPart {
  // The file's colour as a linear diffuse reflectance, if it gives one (an IFC surface colour is a
  // display colour: decoded from sRGB; a glTF base colour is linear already).
  std::optional<Rgb> albedo;
  bool transparent = false;   // an alpha below 1, or a glTF/OBJ material that transmits
  std::string material_name;  // the file's material or style name, "" when none
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;  // counter-clockwise seen from the front, as the file winds them
};

struct ModelElement {
  std::uint32_t id = 0;   // the IFC entity's number; the material's index in a mesh file
  std::string ifc_class;  // upper case ("IFCWALLSTANDARDCASE"); "" for a mesh file's elements
  std::string name, long_name, type_name, predefined_type;
  int storey = -1;           // index into BuildingModel::storeys, −1 when in none
  std::uint32_t parent = 0;  // the aggregate it belongs to (a curtain wall's plates), 0 for none
  bool light_fixture = false;
  // The element's placement: its origin and local axes in the world (a light fixture's aim is
  // its −z axis, its C0 its x axis).
  Vec3 origin{0, 0, 0}, x_axis{1, 0, 0}, z_axis{0, 1, 0};
  std::string photometry;  // a photometric file the model names for a light fixture, "" for none
  std::vector<ModelPart> parts;
};

struct ModelStorey {
  std::uint32_t id = 0;
  std::string name;
  double elevation = 0;  // m
};

struct ModelSite {
  double latitude = 0, longitude = 0, elevation_m = 0;
  double north_deg = 0;  // from the scene's −z clockwise seen from above to true north
};

struct BuildingModel {
  std::string format;  // "IFC4", "IFC2X3", "glTF", "OBJ"
  std::optional<ModelSite> site;
  std::vector<ModelStorey> storeys;  // ascending elevation
  std::vector<ModelElement> elements;
};

// IFC's axes (z up, +y project north) in relight's (y up, −z project north): a rotation, so the
// winding of every triangle is kept.
constexpr Vec3 from_ifc_axes(Vec3 p) {
  return {p.x, p.z, -p.y};
}

}  // namespace relight

// OBJ import. tinyobjloader reads faces, groups and materials, but it repairs or skips what
// it cannot parse (a bad coordinate becomes 0, a two-vertex face disappears, an index past the
// end is kept). A first pass over the lines therefore checks every `v` and `f` statement and
// reports the first problem with its line number, so bad input gets a clear error; it also keeps
// the coordinates in double precision, which tinyobjloader's float build would round.
#include "scene/obj_import.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "common/input_error.h"
#include "common/read_file.h"
#include "scene/mesh_import_polygon.h"

namespace relight {
namespace {

// tinyobjloader stores a face's corner count in an unsigned char.
constexpr std::size_t kMaxFaceCorners = 255;

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// Splits at spaces and tabs, as tinyobjloader does; a word starting with '#' ends the line
// (a trailing comment, which tinyobjloader ignores too).
std::vector<std::string_view> split_blanks(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i < line.size() && line[i] == '#') break;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

bool parse_long(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

std::string quoted(std::string_view s) {
  std::string text(1, '\'');
  text.append(s);
  text.push_back('\'');
  return text;
}

// What the validating pass learns: the positions in double precision and the number of faces.
struct ObjScan {
  std::vector<Vec3> positions;
  std::size_t face_count = 0;
};

struct ForwardReference {
  int line = 0;
  long long index = 0;
};

// Lines end at "\n", "\r\n" or a lone "\r", like tinyobjloader's reader.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
    line = text_.substr(start, pos_ - start);
    if (pos_ < text_.size()) {
      if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
      ++pos_;
    }
    ++number_;
    return true;
  }
  int number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int number_ = 0;
};

void check_vertex(const std::filesystem::path& file, int line,
                  const std::vector<std::string_view>& args, ObjScan& scan) {
  if (args.size() < 3) {
    fail_input(at_line(file, line),
               "vertex needs x, y and z, got " + std::to_string(args.size()) + " value(s)");
  }
  std::array<double, 3> xyz{};
  for (std::size_t i = 0; i < args.size(); ++i) {
    double value = 0;
    if (!parse_double(args[i], value)) {
      fail_input(at_line(file, line), "vertex coordinate " + quoted(args[i]) + " is not a number");
    }
    if (i < 3) {
      if (!std::isfinite(value)) {
        fail_input(at_line(file, line), "vertex coordinate " + quoted(args[i]) + " is not finite");
      }
      if (std::abs(value) > std::numeric_limits<float>::max()) {
        fail_input(at_line(file, line),
                   "vertex coordinate " + quoted(args[i]) + " is out of range");
      }
      xyz[i] = value;
    }
  }
  scan.positions.push_back({xyz[0], xyz[1], xyz[2]});
}

void check_face(const std::filesystem::path& file, int line,
                const std::vector<std::string_view>& args, ObjScan& scan,
                std::vector<ForwardReference>& forward) {
  if (args.size() < 3) {
    fail_input(at_line(file, line),
               "face has " + std::to_string(args.size()) + " vertices, needs at least 3");
  }
  if (args.size() > kMaxFaceCorners) {
    fail_input(at_line(file, line), "face has " + std::to_string(args.size()) +
                                        " vertices, at most " + std::to_string(kMaxFaceCorners) +
                                        " are supported");
  }
  const auto known = static_cast<long long>(scan.positions.size());
  long long largest = 0;
  for (const std::string_view corner : args) {
    // v, v/vt, v/vt/vn or v//vn
    std::size_t start = 0;
    for (int part = 0; start <= corner.size() && part < 3; ++part) {
      const std::size_t slash = corner.find('/', start);
      const std::size_t end = slash == std::string_view::npos ? corner.size() : slash;
      const std::string_view text = corner.substr(start, end - start);
      long long index = 0;
      const bool optional = part > 0 && text.empty();
      if (!optional && (!parse_long(text, index) || index == 0)) {
        fail_input(at_line(file, line), "bad face index " + quoted(corner));
      }
      if (part == 0) {
        if (index < 0 && known + index < 0) {
          fail_input(at_line(file, line), "face index " + std::to_string(index) +
                                              " reaches before the first vertex (" +
                                              std::to_string(known) + " defined so far)");
        }
        largest = std::max(largest, index);
      }
      if (slash == std::string_view::npos) break;
      if (part == 2) fail_input(at_line(file, line), "bad face index " + quoted(corner));
      start = slash + 1;
    }
  }
  // Positive indices may point at vertices defined further down the file.
  if (largest > known) forward.push_back({line, largest});
  ++scan.face_count;
}

ObjScan scan_obj(const std::filesystem::path& file, std::string_view text) {
  ObjScan scan;
  std::vector<ForwardReference> forward;
  LineCursor cursor(text);
  std::string_view line;
  while (cursor.next(line)) {
    std::size_t start = 0;
    while (start < line.size() && is_blank(line[start])) ++start;
    line.remove_prefix(start);
    if (line.empty() || line.front() == '#') continue;
    std::vector<std::string_view> tokens = split_blanks(line);
    const std::string_view keyword = tokens.front();
    tokens.erase(tokens.begin());
    if (keyword == "v") {
      check_vertex(file, cursor.number(), tokens, scan);
    } else if (keyword == "f") {
      check_face(file, cursor.number(), tokens, scan, forward);
    }
  }
  const auto total = static_cast<long long>(scan.positions.size());
  for (const ForwardReference& ref : forward) {
    if (ref.index > total) {
      fail_input(at_line(file, ref.line), "face index " + std::to_string(ref.index) +
                                              " is out of range (" + std::to_string(total) +
                                              " vertices in the file)");
    }
  }
  if (scan.face_count == 0) fail_input(file.string(), "no faces, so no triangles to import");
  return scan;
}

// Reads .mtl files relative to the .obj's folder (tinyobjloader's own reader splits its search
// path at ':', which breaks on such folder names). A missing file is a warning.
class MtlFileReader : public tinyobj::MaterialReader {
 public:
  explicit MtlFileReader(std::filesystem::path folder) : folder_(std::move(folder)) {}
  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* warning,
                  std::string* error) override {
    std::ifstream in(folder_ / name);
    if (!in) {
      if (warning) *warning += "material file '" + name + "' not found\n";
      return false;
    }
    tinyobj::LoadMtl(names, materials, &in, warning, error);
    return true;
  }

 private:
  std::filesystem::path folder_;
};

}  // namespace

ImportedMesh import_obj(const std::filesystem::path& file) {
  const std::string text = read_file(file);
  ObjScan scan = scan_obj(file, text);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> obj_materials;
  std::string warning, error;
  std::istringstream stream(text);
  MtlFileReader mtl_reader(file.parent_path());
  const bool ok = tinyobj::LoadObj(&attrib, &shapes, &obj_materials, &warning, &error, &stream,
                                   &mtl_reader, /*triangulate=*/false,
                                   /*default_vcols_fallback=*/false);
  if (!ok) fail_input(file.string(), "cannot parse OBJ: " + error);
  if (attrib.vertices.size() != 3 * scan.positions.size()) {
    fail_input(file.string(), "cannot parse OBJ: vertex count differs between readers");
  }

  ImportedMesh mesh;
  mesh.positions = std::move(scan.positions);
  const auto vertex_count = static_cast<int>(mesh.positions.size());

  // tinyobjloader material id (-1 = none or unknown) -> index into mesh.materials.
  std::unordered_map<int, std::uint32_t> material_slot;
  const auto slot_of = [&](int id) {
    if (id < 0 || id >= static_cast<int>(obj_materials.size())) id = -1;
    const auto [it, inserted] =
        material_slot.try_emplace(id, static_cast<std::uint32_t>(mesh.materials.size()));
    if (inserted) {
      if (id < 0) {
        mesh.materials.push_back({kDefaultImportMaterialName, kDefaultImportAlbedo});
      } else {
        const tinyobj::material_t& m = obj_materials[static_cast<std::size_t>(id)];
        ImportedMaterial imported{m.name, Rgb{m.diffuse[0], m.diffuse[1], m.diffuse[2]}};
        // tinyobjloader reads `Tr` as 1 − dissolve into the same field.
        imported.transparent = m.dissolve < 1;
        mesh.materials.push_back(imported);
      }
    }
    return it->second;
  };

  std::vector<std::uint32_t> corners;
  for (const tinyobj::shape_t& shape : shapes) {
    std::size_t offset = 0;
    for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      const std::size_t count = shape.mesh.num_face_vertices[face];
      if (offset + count > shape.mesh.indices.size()) {
        fail_input(file.string(), "cannot parse OBJ: face list is inconsistent");
      }
      corners.clear();
      for (std::size_t k = 0; k < count; ++k) {
        const int index = shape.mesh.indices[offset + k].vertex_index;
        if (index < 0 || index >= vertex_count) {
          fail_input(file.string(), "face index out of range in shape '" + shape.name + "'");
        }
        corners.push_back(static_cast<std::uint32_t>(index));
      }
      offset += count;
      const int material_id =
          face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
      const std::uint32_t slot = slot_of(material_id);
      const std::size_t before = mesh.triangles.size();
      triangulate_polygon(corners, mesh.positions, mesh.triangles);
      mesh.triangle_material.insert(mesh.triangle_material.end(), mesh.triangles.size() - before,
                                    slot);
    }
  }
  if (mesh.triangles.empty()) fail_input(file.string(), "no faces, so no triangles to import");
  return mesh;
}

}  // namespace relight

// PLY import. The header is text and fully validated, with "FILE:LINE" in errors; the body is
// read element by element in header order, skipping what we do not use, with "FILE:LINE"
// errors for ascii bodies and "FILE" errors for binary ones. Every count is checked against
// the bytes left before anything is allocated, so a truncated or lying file cannot crash us.
#include "scene/ply_import.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "common/input_error.h"
#include "common/read_file.h"
#include "math/srgb.h"
#include "scene/mesh_import_bytes.h"
#include "scene/mesh_import_polygon.h"

namespace relight {
namespace {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };
enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

std::optional<PlyType> parse_type(std::string_view name) {
  if (name == "char" || name == "int8") return PlyType::kInt8;
  if (name == "uchar" || name == "uint8") return PlyType::kUint8;
  if (name == "short" || name == "int16") return PlyType::kInt16;
  if (name == "ushort" || name == "uint16") return PlyType::kUint16;
  if (name == "int" || name == "int32") return PlyType::kInt32;
  if (name == "uint" || name == "uint32") return PlyType::kUint32;
  if (name == "float" || name == "float32") return PlyType::kFloat32;
  if (name == "double" || name == "float64") return PlyType::kFloat64;
  return std::nullopt;
}

std::size_t size_of(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 0;
}

bool is_integer(PlyType type) {
  return type != PlyType::kFloat32 && type != PlyType::kFloat64;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;  // of the value, or of each list item
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;  // first byte after "end_header\n"
  int body_line = 0;            // line number of the first body line (ascii)
};

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

PlyHeader parse_header(const std::filesystem::path& file, std::string_view data) {
  PlyHeader header;
  std::size_t pos = 0;
  int line_number = 0;
  bool have_format = false;
  while (true) {
    if (pos >= data.size()) {
      fail_input(at_line(file, std::max(line_number, 1)), "header has no end_header line");
    }
    const std::size_t end = data.find('\n', pos);
    const std::size_t line_end = end == std::string_view::npos ? data.size() : end;
    const std::string_view line = data.substr(pos, line_end - pos);
    pos = end == std::string_view::npos ? data.size() : end + 1;
    ++line_number;
    const std::string where = at_line(file, line_number);
    const std::vector<std::string_view> words = split_words(line);
    if (line_number == 1) {
      if (words.size() != 1 || words[0] != "ply") fail_input(where, "not a PLY file (no 'ply')");
      continue;
    }
    if (words.empty()) continue;
    const std::string_view keyword = words[0];
    if (keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (!have_format) fail_input(where, "header has no format line");
      header.body_offset = pos;
      header.body_line = line_number + 1;
      return header;
    }
    if (keyword == "format") {
      if (words.size() != 3) fail_input(where, "format line needs a format and a version");
      if (words[1] == "ascii") {
        header.format = PlyFormat::kAscii;
      } else if (words[1] == "binary_little_endian") {
        header.format = PlyFormat::kBinaryLittleEndian;
      } else if (words[1] == "binary_big_endian") {
        header.format = PlyFormat::kBinaryBigEndian;
      } else {
        fail_input(where, "unknown format '" + std::string(words[1]) + "'");
      }
      if (words[2] != "1.0") {
        fail_input(where, "unsupported version '" + std::string(words[2]) + "'");
      }
      have_format = true;
    } else if (keyword == "element") {
      if (words.size() != 3) fail_input(where, "element line needs a name and a count");
      std::uint64_t count = 0;
      const std::string_view text = words[2];
      const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), count);
      if (ec != std::errc() || ptr != text.data() + text.size()) {
        fail_input(where, "bad element count '" + std::string(text) + "'");
      }
      header.elements.push_back({std::string(words[1]), count, {}, line_number});
    } else if (keyword == "property") {
      if (header.elements.empty()) fail_input(where, "property before any element");
      PlyProperty property;
      if (words.size() >= 2 && words[1] == "list") {
        if (words.size() != 5) fail_input(where, "list property needs count type, item type, name");
        const auto count_type = parse_type(words[2]);
        const auto item_type = parse_type(words[3]);
        if (!count_type || !is_integer(*count_type)) {
          fail_input(where, "bad list count type '" + std::string(words[2]) + "'");
        }
        if (!item_type) fail_input(where, "unknown type '" + std::string(words[3]) + "'");
        property = {std::string(words[4]), *item_type, true, *count_type};
      } else {
        if (words.size() != 3) fail_input(where, "property line needs a type and a name");
        const auto type = parse_type(words[1]);
        if (!type) fail_input(where, "unknown type '" + std::string(words[1]) + "'");
        property = {std::string(words[2]), *type, false, PlyType::kUint8};
      }
      header.elements.back().properties.push_back(property);
    } else {
      fail_input(where, "unknown header keyword '" + std::string(keyword) + "'");
    }
  }
}

// Where the body reader is, for error messages; updated as the body is walked, formatted
// only when something fails.
struct BodyLocation {
  const PlyElement* element = nullptr;
  std::uint64_t instance = 0;
  const PlyProperty* property = nullptr;

  std::string describe() const {
    if (!element) return "body";
    std::string text = "element '" + element->name + "' " + std::to_string(instance) + " of " +
                       std::to_string(element->count);
    if (property) text += ", property '" + property->name + "'";
    return text;
  }
};

bool fits(double value, PlyType type) {
  switch (type) {
    case PlyType::kInt8:
      return value >= -128 && value <= 127;
    case PlyType::kUint8:
      return value >= 0 && value <= 255;
    case PlyType::kInt16:
      return value >= -32768 && value <= 32767;
    case PlyType::kUint16:
      return value >= 0 && value <= 65535;
    case PlyType::kInt32:
      return value >= -2147483648.0 && value <= 2147483647.0;
    case PlyType::kUint32:
      return value >= 0 && value <= 4294967295.0;
    case PlyType::kFloat32:
    case PlyType::kFloat64:
      return true;
  }
  return false;
}

// Reads scalars from the body, one value at a time, in the file's encoding.
class BodyReader {
 public:
  BodyReader(const std::filesystem::path& file, std::string_view body, PlyFormat format,
             int first_line)
      : file_(file), body_(body), format_(format), line_(first_line) {}

  BodyLocation at;

  bool ascii() const { return format_ == PlyFormat::kAscii; }
  std::size_t bytes_left() const { return body_.size() - pos_; }

  // "FILE:LINE: reason, in LOCATION" for ascii, "FILE: reason, in LOCATION" for binary.
  [[noreturn]] void fail(const std::string& reason) const {
    fail_input(ascii() ? at_line(file_, line_) : file_.string(), reason + ", in " + at.describe());
  }

  double read(PlyType type) { return ascii() ? read_text(type) : read_binary(type); }

  void skip(PlyType type, std::uint64_t count) {
    if (ascii()) {
      for (std::uint64_t i = 0; i < count; ++i) read_text(type);
      return;
    }
    const std::size_t size = size_of(type);
    if (count > bytes_left() / size) fail("unexpected end of data");
    pos_ += static_cast<std::size_t>(count) * size;
  }

 private:
  double read_binary(PlyType type) {
    const std::size_t size = size_of(type);
    if (bytes_left() < size) fail("unexpected end of data");
    const auto* p = reinterpret_cast<const unsigned char*>(body_.data() + pos_);
    pos_ += size;
    const bool little = format_ == PlyFormat::kBinaryLittleEndian;
    switch (type) {
      case PlyType::kInt8:
        return static_cast<std::int8_t>(*p);
      case PlyType::kUint8:
        return *p;
      case PlyType::kInt16:
        return load_scalar<std::int16_t>(p, little);
      case PlyType::kUint16:
        return load_scalar<std::uint16_t>(p, little);
      case PlyType::kInt32:
        return load_scalar<std::int32_t>(p, little);
      case PlyType::kUint32:
        return load_scalar<std::uint32_t>(p, little);
      case PlyType::kFloat32:
        return load_scalar<float>(p, little);
      case PlyType::kFloat64:
        return load_scalar<double>(p, little);
    }
    return 0;
  }

  double read_text(PlyType type) {
    // Skip blanks, counting lines.
    while (pos_ < body_.size()) {
      const char c = body_[pos_];
      if (c == '\n') {
        ++line_;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        break;
      }
      ++pos_;
    }
    if (pos_ >= body_.size()) fail("unexpected end of file");
    const std::size_t start = pos_;
    while (pos_ < body_.size() && body_[pos_] != ' ' && body_[pos_] != '\t' &&
           body_[pos_] != '\r' && body_[pos_] != '\n') {
      ++pos_;
    }
    std::string_view token = body_.substr(start, pos_ - start);
    const std::string_view shown = token;
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    double value = 0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || ptr != token.data() + token.size()) {
      fail("'" + std::string(shown) + "' is not a number");
    }
    if (is_integer(type) && (!std::isfinite(value) || value != std::floor(value))) {
      fail("'" + std::string(shown) + "' is not an integer");
    }
    if (!fits(value, type)) fail("'" + std::string(shown) + "' is out of range for its type");
    return value;
  }

  const std::filesystem::path& file_;
  std::string_view body_;
  PlyFormat format_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

// Which property of an element feeds which value we keep. Only the first element named
// "vertex" and the first named "face" feed anything; later ones of the same name are read past
// (make fuzz found a second face element adding faces without colours:
// PlyImport.OnlyTheFirstVertexAndFaceElementsAreRead).
enum class Role { kSkip, kX, kY, kZ, kFaceIndices, kRed, kGreen, kBlue };

Role role_of(const PlyProperty& property, bool is_vertex, bool is_face, bool face_colours) {
  if (is_vertex && !property.is_list) {
    if (property.name == "x") return Role::kX;
    if (property.name == "y") return Role::kY;
    if (property.name == "z") return Role::kZ;
  }
  if (is_face) {
    if (property.is_list &&
        (property.name == "vertex_indices" || property.name == "vertex_index")) {
      return Role::kFaceIndices;
    }
    if (face_colours && property.name == "red") return Role::kRed;
    if (face_colours && property.name == "green") return Role::kGreen;
    if (face_colours && property.name == "blue") return Role::kBlue;
  }
  return Role::kSkip;
}

const PlyProperty* find_property(const PlyElement& element, std::string_view name) {
  for (const PlyProperty& p : element.properties) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

// Smallest number of bytes one instance of `element` takes in a binary body.
std::size_t min_binary_size(const PlyElement& element) {
  std::size_t size = 0;
  for (const PlyProperty& p : element.properties) {
    size += p.is_list ? size_of(p.count_type) : size_of(p.type);
  }
  return size;
}

}  // namespace

ImportedMesh import_ply(const std::filesystem::path& file) {
  const std::string data = read_file(file);
  const PlyHeader header = parse_header(file, data);

  const PlyElement* vertex_element = nullptr;
  const PlyElement* face_element = nullptr;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex" && !vertex_element) vertex_element = &element;
    if (element.name == "face" && !face_element) face_element = &element;
  }
  if (!vertex_element) fail_input(file.string(), "no vertex element");
  for (const char* axis : {"x", "y", "z"}) {
    const PlyProperty* p = find_property(*vertex_element, axis);
    if (!p || p->is_list) {
      fail_input(at_line(file, vertex_element->line),
                 std::string("vertex element has no scalar property ") + axis);
    }
  }
  if (!face_element) fail_input(file.string(), "no face element (point clouds are not meshes)");
  if (!find_property(*face_element, "vertex_indices") &&
      !find_property(*face_element, "vertex_index")) {
    fail_input(at_line(file, face_element->line),
               "face element has no list property vertex_indices");
  }
  bool face_colours = true;
  for (const char* channel : {"red", "green", "blue"}) {
    const PlyProperty* p = find_property(*face_element, channel);
    face_colours = face_colours && p && !p->is_list && p->type == PlyType::kUint8;
  }
  if (vertex_element->count > std::numeric_limits<std::uint32_t>::max()) {
    fail_input(at_line(file, vertex_element->line), "too many vertices");
  }

  BodyReader reader(file, std::string_view(data).substr(header.body_offset), header.format,
                    header.body_line);
  ImportedMesh mesh;
  std::vector<std::uint32_t> corners;        // all faces' corners, concatenated
  std::vector<std::uint32_t> corner_counts;  // per face
  std::vector<std::uint32_t> face_colour;    // per face, 0xRRGGBB

  for (const PlyElement& element : header.elements) {
    reader.at = {&element, 0, nullptr};
    if (!reader.ascii() && element.count > 0) {
      const std::size_t min_size = min_binary_size(element);
      if (min_size > 0 && element.count > reader.bytes_left() / min_size) {
        reader.fail("unexpected end of data: " + std::to_string(element.count) +
                    " instances need at least " + std::to_string(min_size) + " bytes each");
      }
    }
    // An element without properties has nothing to read however many instances it declares
    // (make fuzz found 2·10¹⁸ of them spinning here; PlyImport.AnElementWithoutProperties...).
    if (element.properties.empty()) continue;
    const bool is_vertex = &element == vertex_element;
    const bool is_face = &element == face_element;
    if (is_vertex) {
      // An ascii value takes at least two bytes, so a lying count cannot over-allocate.
      const std::uint64_t room = reader.ascii() ? reader.bytes_left() / 2 : element.count;
      mesh.positions.reserve(static_cast<std::size_t>(std::min(element.count, room)));
    }
    std::vector<Role> roles;
    for (const PlyProperty& p : element.properties) {
      roles.push_back(role_of(p, is_vertex, is_face, face_colours));
    }

    for (std::uint64_t i = 0; i < element.count; ++i) {
      reader.at.instance = i;
      Vec3 position;
      std::uint32_t colour = 0;
      bool have_indices = false;
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& property = element.properties[k];
        reader.at.property = &property;
        if (!property.is_list) {
          const double value = reader.read(property.type);
          switch (roles[k]) {
            case Role::kX:
              position.x = value;
              break;
            case Role::kY:
              position.y = value;
              break;
            case Role::kZ:
              position.z = value;
              break;
            case Role::kRed:
              colour |= static_cast<std::uint32_t>(value) << 16;
              break;
            case Role::kGreen:
              colour |= static_cast<std::uint32_t>(value) << 8;
              break;
            case Role::kBlue:
              colour |= static_cast<std::uint32_t>(value);
              break;
            default:
              break;
          }
          continue;
        }
        const double count_value = reader.read(property.count_type);
        if (count_value < 0) reader.fail("negative list length");
        const auto count = static_cast<std::uint64_t>(count_value);
        if (roles[k] != Role::kFaceIndices || have_indices) {
          reader.skip(property.type, count);
          continue;
        }
        have_indices = true;
        if (!is_integer(property.type)) reader.fail("face indices must be integers");
        if (count < 3) {
          reader.fail("face has " + std::to_string(count) + " vertices, needs at least 3");
        }
        if (!reader.ascii() && count > reader.bytes_left() / size_of(property.type)) {
          reader.fail("unexpected end of data");
        }
        for (std::uint64_t c = 0; c < count; ++c) {
          const double index = reader.read(property.type);
          if (index < 0 || index >= static_cast<double>(vertex_element->count)) {
            reader.fail("vertex index " + std::to_string(static_cast<long long>(index)) +
                        " is out of range (" + std::to_string(vertex_element->count) +
                        " vertices)");
          }
          corners.push_back(static_cast<std::uint32_t>(index));
        }
        corner_counts.push_back(static_cast<std::uint32_t>(count));
      }
      reader.at.property = nullptr;
      if (is_vertex) {
        if (!is_finite(position)) reader.fail("vertex coordinate is not finite");
        mesh.positions.push_back(position);
      }
      if (is_face) face_colour.push_back(colour);
    }
  }
  if (corner_counts.empty()) fail_input(file.string(), "no faces, so no triangles to import");

  std::map<std::uint32_t, std::uint32_t> colour_slot;  // 0xRRGGBB -> material
  const auto slot_of = [&](std::uint32_t colour) {
    if (!face_colours) colour = 0;
    const auto [it, inserted] =
        colour_slot.try_emplace(colour, static_cast<std::uint32_t>(mesh.materials.size()));
    if (inserted) {
      if (!face_colours) {
        mesh.materials.push_back({kDefaultImportMaterialName, kDefaultImportAlbedo});
      } else {
        const std::uint32_t r = colour >> 16, g = (colour >> 8) & 0xff, b = colour & 0xff;
        mesh.materials.push_back(
            {"rgb(" + std::to_string(r) + "," + std::to_string(g) + "," + std::to_string(b) + ")",
             Rgb{srgb_decode(r / 255.0), srgb_decode(g / 255.0), srgb_decode(b / 255.0)}});
      }
    }
    return it->second;
  };

  std::size_t offset = 0;
  for (std::size_t face = 0; face < corner_counts.size(); ++face) {
    const std::span<const std::uint32_t> polygon(corners.data() + offset, corner_counts[face]);
    offset += corner_counts[face];
    const std::uint32_t slot = slot_of(face_colour[face]);
    const std::size_t before = mesh.triangles.size();
    triangulate_polygon(polygon, mesh.positions, mesh.triangles);
    mesh.triangle_material.insert(mesh.triangle_material.end(), mesh.triangles.size() - before,
                                  slot);
  }
  return mesh;
}

}  // namespace relight

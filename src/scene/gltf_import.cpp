// glTF 2.0 import. tinygltf parses JSON and buffers but leaves indices and byte ranges
// unchecked, so every index and every accessor range is validated here before it is read:
// a broken file gives InputError "FILE: reason", never an out-of-bounds read. Images are
// kept encoded as tinygltf hands them over (data URI, GLB buffer view or file beside the
// .gltf) and decoded only when a material's base colour texture uses them (image/photo.h:
// PNG and JPEG, glTF 2.0 §3.9.2's two formats); the texture then rides on the triangles
// (scene/surface_texture.h).
#include "scene/gltf_import.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <unordered_map>

#include <tiny_gltf.h>

#include "common/input_error.h"
#include "image/photo.h"
#include "scene/mesh_import_bytes.h"

namespace relight {
namespace {

// Row-major 3x4 affine transform.
struct Affine {
  std::array<std::array<double, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};
};

// KHR_materials_transmission's transmissionFactor (0 without the extension or the key).
double transmission_factor(const tinygltf::Material& m) {
  const auto extension = m.extensions.find("KHR_materials_transmission");
  if (extension == m.extensions.end() || !extension->second.IsObject()) return 0;
  const tinygltf::Value& factor = extension->second.Get("transmissionFactor");
  return factor.IsNumber() ? factor.GetNumberAsDouble() : 0;
}

Affine operator*(const Affine& a, const Affine& b) {
  Affine r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j] +
                  (j == 3 ? a.m[i][3] : 0.0);
    }
  }
  return r;
}

Vec3 apply(const Affine& a, Vec3 p) {
  return {a.m[0][0] * p.x + a.m[0][1] * p.y + a.m[0][2] * p.z + a.m[0][3],
          a.m[1][0] * p.x + a.m[1][1] * p.y + a.m[1][2] * p.z + a.m[1][3],
          a.m[2][0] * p.x + a.m[2][1] * p.y + a.m[2][2] * p.z + a.m[2][3]};
}

double determinant(const Affine& a) {
  const auto& m = a.m;
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The images' encoded bytes by image index, as tinygltf's loader callback hands them over.
using EncodedImages = std::unordered_map<int, std::vector<std::uint8_t>>;

class GltfReader {
 public:
  GltfReader(const std::filesystem::path& file, const tinygltf::Model& model,
             const EncodedImages& images)
      : file_(file), model_(model), images_(images) {}

  ImportedMesh read() {
    check_extensions();
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const int scene = model_.defaultScene >= 0 ? model_.defaultScene : 0;
      if (scene >= static_cast<int>(model_.scenes.size())) {
        fail("default scene " + std::to_string(scene) + " does not exist");
      }
      roots = model_.scenes[static_cast<std::size_t>(scene)].nodes;
    } else {
      roots = root_nodes();
    }
    visited_.assign(model_.nodes.size(), false);
    for (const int root : roots) walk(root, Affine{});
    if (mesh_.triangles.empty()) fail("no triangles in the scene");
    return std::move(mesh_);
  }

 private:
  struct MaterialTexture {
    std::int32_t slot = -1;  // into mesh_.textures.textures
    int set = 0;             // TEXCOORD_<set>
    // UV' = [m0 m1 m2; m3 m4 m5] · (u, v, 1): KHR_texture_transform, the identity without it.
    std::array<double, 6> transform{1, 0, 0, 0, 1, 0};
  };

  [[noreturn]] void fail(const std::string& reason) const { fail_input(file_.string(), reason); }

  void check_extensions() const {
    for (const std::string& name : model_.extensionsRequired) {
      const bool harmless = name.rfind("KHR_materials_", 0) == 0 ||
                            name.rfind("KHR_texture_", 0) == 0 ||
                            name.rfind("EXT_texture_", 0) == 0 || name == "KHR_lights_punctual";
      if (!harmless) fail("requires unsupported extension " + name);
    }
  }

  std::vector<int> root_nodes() const {
    std::vector<bool> is_child(model_.nodes.size(), false);
    for (const tinygltf::Node& node : model_.nodes) {
      for (const int child : node.children) {
        if (child >= 0 && child < static_cast<int>(is_child.size())) {
          is_child[static_cast<std::size_t>(child)] = true;
        }
      }
    }
    std::vector<int> roots;
    for (std::size_t i = 0; i < is_child.size(); ++i) {
      if (!is_child[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
  }

  Affine local_transform(const tinygltf::Node& node, int index) const {
    const std::string where = "node " + std::to_string(index);
    Affine t;
    if (!node.matrix.empty()) {
      if (node.matrix.size() != 16) fail(where + ": matrix needs 16 numbers");
      for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 4; ++col) {
          t.m[row][col] = node.matrix[static_cast<std::size_t>(col) * 4 +
                                      static_cast<std::size_t>(row)];  // column-major
        }
      }
    } else {
      Vec3 translation{0, 0, 0}, scale{1, 1, 1};
      std::array<double, 4> q{0, 0, 0, 1};  // x, y, z, w
      if (!node.translation.empty()) {
        if (node.translation.size() != 3) fail(where + ": translation needs 3 numbers");
        translation = {node.translation[0], node.translation[1], node.translation[2]};
      }
      if (!node.scale.empty()) {
        if (node.scale.size() != 3) fail(where + ": scale needs 3 numbers");
        scale = {node.scale[0], node.scale[1], node.scale[2]};
      }
      if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) fail(where + ": rotation needs 4 numbers");
        const double norm =
            std::sqrt(node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                      node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3]);
        if (!(norm > 0) || !std::isfinite(norm)) fail(where + ": rotation is not a quaternion");
        for (int i = 0; i < 4; ++i) q[static_cast<std::size_t>(i)] = node.rotation[i] / norm;
      }
      const double x = q[0], y = q[1], z = q[2], w = q[3];
      const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                              {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                              {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
      for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) t.m[row][col] = r[row][col] * scale[col];
        t.m[row][3] = translation[row];
      }
    }
    for (const auto& row : t.m) {
      for (const double v : row) {
        if (!std::isfinite(v)) fail(where + ": transform is not finite");
      }
    }
    return t;
  }

  void walk(int index, const Affine& parent) {
    if (index < 0 || index >= static_cast<int>(model_.nodes.size())) {
      fail("node " + std::to_string(index) + " does not exist");
    }
    if (visited_[static_cast<std::size_t>(index)]) {
      fail("node " + std::to_string(index) + " has more than one parent or is its own ancestor");
    }
    visited_[static_cast<std::size_t>(index)] = true;
    const tinygltf::Node& node = model_.nodes[static_cast<std::size_t>(index)];
    const Affine world = parent * local_transform(node, index);
    if (node.mesh >= 0) {
      if (node.mesh >= static_cast<int>(model_.meshes.size())) {
        fail("node " + std::to_string(index) + " uses mesh " + std::to_string(node.mesh) +
             ", which does not exist");
      }
      add_mesh(model_.meshes[static_cast<std::size_t>(node.mesh)], node.mesh, world);
    }
    for (const int child : node.children) walk(child, world);
  }

  // Bytes of accessor `index` with their stride, after checking they lie inside the buffer.
  struct AccessorView {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int component_type = 0;
  };

  AccessorView view(int index, const std::string& what) const {
    if (index < 0 || index >= static_cast<int>(model_.accessors.size())) {
      fail(what + ": accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(index)];
    const std::string where = what + " (accessor " + std::to_string(index) + ")";
    if (accessor.sparse.isSparse) fail(where + ": sparse accessors are not supported");
    const int component_size =
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
    const int components =
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
    if (component_size <= 0 || components <= 0) fail(where + ": bad component type or type");
    AccessorView result;
    result.count = accessor.count;
    result.component_type = accessor.componentType;
    // Without a bufferView an accessor is all zeros (or sparse): no usable geometry.
    if (accessor.bufferView < 0) fail(where + ": has no bufferView");
    if (accessor.bufferView >= static_cast<int>(model_.bufferViews.size())) {
      fail(where + ": bufferView " + std::to_string(accessor.bufferView) + " does not exist");
    }
    const tinygltf::BufferView& buffer_view =
        model_.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (buffer_view.buffer < 0 || buffer_view.buffer >= static_cast<int>(model_.buffers.size())) {
      fail(where + ": buffer " + std::to_string(buffer_view.buffer) + " does not exist");
    }
    const tinygltf::Buffer& buffer = model_.buffers[static_cast<std::size_t>(buffer_view.buffer)];
    const int stride = accessor.ByteStride(buffer_view);
    if (stride <= 0) fail(where + ": bad byteStride");
    const std::size_t element =
        static_cast<std::size_t>(component_size) * static_cast<std::size_t>(components);
    if (buffer_view.byteOffset > buffer.data.size() ||
        buffer_view.byteLength > buffer.data.size() - buffer_view.byteOffset) {
      fail(where + ": bufferView reaches past the end of its buffer");
    }
    const std::size_t offset = accessor.byteOffset;
    if (offset > buffer_view.byteLength) fail(where + ": byteOffset is past its bufferView");
    const std::size_t room = buffer_view.byteLength - offset;
    if (result.count > 0) {
      const std::size_t last = result.count - 1;
      const bool fits = last <= room / static_cast<std::size_t>(stride) &&
                        last * static_cast<std::size_t>(stride) + element <= room;
      if (!fits) fail(where + ": accessor reaches past the end of its bufferView");
    }
    result.data = buffer.data.data() + buffer_view.byteOffset + offset;
    result.stride = static_cast<std::size_t>(stride);
    return result;
  }

  std::vector<Vec3> read_positions(int index, const Affine& world, const std::string& what) const {
    const tinygltf::Accessor* accessor =
        index >= 0 && index < static_cast<int>(model_.accessors.size())
            ? &model_.accessors[static_cast<std::size_t>(index)]
            : nullptr;
    if (accessor && (accessor->componentType != TINYGLTF_COMPONENT_TYPE_FLOAT ||
                     accessor->type != TINYGLTF_TYPE_VEC3)) {
      fail(what + ": POSITION must be a float VEC3 accessor");
    }
    const AccessorView v = view(index, what + " POSITION");
    std::vector<Vec3> positions(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
      const unsigned char* p = v.data + i * v.stride;
      const Vec3 local{load_scalar<float>(p, true), load_scalar<float>(p + 4, true),
                       load_scalar<float>(p + 8, true)};
      if (!is_finite(local)) fail(what + ": POSITION " + std::to_string(i) + " is not finite");
      positions[i] = local;
    }
    for (Vec3& p : positions) p = apply(world, p);
    return positions;
  }

  std::vector<std::uint32_t> read_indices(int index, std::size_t vertex_count,
                                          const std::string& what) const {
    const tinygltf::Accessor& accessor = model_.accessors.at(static_cast<std::size_t>(index));
    if (accessor.type != TINYGLTF_TYPE_SCALAR) fail(what + ": indices must be SCALAR");
    const AccessorView v = view(index, what + " indices");
    std::vector<std::uint32_t> indices(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
      const unsigned char* p = v.data + i * v.stride;
      std::uint32_t value = 0;
      switch (v.component_type) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          value = *p;
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
          value = load_scalar<std::uint16_t>(p, true);
          break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
          value = load_scalar<std::uint32_t>(p, true);
          break;
        default:
          fail(what + ": indices must be unsigned byte, short or int");
      }
      if (value >= vertex_count) {
        fail(what + ": index " + std::to_string(value) + " is out of range (" +
             std::to_string(vertex_count) + " vertices)");
      }
      indices[i] = value;
    }
    return indices;
  }

  TextureWrap wrap_mode(int mode, const std::string& where) const {
    switch (mode) {
      case TINYGLTF_TEXTURE_WRAP_REPEAT:
        return TextureWrap::kRepeat;
      case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return TextureWrap::kClampToEdge;
      case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return TextureWrap::kMirroredRepeat;
      default:
        fail(where + ": unknown wrap mode " + std::to_string(mode));
    }
  }

  // The index into mesh_.textures.textures of glTF texture `index`, decoded on first use.
  std::int32_t texture_slot(int index, const std::string& where) {
    if (index < 0 || index >= static_cast<int>(model_.textures.size())) {
      fail(where + ": texture " + std::to_string(index) + " does not exist");
    }
    if (const auto it = texture_slots_.find(index); it != texture_slots_.end()) return it->second;
    const tinygltf::Texture& texture = model_.textures[static_cast<std::size_t>(index)];
    const std::string what = "texture " + std::to_string(index);
    if (texture.source < 0 || texture.source >= static_cast<int>(model_.images.size())) {
      fail(what + ": image " + std::to_string(texture.source) + " does not exist");
    }
    TextureWrap wrap_u = TextureWrap::kRepeat, wrap_v = TextureWrap::kRepeat;
    if (texture.sampler >= 0) {
      if (texture.sampler >= static_cast<int>(model_.samplers.size())) {
        fail(what + ": sampler " + std::to_string(texture.sampler) + " does not exist");
      }
      const tinygltf::Sampler& sampler = model_.samplers[static_cast<std::size_t>(texture.sampler)];
      wrap_u = wrap_mode(sampler.wrapS, what);
      wrap_v = wrap_mode(sampler.wrapT, what);
    }
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(texture.source)];
    const std::string image_what =
        "image " + std::to_string(texture.source) +
        (image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? std::string()
                                                               : " (" + image.uri + ")");
    const auto bytes = images_.find(texture.source);
    if (bytes == images_.end() || bytes->second.empty()) {
      fail(image_what + ": cannot be read (a base colour texture needs it)");
    }
    const Photo photo = decode_photo(bytes->second, file_.string() + ": " + image_what);
    const auto slot = static_cast<std::int32_t>(mesh_.textures.textures.size());
    mesh_.textures.textures.push_back(
        std::make_shared<const SurfaceTexture>(make_surface_texture(photo, wrap_u, wrap_v)));
    texture_slots_.emplace(index, slot);
    return slot;
  }

  // The texture coordinates TEXCOORD_<set> of a primitive: float, or normalised unsigned byte
  // or short (glTF 2.0 §3.7.2.1).
  std::vector<TextureCoord> read_texture_coords(const tinygltf::Primitive& primitive, int set,
                                                std::size_t vertex_count,
                                                const std::string& what) const {
    const std::string name = "TEXCOORD_" + std::to_string(set);
    const auto found = primitive.attributes.find(name);
    if (found == primitive.attributes.end()) {
      fail(what + ": its material's base colour texture needs " + name + ", which it lacks");
    }
    const AccessorView v = view(found->second, what + " " + name);
    const tinygltf::Accessor& accessor = model_.accessors[static_cast<std::size_t>(found->second)];
    const std::string where = what + ": " + name;
    if (accessor.type != TINYGLTF_TYPE_VEC2) fail(where + " must be VEC2");
    if (v.count != vertex_count) fail(where + " has another count than POSITION");
    std::vector<TextureCoord> uv(v.count);
    for (std::size_t i = 0; i < v.count; ++i) {
      const unsigned char* p = v.data + i * v.stride;
      for (std::size_t c = 0; c < 2; ++c) {
        double x = 0;
        switch (v.component_type) {
          case TINYGLTF_COMPONENT_TYPE_FLOAT:
            x = load_scalar<float>(p + 4 * c, true);
            break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            x = p[c] / 255.0;
            break;
          case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            x = load_scalar<std::uint16_t>(p + 2 * c, true) / 65535.0;
            break;
          default:
            fail(where + " must be float, unsigned byte or unsigned short");
        }
        if (!std::isfinite(x)) {
          fail(where + " " + std::to_string(i) + " is not finite");
        }
        uv[i][c] = static_cast<float>(x);
      }
    }
    return uv;
  }

  // KHR_texture_transform (Khronos glTF extension registry, KHR_texture_transform): the
  // texture's UVs taken through T · R · S, T the offset, R a turn by `rotation` radians
  // counter-clockwise in UV space, S the scale; `texCoord` in it overrides the texture info's.
  void read_texture_transform(const tinygltf::Value& value, const std::string& where,
                              MaterialTexture& texture) const {
    if (!value.IsObject()) fail(where + " must be an object");
    const auto number = [&](const tinygltf::Value& v, const std::string& key) {
      if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) {
        fail(where + ": " + key + " must be a finite number");
      }
      return v.GetNumberAsDouble();
    };
    const auto pair = [&](const std::string& key, std::array<double, 2> fallback) {
      if (!value.Has(key)) return fallback;
      const tinygltf::Value& v = value.Get(key);
      if (!v.IsArray() || v.ArrayLen() != 2) fail(where + ": " + key + " must be two numbers");
      return std::array<double, 2>{number(v.Get(0), key), number(v.Get(1), key)};
    };
    const std::array<double, 2> offset = pair("offset", {0, 0});
    const std::array<double, 2> scale = pair("scale", {1, 1});
    const double rotation = value.Has("rotation") ? number(value.Get("rotation"), "rotation") : 0;
    if (value.Has("texCoord")) {
      const tinygltf::Value& set = value.Get("texCoord");
      if (!set.IsInt() || set.GetNumberAsInt() < 0) {
        fail(where + ": texCoord must be a non-negative integer");
      }
      texture.set = set.GetNumberAsInt();
    }
    const double c = std::cos(rotation), s = std::sin(rotation);
    texture.transform = {c * scale[0],  s * scale[1], offset[0],
                         -s * scale[0], c * scale[1], offset[1]};
  }

  std::uint32_t material_slot(int material, const std::string& what) {
    if (material >= static_cast<int>(model_.materials.size())) {
      fail(what + ": material " + std::to_string(material) + " does not exist");
    }
    if (material < 0) material = -1;
    const auto [it, inserted] =
        slots_.try_emplace(material, static_cast<std::uint32_t>(mesh_.materials.size()));
    if (inserted) {
      if (material < 0) {
        mesh_.materials.push_back({kDefaultImportMaterialName, kDefaultImportAlbedo});
      } else {
        const tinygltf::Material& m = model_.materials[static_cast<std::size_t>(material)];
        const std::vector<double>& f = m.pbrMetallicRoughness.baseColorFactor;
        if (f.size() < 3) fail("material " + std::to_string(material) + ": bad baseColorFactor");
        const std::string name = m.name.empty() ? "material " + std::to_string(material) : m.name;
        ImportedMaterial imported{name, Rgb{f[0], f[1], f[2]}};
        // metallicFactor and roughnessFactor (glTF 2.0 §5.19, both 1 when absent) make the
        // surface glossy only when the file gives either: a file with base colours alone
        // stays Lambertian, as it imported before materials had these keys.
        const auto& pbr = m.pbrMetallicRoughness;
        if (m.values.contains("metallicFactor") || m.values.contains("roughnessFactor")) {
          const auto unit = [&](double x, const char* key) {
            if (!(x >= 0 && x <= 1)) {
              fail("material " + std::to_string(material) + ": " + key +
                   " must be between 0 and 1");
            }
            return x;
          };
          imported.glossy = true;
          imported.metallic = unit(pbr.metallicFactor, "metallicFactor");
          imported.roughness = unit(pbr.roughnessFactor, "roughnessFactor");
        }
        imported.transparent = m.alphaMode == "BLEND" || transmission_factor(m) > 0;
        mesh_.materials.push_back(imported);
        const tinygltf::TextureInfo& base_colour = pbr.baseColorTexture;
        if (base_colour.index >= 0) {
          const std::string where = "material " + std::to_string(material);
          MaterialTexture texture{texture_slot(base_colour.index, where), base_colour.texCoord};
          const auto transform = base_colour.extensions.find("KHR_texture_transform");
          if (transform != base_colour.extensions.end()) {
            read_texture_transform(transform->second,
                                   where + ": baseColorTexture: KHR_texture_transform", texture);
          }
          material_texture_[it->second] = texture;
        }
      }
    }
    return it->second;
  }

  void add_mesh(const tinygltf::Mesh& gltf_mesh, int mesh_index, const Affine& world) {
    const bool mirrored = determinant(world) < 0;
    for (std::size_t p = 0; p < gltf_mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = gltf_mesh.primitives[p];
      const std::string what =
          "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(p);
      const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        continue;  // points and lines carry no surface
      }
      const auto position = primitive.attributes.find("POSITION");
      if (position == primitive.attributes.end()) fail(what + ": has no POSITION");
      const std::vector<Vec3> positions = read_positions(position->second, world, what);

      std::vector<std::uint32_t> indices;
      if (primitive.indices >= 0) {
        if (primitive.indices >= static_cast<int>(model_.accessors.size())) {
          fail(what + ": accessor " + std::to_string(primitive.indices) + " does not exist");
        }
        indices = read_indices(primitive.indices, positions.size(), what);
      } else {
        indices.resize(positions.size());
        for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
      }

      std::vector<Triangle> triangles;
      if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (indices.size() % 3 != 0) fail(what + ": vertex count is not a multiple of 3");
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
          triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
        }
      } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < indices.size(); ++i) {
          if (i % 2 == 0) {
            triangles.push_back({indices[i], indices[i + 1], indices[i + 2]});
          } else {
            triangles.push_back({indices[i], indices[i + 2], indices[i + 1]});
          }
        }
      } else {
        for (std::size_t i = 1; i + 1 < indices.size(); ++i) {
          triangles.push_back({indices[0], indices[i], indices[i + 1]});
        }
      }
      if (triangles.empty()) continue;

      if (mesh_.positions.size() + positions.size() > UINT32_MAX) fail("too many vertices");
      const auto offset = static_cast<std::uint32_t>(mesh_.positions.size());
      mesh_.positions.insert(mesh_.positions.end(), positions.begin(), positions.end());
      const std::uint32_t slot = material_slot(primitive.material, what);
      const auto textured = material_texture_.find(slot);
      std::vector<TextureCoord> uv, corners;
      if (textured != material_texture_.end()) {
        uv = read_texture_coords(primitive, textured->second.set, positions.size(), what);
        const std::array<double, 6>& m = textured->second.transform;
        for (TextureCoord& t : uv) {
          const double u = t[0], v = t[1];
          t = {static_cast<float>(m[0] * u + m[1] * v + m[2]),
               static_cast<float>(m[3] * u + m[4] * v + m[5])};
        }
      }
      for (Triangle t : triangles) {
        if (mirrored) std::swap(t[1], t[2]);
        mesh_.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
        mesh_.triangle_material.push_back(slot);
        if (!uv.empty()) corners.insert(corners.end(), {uv[t[0]], uv[t[1]], uv[t[2]]});
      }
      add_textures(uv.empty() ? -1 : textured->second.slot, corners, triangles.size());
    }
  }

  // Texture `slot` (−1: none) on the last `count` triangles, `corners` their corners' UVs.
  void add_textures(std::int32_t slot, const std::vector<TextureCoord>& corners,
                    std::size_t count) {
    TriangleTextures& all = mesh_.textures;
    if (slot < 0 && all.empty()) return;
    const std::size_t before = mesh_.triangles.size() - count;
    all.triangle_texture.resize(before, -1);  // the triangles before, when these are the first
    all.corner_uv.resize(3 * before, TextureCoord{0, 0});
    all.triangle_texture.insert(all.triangle_texture.end(), count, slot);
    if (slot < 0) {
      all.corner_uv.resize(3 * (before + count), TextureCoord{0, 0});
    } else {
      all.corner_uv.insert(all.corner_uv.end(), corners.begin(), corners.end());
    }
  }

  const std::filesystem::path& file_;
  const tinygltf::Model& model_;
  const EncodedImages& images_;
  std::vector<bool> visited_;
  std::unordered_map<int, std::uint32_t> slots_;
  std::unordered_map<int, std::int32_t> texture_slots_;                  // glTF texture → slot
  std::unordered_map<std::uint32_t, MaterialTexture> material_texture_;  // material slot →
  ImportedMesh mesh_;
};

// What keep_image reads and fills: the images' encoded bytes, and the model being loaded.
struct ImageLoad {
  EncodedImages* images = nullptr;
  const tinygltf::Model* model = nullptr;
};

// Keeps an image's encoded bytes; decoding waits until a base colour texture needs it, so
// that the images of other textures (normal maps, occlusion) are neither decoded nor required
// to be readable. tinygltf hands over an image in a buffer view as the view's bytes without
// checking that the view lies inside its buffer (the model's buffers and views are loaded by
// then): such an image is refused here instead of read past the buffer (found by fuzz_gltf,
// tests/fuzz/corpus/gltf/image-view-past-its-buffer.gltf).
bool keep_image(tinygltf::Image* image, const int index, std::string* error, std::string*, int, int,
                const unsigned char* bytes, int size, void* user) {
  const ImageLoad& load = *static_cast<const ImageLoad*>(user);
  if (image != nullptr && image->bufferView >= 0) {
    const std::vector<tinygltf::BufferView>& views = load.model->bufferViews;
    const auto v = static_cast<std::size_t>(image->bufferView);
    const bool inside = [&] {
      if (v >= views.size() || views[v].buffer < 0 ||
          static_cast<std::size_t>(views[v].buffer) >= load.model->buffers.size()) {
        return false;
      }
      const std::size_t held =
          load.model->buffers[static_cast<std::size_t>(views[v].buffer)].data.size();
      return views[v].byteOffset <= held && views[v].byteLength <= held - views[v].byteOffset &&
             static_cast<std::size_t>(std::max(size, 0)) <= views[v].byteLength;
    }();
    if (!inside) {
      if (error != nullptr) {
        *error = "image " + std::to_string(index) + ": its buffer view lies outside its buffer";
      }
      return false;
    }
  }
  if (bytes != nullptr && size > 0) (*load.images)[index].assign(bytes, bytes + size);
  return true;
}

bool starts_with_glb_magic(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) fail_input(file.string(), "cannot open file");
  char magic[4] = {};
  in.read(magic, 4);
  return in.gcount() == 4 && magic[0] == 'g' && magic[1] == 'l' && magic[2] == 'T' &&
         magic[3] == 'F';
}

std::string first_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) {
    text.pop_back();
  }
  return text.empty() ? "unknown error" : text;
}

}  // namespace

ImportedMesh import_gltf(const std::filesystem::path& file) {
  const bool binary = starts_with_glb_magic(file);
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  EncodedImages images;
  ImageLoad load{&images, &model};
  loader.SetImageLoader(&keep_image, &load);
  std::string error, warning;
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, file.string())
                : loader.LoadASCIIFromFile(&model, &error, &warning, file.string());
  } catch (const std::exception& e) {
    fail_input(file.string(), std::string("cannot parse glTF: ") + e.what());
  }
  if (!ok) fail_input(file.string(), "cannot parse glTF: " + first_line(error));
  return GltfReader(file, model, images).read();
}

}  // namespace relight

// glTF 2.0 import (scene/gltf_import.h): embedded and external buffers, .glb, node
// transforms, primitive modes, materials, and InputError for broken files. The assets are
// written by the tests so the bytes they check are visible here.
#include "scene/gltf_import.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/input_error.h"
#include "image/image_png.h"
#include "math/srgb.h"
#include "scene/mesh_import.h"
#include "support/mesh_import_error.h"

namespace relight {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Four quad corners (float VEC3, 48 bytes) then indices 0 1 2 0 2 3 (uint16, 12 bytes).
std::vector<unsigned char> quad_buffer() {
  const float positions[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  std::vector<unsigned char> bytes(sizeof positions + sizeof indices);
  std::memcpy(bytes.data(), positions, sizeof positions);
  std::memcpy(bytes.data() + sizeof positions, indices, sizeof indices);
  return bytes;
}

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = std::uint32_t{bytes[i]} << 16 |
                            (i + 1 < bytes.size() ? std::uint32_t{bytes[i + 1]} << 8 : 0) |
                            (i + 2 < bytes.size() ? std::uint32_t{bytes[i + 2]} : 0);
    out += alphabet[n >> 18 & 63];
    out += alphabet[n >> 12 & 63];
    out += i + 1 < bytes.size() ? alphabet[n >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? alphabet[n & 63] : '=';
  }
  return out;
}

// A document around quad_buffer(): accessor 0 = positions, 1 = indices; material 0 has
// baseColorFactor (0.2, 0.4, 0.6). `buffer` is the buffers[0] entry.
json quad_document(json buffer, json nodes, json primitives) {
  return {{"asset", {{"version", "2.0"}}},
          {"scene", 0},
          {"scenes", {{{"nodes", {0}}}}},
          {"nodes", std::move(nodes)},
          {"meshes", {{{"primitives", std::move(primitives)}}}},
          {"materials",
           {{{"name", "paint"},
             {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}}}}}},
          {"buffers", {std::move(buffer)}},
          {"bufferViews",
           {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
            {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}}}},
          {"accessors",
           {{{"bufferView", 0},
             {"componentType", 5126},
             {"count", 4},
             {"type", "VEC3"},
             {"min", {0, 0, 0}},
             {"max", {1, 1, 0}}},
            {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}}};
}

json embedded_buffer() {
  return {{"byteLength", 60},
          {"uri", "data:application/octet-stream;base64," + base64(quad_buffer())}};
}

json indexed_quad(int material = 0) {
  return {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", material}}};
}

class GltfImport : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& bytes) const {
    return dir_.write(name, bytes);
  }

  fs::path write_glb(const std::string& name, json document,
                     const std::vector<unsigned char>& bin) const {
    std::string text = document.dump();
    while (text.size() % 4 != 0) text += ' ';
    std::string payload(bin.begin(), bin.end());
    while (payload.size() % 4 != 0) payload += '\0';
    std::string out;
    const auto u32 = [&out](std::uint32_t v) {
      for (int i = 0; i < 4; ++i) out += static_cast<char>(v >> (8 * i) & 0xff);
    };
    out += "glTF";
    u32(2);
    u32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + payload.size()));
    u32(static_cast<std::uint32_t>(text.size()));
    u32(0x4E4F534A);  // JSON
    out += text;
    u32(static_cast<std::uint32_t>(payload.size()));
    u32(0x004E4942);  // BIN
    out += payload;
    return write(name, out);
  }

  std::string error_of(const fs::path& path) const { return testing::mesh_import_error(path); }

  testing::TempDir dir_;
};

Vec3 normal_of(const ImportedMesh& m, const Triangle& t) {
  return normalize(
      cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]));
}

void expect_near(Vec3 a, Vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-6);
  EXPECT_NEAR(a.y, b.y, 1e-6);
  EXPECT_NEAR(a.z, b.z, 1e-6);
}

TEST_F(GltfImport, EmbeddedBufferQuadIsTranslatedWithBaseColorAlbedo) {
  const json doc =
      quad_document(embedded_buffer(), {{{"mesh", 0}, {"translation", {1, 2, 3}}}}, indexed_quad());
  const ImportedMesh mesh = import_mesh(write("quad.gltf", doc.dump()));
  ASSERT_EQ(mesh.positions.size(), 4u);
  expect_near(mesh.positions[0], {1, 2, 3});
  expect_near(mesh.positions[2], {2, 3, 3});
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[1], (Triangle{0, 2, 3}));
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].name, "paint");
  EXPECT_DOUBLE_EQ(mesh.materials[0].albedo.r, 0.2);
  EXPECT_DOUBLE_EQ(mesh.materials[0].albedo.g, 0.4);
  EXPECT_DOUBLE_EQ(mesh.materials[0].albedo.b, 0.6);
  EXPECT_EQ(mesh.triangle_material, (std::vector<std::uint32_t>{0, 0}));
}

// metallicFactor and roughnessFactor make the material glossy (the absent one at glTF's default 1);
// a file with base colours only stays Lambertian (the test above); a factor outside 0..1 is an
// input error.
TEST_F(GltfImport, MetallicAndRoughnessFactorsMakeTheMaterialGlossy) {
  json doc =
      quad_document(embedded_buffer(), {{{"mesh", 0}, {"translation", {1, 2, 3}}}}, indexed_quad());
  EXPECT_FALSE(import_mesh(write("plain.gltf", doc.dump())).materials.at(0).glossy);
  doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0.25;
  const ImportedMaterial rough = import_mesh(write("rough.gltf", doc.dump())).materials.at(0);
  EXPECT_TRUE(rough.glossy);
  EXPECT_DOUBLE_EQ(rough.roughness, 0.25);
  EXPECT_DOUBLE_EQ(rough.metallic, 1.0);
  doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 0.0;
  const ImportedMaterial dielectric = import_mesh(write("satin.gltf", doc.dump())).materials.at(0);
  EXPECT_DOUBLE_EQ(dielectric.metallic, 0.0);
  doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 1.5;
  const fs::path bad = write("bad.gltf", doc.dump());
  EXPECT_NE(error_of(bad).find("metallicFactor must be between 0 and 1"), std::string::npos)
      << error_of(bad);
}

TEST_F(GltfImport, ExternalBufferAndNodeHierarchyComposeTransforms) {
  const std::vector<unsigned char> bin = quad_buffer();
  write("quad.bin", std::string(bin.begin(), bin.end()));
  const double s = std::sqrt(0.5);
  // Parent scales by 2; child rotates 90 degrees about z, then moves by +1 in x.
  const json nodes = {{{"children", {1}}, {"scale", {2, 2, 2}}},
                      {{"mesh", 0}, {"translation", {1, 0, 0}}, {"rotation", {0, 0, s, s}}}};
  // Second primitive: not indexed, no material -> one triangle of corners 0 1 2, default grey.
  const json primitives = {indexed_quad()[0], {{"attributes", {{"POSITION", 0}}}}};
  json doc = quad_document({{"byteLength", 60}, {"uri", "quad.bin"}}, nodes, primitives);
  doc["accessors"].push_back(
      {{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  doc["meshes"][0]["primitives"][1]["attributes"]["POSITION"] = 2;
  const ImportedMesh mesh = import_mesh(write("tree.gltf", doc.dump()));
  ASSERT_EQ(mesh.positions.size(), 7u);
  expect_near(mesh.positions[0], {2, 0, 0});  // (0,0,0) -> rotate -> +x 1 -> *2
  expect_near(mesh.positions[1], {2, 2, 0});  // (1,0,0) -> (0,1,0) -> (1,1,0) -> (2,2,0)
  expect_near(mesh.positions[3], {0, 0, 0});  // (0,1,0) -> (-1,0,0) -> (0,0,0)
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[2], (Triangle{4, 5, 6}));
  ASSERT_EQ(mesh.materials.size(), 2u);
  EXPECT_EQ(mesh.materials[1].name, "default");
  EXPECT_DOUBLE_EQ(mesh.materials[1].albedo.g, 0.8);
  EXPECT_EQ(mesh.triangle_material, (std::vector<std::uint32_t>{0, 0, 1}));
  for (const Triangle& t : mesh.triangles) EXPECT_NEAR(normal_of(mesh, t).z, 1.0, 1e-9);
}

TEST_F(GltfImport, GlbWithMatrixNodeMatchesGltf) {
  // Column-major matrix: scale 3 in x, translate (0, 0, 5).
  const json nodes = {{{"mesh", 0}, {"matrix", {3, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}}};
  const json doc = quad_document({{"byteLength", 60}}, nodes, indexed_quad());
  const ImportedMesh mesh = import_mesh(write_glb("quad.glb", doc, quad_buffer()));
  ASSERT_EQ(mesh.positions.size(), 4u);
  expect_near(mesh.positions[2], {3, 1, 5});
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_DOUBLE_EQ(mesh.materials.at(0).albedo.b, 0.6);
}

TEST_F(GltfImport, MirroringNodeKeepsFrontFaces) {
  const json doc =
      quad_document(embedded_buffer(), {{{"mesh", 0}, {"scale", {-1, 1, 1}}}}, indexed_quad());
  const ImportedMesh mesh = import_mesh(write("mirror.gltf", doc.dump()));
  ASSERT_EQ(mesh.triangles.size(), 2u);
  expect_near(mesh.positions[1], {-1, 0, 0});
  // The quad faces +z before mirroring in x, and so must it after.
  for (const Triangle& t : mesh.triangles) EXPECT_NEAR(normal_of(mesh, t).z, 1.0, 1e-9);
}

TEST_F(GltfImport, TriangleStripAndFanKeepWinding) {
  // Strip over corners 0 1 3 2 and fan over 0 1 2 3 both cover the quad facing +z.
  std::vector<unsigned char> bin = quad_buffer();
  const std::uint16_t strip[4] = {0, 1, 3, 2};
  std::memcpy(bin.data() + 48, strip, sizeof strip);
  bin.resize(56);
  const std::uint16_t fan[4] = {0, 1, 2, 3};
  bin.insert(bin.end(), reinterpret_cast<const unsigned char*>(fan),
             reinterpret_cast<const unsigned char*>(fan) + sizeof fan);
  json doc = quad_document(
      {{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}},
      {{{"mesh", 0}}},
      {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", 5}},
       {{"attributes", {{"POSITION", 0}}}, {"indices", 2}, {"mode", 6}}});
  doc["bufferViews"][1]["byteLength"] = 8;
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 56}, {"byteLength", 8}});
  doc["accessors"][1]["count"] = 4;
  doc["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5123}, {"count", 4}, {"type", "SCALAR"}});
  const ImportedMesh mesh = import_mesh(write("strip.gltf", doc.dump()));
  ASSERT_EQ(mesh.triangles.size(), 4u);
  double area = 0;
  for (const Triangle& t : mesh.triangles) {
    EXPECT_NEAR(normal_of(mesh, t).z, 1.0, 1e-9);
    area += 0.5 * length(cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                               mesh.positions[t[2]] - mesh.positions[t[0]]));
  }
  EXPECT_NEAR(area, 2.0, 1e-9);
}

TEST_F(GltfImport, AccessorPastItsBufferViewIsAnInputError) {
  json doc = quad_document(embedded_buffer(), {{{"mesh", 0}}}, indexed_quad());
  doc["accessors"][0]["count"] = 400;
  const fs::path path = write("long.gltf", doc.dump());
  const std::string message = error_of(path);
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
}

TEST_F(GltfImport, IndexOutOfRangeIsAnInputError) {
  std::vector<unsigned char> bin = quad_buffer();
  bin[48 + 4] = 9;  // third index -> 9
  const json doc = quad_document(
      {{"byteLength", 60}, {"uri", "data:application/octet-stream;base64," + base64(bin)}},
      {{{"mesh", 0}}}, indexed_quad());
  const fs::path path = write("index.gltf", doc.dump());
  const std::string message = error_of(path);
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("index 9"), std::string::npos) << message;
}

TEST_F(GltfImport, BrokenJsonMissingBufferAndBadReferencesAreInputErrors) {
  const fs::path broken = write("broken.gltf", "{\"asset\": {\"version\": \"2.0\"");
  EXPECT_EQ(error_of(broken).rfind(broken.string() + ": ", 0), 0u);

  const json missing =
      quad_document({{"byteLength", 60}, {"uri", "absent.bin"}}, {{{"mesh", 0}}}, indexed_quad());
  EXPECT_THROW(import_mesh(write("missing.gltf", missing.dump())), InputError);

  const json bad_material = quad_document(embedded_buffer(), {{{"mesh", 0}}}, indexed_quad(4));
  EXPECT_THROW(import_mesh(write("material.gltf", bad_material.dump())), InputError);

  json cycle = quad_document(embedded_buffer(), {{{"mesh", 0}, {"children", {0}}}}, indexed_quad());
  EXPECT_THROW(import_mesh(write("cycle.gltf", cycle.dump())), InputError);

  const fs::path truncated = write("cut.glb", "glTF\x02\0\0\0");
  EXPECT_THROW(import_mesh(truncated), InputError);
}

// Found by fuzz_gltf: tinygltf hands an image in a buffer view to the image loader as the view's
// bytes without checking that the view lies inside its buffer; the import refuses it instead of
// reading past the buffer (under ASan, reading it is a heap-buffer-overflow).
TEST_F(GltfImport, AnImageWhoseBufferViewRunsPastItsBufferIsAnInputError) {
  json doc = quad_document(embedded_buffer(), {{{"mesh", 0}}}, indexed_quad());
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 40}, {"byteLength", 400}});
  doc["images"] = {{{"bufferView", doc["bufferViews"].size() - 1}, {"mimeType", "image/png"}}};
  const fs::path path = write("view.gltf", doc.dump());
  const std::string message = error_of(path);
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find("buffer view lies outside its buffer"), std::string::npos) << message;
}

// The quad with corner UVs (0, 0), (1, 0), (1, 1), (0, 1) as TEXCOORD_<set> (accessor 2).
json quad_document_with_uvs(int set) {
  std::vector<unsigned char> bytes = quad_buffer();
  const float uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
  bytes.resize(60 + sizeof uv);
  std::memcpy(bytes.data() + 60, uv, sizeof uv);
  json doc =
      quad_document({{"byteLength", bytes.size()},
                     {"uri", "data:application/octet-stream;base64," + base64(bytes)}},
                    {{{"mesh", 0}}},
                    {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_" + std::to_string(set), 2}}},
                      {"indices", 1},
                      {"material", 0}}});
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 60}, {"byteLength", sizeof uv}});
  doc["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
  return doc;
}

// A base colour texture (a 2 × 1 PNG: red, then blue) on the quad, through TEXCOORD_0 (accessor 2),
// as a file beside the .gltf and as a data URI: the triangles carry the texture and their corners'
// UVs, the texture holds the decoded (linear) texels.
TEST_F(GltfImport, BaseColourTextureRidesOnTheTrianglesWithTheirUvs) {
  Image8 image;
  image.width = 2;
  image.height = 1;
  image.rgb = {255, 0, 0, 0, 0, 128};
  write_png(dir_.path() / "paint.png", image);
  std::ifstream png(dir_.path() / "paint.png", std::ios::binary);
  const std::vector<unsigned char> png_bytes{std::istreambuf_iterator<char>(png), {}};

  json doc = quad_document_with_uvs(0);
  doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
  doc["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}}};
  for (const std::string& uri :
       {std::string("paint.png"), "data:image/png;base64," + base64(png_bytes)}) {
    doc["images"] = {{{"uri", uri}}};
    const ImportedMesh mesh = import_mesh(write("textured.gltf", doc.dump()));
    ASSERT_EQ(mesh.textures.triangle_texture, (std::vector<std::int32_t>{0, 0}));
    ASSERT_EQ(mesh.textures.corner_uv.size(), 6u);
    EXPECT_EQ(mesh.textures.corner_uv[1], (TextureCoord{1, 0}));  // triangle 0 1 2
    EXPECT_EQ(mesh.textures.corner_uv[5], (TextureCoord{0, 1}));  // triangle 0 2 3
    const SurfaceTexture& texture = *mesh.textures.textures.at(0);
    EXPECT_EQ(texture.wrap_u, TextureWrap::kClampToEdge);
    EXPECT_EQ(texture.wrap_v, TextureWrap::kMirroredRepeat);
    ASSERT_EQ(texture.levels.at(0).width, 2);
    EXPECT_NEAR(texture.levels[0].rgb[0], 1.0, 1e-6);
    EXPECT_NEAR(texture.levels[0].rgb[5], srgb_decode(128 / 255.0), 1e-6);
    EXPECT_DOUBLE_EQ(mesh.materials.at(0).albedo.g, 0.4);  // the factor stays the material's
  }

  // Without TEXCOORD_0, with the image missing or not an image: clear errors.
  doc["images"] = {{{"uri", "absent.png"}}};
  const fs::path absent = write("absent.gltf", doc.dump());
  EXPECT_NE(error_of(absent).find("image 0 (absent.png): cannot be read"), std::string::npos)
      << error_of(absent);
  dir_.write("garbage.png", "not a png at all");
  doc["images"] = {{{"uri", "garbage.png"}}};
  const fs::path garbage = write("garbage.gltf", doc.dump());
  EXPECT_NE(error_of(garbage).find("image 0 (garbage.png): not a JPEG, PNG or TIFF"),
            std::string::npos)
      << error_of(garbage);
  doc["images"] = {{{"uri", "paint.png"}}};
  doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
  const fs::path no_uv = write("no_uv.gltf", doc.dump());
  EXPECT_NE(error_of(no_uv).find("needs TEXCOORD_0, which it lacks"), std::string::npos)
      << error_of(no_uv);
}

// KHR_texture_transform on the base colour texture takes the UVs through offset · rotation · scale
// (the extension's T · R · S; rotation counter-clockwise in UV space), and its texCoord overrides
// the texture info's; bad values are input errors naming it.
TEST_F(GltfImport, TextureTransformMovesTurnsAndScalesTheUvs) {
  Image8 image;
  image.width = 2;
  image.height = 1;
  image.rgb = {255, 0, 0, 0, 0, 255};
  write_png(dir_.path() / "paint.png", image);
  json doc = quad_document_with_uvs(1);
  doc["textures"] = {{{"source", 0}}};
  doc["images"] = {{{"uri", "paint.png"}}};
  doc["extensionsUsed"] = {"KHR_texture_transform"};
  json& info = doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"];
  info = {{"index", 0},
          {"extensions",
           {{"KHR_texture_transform",
             {{"offset", {0.5, 0.25}},
              {"rotation", std::acos(-1.0) / 2},
              {"scale", {2, 3}},
              {"texCoord", 1}}}}}};
  const ImportedMesh mesh = import_mesh(write("transformed.gltf", doc.dump()));
  ASSERT_EQ(mesh.textures.corner_uv.size(), 6u);
  // (u, v) → (2u·cos + 3v·sin + 0.5, −2u·sin + 3v·cos + 0.25), turned a quarter.
  const auto expect_uv = [&](std::size_t corner, float u, float v) {
    EXPECT_NEAR(mesh.textures.corner_uv[corner][0], u, 1e-6) << corner;
    EXPECT_NEAR(mesh.textures.corner_uv[corner][1], v, 1e-6) << corner;
  };
  expect_uv(0, 0.5f, 0.25f);   // (0, 0)
  expect_uv(1, 0.5f, -1.75f);  // (1, 0)
  expect_uv(2, 3.5f, -1.75f);  // (1, 1)
  expect_uv(5, 3.5f, 0.25f);   // (0, 1)

  // Without the extension's texCoord the texture info's set 0 is read, which this mesh lacks.
  info["extensions"]["KHR_texture_transform"].erase("texCoord");
  const fs::path set_zero = write("set_zero.gltf", doc.dump());
  EXPECT_NE(error_of(set_zero).find("needs TEXCOORD_0, which it lacks"), std::string::npos)
      << error_of(set_zero);
  for (const auto& [key, value, reason] :
       {std::tuple<std::string, json, std::string>{
            "scale", {1, "x"}, "scale must be a finite number"},
        {"offset", {1}, "offset must be two numbers"},
        {"rotation", "a quarter", "rotation must be a finite number"},
        {"texCoord", -1, "texCoord must be a non-negative integer"}}) {
    json bad = doc;
    bad["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]
       ["KHR_texture_transform"][key] = value;
    const std::string message = error_of(write("bad.gltf", bad.dump()));
    EXPECT_NE(message.find("material 0: baseColorTexture: KHR_texture_transform: " + reason),
              std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace relight

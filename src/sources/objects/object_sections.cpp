#include "sources/objects/object_sections.h"

#include <algorithm>

#include "common/input_error.h"

namespace relight {

namespace {

constexpr std::uint32_t kObjectCounts = rlt_fourcc("OCNT");
constexpr std::uint32_t kObjectPositions = rlt_fourcc("OPOS");
constexpr std::uint32_t kObjectNormals = rlt_fourcc("ONRM");
constexpr std::uint32_t kObjectRayPoints = rlt_fourcc("ORAY");
constexpr std::uint32_t kObjectPivots = rlt_fourcc("OPIV");
constexpr std::uint32_t kObjectAlbedo = rlt_fourcc("OALB");
constexpr std::uint32_t kObjectTriangles = rlt_fourcc("OTRI");
constexpr std::uint32_t kObjectMaterials = rlt_fourcc("OMAT");
constexpr std::uint32_t kObjectTexture = rlt_fourcc("OTEX");

void append(std::vector<float>& out, const std::vector<Vec3>& points) {
  for (const Vec3& p : points) {
    out.insert(out.end(),
               {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
  }
}

Vec3 at(std::span<const float> v, std::size_t i) {
  return {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
}

}  // namespace

void write_object_sections(RltWriter& w, std::span<const ObjectMesh> objects,
                           ObjectSectionData& d) {
  if (objects.empty()) return;
  const bool textured = std::any_of(objects.begin(), objects.end(),
                                    [](const ObjectMesh& o) { return !o.texture.empty(); });
  for (const ObjectMesh& o : objects) {
    if (textured && o.texture.empty())
      d.texture.insert(d.texture.end(), 3 * o.positions.size(), 1.0f);
    d.texture.insert(d.texture.end(), o.texture.begin(), o.texture.end());
    d.counts.push_back(static_cast<std::uint32_t>(o.positions.size()));
    d.counts.push_back(static_cast<std::uint32_t>(o.triangles.size()));
    append(d.positions, o.positions);
    append(d.normals, o.normals);
    append(d.ray_points, o.ray_points);
    append(d.pivots, {o.pivot});
    d.albedo.insert(d.albedo.end(), o.albedo.begin(), o.albedo.end());
    d.materials.insert(d.materials.end(), o.vertex_material.begin(), o.vertex_material.end());
    for (const Triangle& t : o.triangles) d.triangles.insert(d.triangles.end(), t.begin(), t.end());
  }
  w.add_u32(kObjectCounts, "object counts", d.counts);
  w.add_f32(kObjectPositions, "object positions", d.positions);
  w.add_f32(kObjectNormals, "object normals", d.normals);
  w.add_f32(kObjectRayPoints, "object ray points", d.ray_points);
  w.add_f32(kObjectPivots, "object pivots", d.pivots);
  w.add_f32(kObjectAlbedo, "object albedo", d.albedo);
  w.add_u32(kObjectTriangles, "object triangles", d.triangles);
  if (d.materials.size() == d.albedo.size() / 3) {
    w.add_u32(kObjectMaterials, "object materials", d.materials);
  }
  if (textured) w.add_f32(kObjectTexture, "object texture", d.texture);
}

std::vector<ObjectMesh> read_object_sections(const RltFile& file, const Scene& scene,
                                             const std::string& where) {
  std::vector<ObjectMesh> out;
  if (scene.objects.empty()) return out;
  if (!file.find_info(kObjectCounts)) {
    fail_input(where,
               "the scene has movable objects but the file has no object sections "
               "(run relight precompute again)");
  }
  const auto counts = file.view<std::uint32_t>(kObjectCounts);
  const auto positions = file.view<float>(kObjectPositions);
  const auto normals = file.view<float>(kObjectNormals);
  const auto rays = file.view<float>(kObjectRayPoints);
  const auto pivots = file.view<float>(kObjectPivots);
  const auto albedo = file.view<float>(kObjectAlbedo);
  const auto triangles = file.view<std::uint32_t>(kObjectTriangles);
  // Files written before live material edits have no OMAT: their objects' materials stay put.
  const auto materials = file.find_info(kObjectMaterials)
                             ? file.view<std::uint32_t>(kObjectMaterials)
                             : std::span<const std::uint32_t>{};
  const auto texture =
      file.find_info(kObjectTexture) ? file.view<float>(kObjectTexture) : std::span<const float>{};
  if (counts.size() != 2 * scene.objects.size() || pivots.size() != 3 * scene.objects.size()) {
    fail_input(where, "object sections disagree with the scene's objects");
  }
  std::size_t vertices = 0, tris = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    vertices += counts[2 * i];
    tris += counts[2 * i + 1];
  }
  if (positions.size() != 3 * vertices || normals.size() != 3 * vertices ||
      rays.size() != 3 * vertices || albedo.size() != 3 * vertices ||
      triangles.size() != 3 * tris || (!materials.empty() && materials.size() != vertices) ||
      (!texture.empty() && texture.size() != 3 * vertices)) {
    fail_input(where, "object sections have inconsistent sizes");
  }
  std::size_t v0 = 0, t0 = 0;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    ObjectMesh o;
    o.name = scene.objects[i].name;
    o.pivot = at(pivots, i);
    const std::size_t nv = counts[2 * i], nt = counts[2 * i + 1];
    for (std::size_t v = v0; v < v0 + nv; ++v) {
      o.positions.push_back(at(positions, v));
      o.normals.push_back(at(normals, v));
      o.ray_points.push_back(at(rays, v));
    }
    o.albedo.assign(albedo.begin() + static_cast<std::ptrdiff_t>(3 * v0),
                    albedo.begin() + static_cast<std::ptrdiff_t>(3 * (v0 + nv)));
    if (!texture.empty()) {
      o.texture.assign(texture.begin() + static_cast<std::ptrdiff_t>(3 * v0),
                       texture.begin() + static_cast<std::ptrdiff_t>(3 * (v0 + nv)));
    }
    if (!materials.empty()) {
      for (std::size_t v = v0; v < v0 + nv; ++v) {
        if (materials[v] >= scene.materials.size()) {
          fail_input(where, "an object vertex refers to a missing material");
        }
        o.vertex_material.push_back(materials[v]);
      }
    }
    for (std::size_t t = t0; t < t0 + nt; ++t) {
      const Triangle tri{triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]};
      for (const std::uint32_t v : tri) {
        if (v >= nv) fail_input(where, "an object triangle refers to a missing vertex");
      }
      o.triangles.push_back(tri);
    }
    v0 += nv;
    t0 += nt;
    out.push_back(std::move(o));
  }
  return out;
}

std::size_t object_section_bytes(const ObjectMesh& o) {
  return o.positions.size() * (std::size_t{4 * 3} * sizeof(float) + sizeof(std::uint32_t)) +
         o.texture.size() * sizeof(float) + o.triangles.size() * 3 * sizeof(std::uint32_t) +
         2 * sizeof(std::uint32_t) + 3 * sizeof(float);
}

}  // namespace relight

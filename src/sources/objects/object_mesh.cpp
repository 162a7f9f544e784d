#include "sources/objects/object_mesh.h"

#include <algorithm>
#include <stdexcept>

#include "engine/receivers.h"
#include "material/material_reflectance.h"
#include "scene/mesh_preparation.h"

namespace relight {

ObjectMesh prepare_object(const Scene& scene, const MovableObject& object) {
  PreparationSettings settings;
  settings.max_edge = scene.precompute.max_edge;
  settings.crease_deg = scene.precompute.crease_deg;
  const PreparedMesh mesh = prepare_mesh(object.geometry, settings);
  Receivers receivers;
  receivers.positions = mesh.positions;
  receivers.normals = mesh.normals;
  receivers.vertex_count = mesh.positions.size();
  receivers.albedo.assign(receivers.vertex_count, Rgb{});
  ObjectMesh m{object.name,
               object.pivot,
               mesh.positions,
               mesh.normals,
               receiver_ray_points(receivers, mesh),
               mesh.triangles,
               {},
               mesh.vertex_material,
               {}};
  for (std::size_t v = 0; v < mesh.vertex_material.size(); ++v) {
    const Rgb a = bounce_albedo(scene.materials.at(mesh.vertex_material[v]),
                                vertex_texture_at(mesh.vertex_texture, v));
    m.albedo.insert(m.albedo.end(),
                    {static_cast<float>(a.r), static_cast<float>(a.g), static_cast<float>(a.b)});
  }
  for (const Rgb& t : mesh.vertex_texture) {
    m.texture.insert(m.texture.end(),
                     {static_cast<float>(t.r), static_cast<float>(t.g), static_cast<float>(t.b)});
  }
  return m;
}

Bounds box_around(std::span<const Vec3> points) {
  Bounds b{points.front(), points.front()};
  for (const Vec3& p : points) {
    b.min = min(b.min, p);
    b.max = max(b.max, p);
  }
  return b;
}

BoundingSphere sphere_around(std::span<const Vec3> points) {
  const Bounds box = box_around(points);
  BoundingSphere s{(box.min + box.max) * 0.5, 0};
  for (const Vec3& p : points) s.radius = std::max(s.radius, length(p - s.centre));
  return s;
}

bool segment_near_sphere(Vec3 a, Vec3 b, const BoundingSphere& s, double margin) {
  const Vec3 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0 ? std::clamp(dot(s.centre - a, ab) / len2, 0.0, 1.0) : 0.0;
  const Vec3 gap = a + ab * t - s.centre;
  return dot(gap, gap) <= (s.radius + margin) * (s.radius + margin);
}

bool ray_near_sphere(Vec3 a, Vec3 d, const BoundingSphere& s, double margin) {
  const double t = std::max(0.0, dot(s.centre - a, d));
  const Vec3 gap = a + d * t - s.centre;
  return dot(gap, gap) <= (s.radius + margin) * (s.radius + margin);
}

PlacedObjects place_objects(std::span<const ObjectMesh> objects,
                            std::span<const MovablePlacement> placements) {
  if (objects.size() != placements.size()) {
    throw std::invalid_argument("place_objects: one placement per object expected");
  }
  std::vector<Vec3> positions, normals, ray_points;
  std::vector<float> albedo;
  std::vector<std::uint32_t> first{0}, triangle_object;
  std::vector<Triangle> triangles;
  std::vector<BoundingSphere> bounds;
  std::vector<Bounds> boxes;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const ObjectMesh& o = objects[i];
    const MovablePlacement& p = placements[i];
    const auto base = static_cast<std::uint32_t>(positions.size());
    for (std::size_t v = 0; v < o.positions.size(); ++v) {
      positions.push_back(placed_point(o.positions[v], o.pivot, p));
      normals.push_back(placed_direction(o.normals[v], p));
      ray_points.push_back(placed_point(o.ray_points[v], o.pivot, p));
    }
    albedo.insert(albedo.end(), o.albedo.begin(), o.albedo.end());
    first.push_back(static_cast<std::uint32_t>(positions.size()));
    if (!p.visible || o.triangles.empty()) {
      bounds.push_back({});
      boxes.push_back({});
      continue;
    }
    bounds.push_back(sphere_around(std::span(positions).subspan(base)));
    boxes.push_back(box_around(std::span(positions).subspan(base)));
    for (const Triangle& t : o.triangles) {
      triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
      triangle_object.push_back(static_cast<std::uint32_t>(i));
    }
  }
  RayTracer tracer(positions, triangles, sequential_ids(triangles.size()));
  std::vector<RayTracer> own;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    std::vector<Triangle> mine;
    std::vector<std::uint32_t> ids;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      if (triangle_object[t] != k) continue;
      mine.push_back(triangles[t]);
      ids.push_back(static_cast<std::uint32_t>(t));
    }
    own.emplace_back(positions, mine, ids);
  }
  return {std::move(positions),       std::move(normals), std::move(ray_points),
          std::move(albedo),          std::move(first),   std::move(triangles),
          std::move(triangle_object), std::move(bounds),  std::move(boxes),
          std::move(tracer),          std::move(own)};
}

std::size_t PlacedObjects::object_of_vertex(std::size_t q) const {
  return static_cast<std::size_t>(std::upper_bound(first_vertex.begin(), first_vertex.end(), q) -
                                  first_vertex.begin() - 1);
}

bool passes_through(const PlacedObjects& objects, std::size_t k, const RayTracer& room) {
  if (!objects.visible(k)) return false;
  const Vec3 centre = objects.bounds[k].centre;
  const auto inward = [&](Vec3 p) {
    const Vec3 d = centre - p;
    const double l = length(d);
    return l > 0.02 ? p + d * (0.01 / l) : p;
  };
  for (std::size_t t = 0; t < objects.triangles.size(); ++t) {
    if (objects.triangle_object[t] != k) continue;
    const Triangle& tri = objects.triangles[t];
    for (int e = 0; e < 3; ++e) {
      const Vec3 a = inward(objects.positions[tri[static_cast<std::size_t>(e)]]);
      const Vec3 b = inward(objects.positions[tri[static_cast<std::size_t>((e + 1) % 3)]]);
      const double l = length(b - a);
      if (l > 0 && room.occluded({a, (b - a) / l, 0, l})) return true;
    }
  }
  return false;
}

}  // namespace relight

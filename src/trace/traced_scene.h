// The scene as rays see it: opaque surfaces in one BVH, portal (window) triangles in
// another, so that light paths pass through portals (to the exterior) while every
// other triangle occludes. Sensors are not geometry and never occlude. Hit ids are
// indices into PreparedMesh::triangles.
#pragma once

#include <vector>

#include "scene/mesh_preparation.h"
#include "scene/scene.h"
#include "trace/ray_tracer.h"

namespace relight {

struct TracedScene {
  RayTracer opaque;
  RayTracer portals;
};

TracedScene build_traced_scene(const PreparedMesh& mesh, const std::vector<Material>& materials);

// Unit geometric normal of a prepared-mesh triangle (winding order: (b−a)×(c−a)).
Vec3 geometric_normal(const PreparedMesh& mesh, std::uint32_t triangle);
// Point on a triangle from Embree's barycentrics.
Vec3 point_on_triangle(const PreparedMesh& mesh, std::uint32_t triangle, double u, double v);

// Prepares the scene's triangles into per-vertex receivers with its precompute settings.
PreparedMesh prepare_scene_mesh(const Scene& scene);

}  // namespace relight

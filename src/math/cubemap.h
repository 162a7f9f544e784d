// Cubemaps: cell layout, texel directions, exact per-texel solid angles, SH projection.
//
// Layout (the OpenGL / Direct3D cube map convention, OpenGL 4.6 spec §8.13 Table 8.19, which
// is what cube-map files and GPU APIs use):
//  * Faces in the order 0 +X, 1 −X, 2 +Y, 3 −Y, 4 +Z, 5 −Z (world axes; y is up).
//  * Each face is N×N texels; texel (face, i, j) has column i (along s) and row j (along t),
//    flat index (face·N + j)·N + i; row j = 0 is the first row stored.
//  * With u = 2s − 1, v = 2t − 1 ∈ [−1, 1], the (unnormalised) direction of face point (u, v):
//      +X ( 1, −v, −u)   −X (−1, −v,  u)   +Y ( u,  1,  v)
//      −Y ( u, −1, −v)   +Z ( u, −v,  1)   −Z (−u, −v, −1)
//    i.e. for the four side faces t runs from +y (top, row 0) down to −y. As in OpenGL, a face
//    viewed from the centre of the cube appears mirrored left-right (the convention is
//    left-handed); e.g. on +Z, s grows toward +x.
//  * Texel centres: s = (i + ½)/N, t = (j + ½)/N.
// Solid angle of a texel, exactly: the face point (u, v) at distance 1 has area element
// dω = du dv / (1 + u² + v²)^{3/2}, whose integral over [0, u] × [0, v] is
// A(u, v) = atan2(u v, sqrt(1 + u² + v²)); a texel [u0,u1]×[v0,v1] has
// Ω = A(u1,v1) − A(u0,v1) − A(u1,v0) + A(u0,v0) (e.g. Driscoll, "Cubemap Texel Solid Angle",
// 2012; used for per-texel SH projection in Sun 2005 §3.3.4).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "math/rgb.h"
#include "math/vec3.h"

namespace relight {

enum CubeFace : int { kPosX = 0, kNegX = 1, kPosY = 2, kNegY = 3, kPosZ = 4, kNegZ = 5 };

struct CubemapTexel {
  int face = 0, i = 0, j = 0;
};
// A continuous position on a face: s, t ∈ [0, 1].
struct CubemapCoord {
  int face = 0;
  double s = 0, t = 0;
};

constexpr std::size_t cubemap_texel_count(int n) {
  return std::size_t{6} * n * n;
}
constexpr std::size_t cubemap_texel_index(int n, CubemapTexel c) {
  return (static_cast<std::size_t>(c.face) * n + c.j) * n + c.i;
}
constexpr CubemapTexel cubemap_texel_from_index(int n, std::size_t index) {
  const std::size_t nn = static_cast<std::size_t>(n) * n;
  return {static_cast<int>(index / nn), static_cast<int>(index % n),
          static_cast<int>((index % nn) / n)};
}

// The unnormalised direction of face point (u, v) ∈ [−1, 1]² (the table above): the face's
// axis + u · its s axis + v · its t axis.
Vec3 cubemap_face_point(int face, double u, double v);
// Unit direction of a face point.
Vec3 cubemap_direction(CubemapCoord c);
// Unit direction of a texel centre.
Vec3 cubemap_texel_direction(int n, CubemapTexel c);
// Exact solid angle of the face rectangle [u0,u1]×[v0,v1] (u, v ∈ [−1, 1], any face).
double cubemap_rect_solid_angle(double u0, double u1, double v0, double v1);
// Exact solid angle of texel (i, j) (the same on every face).
double cubemap_texel_solid_angle(int n, int i, int j);
// Solid angles of one face's texels, index j·N + i. They sum to 4π over 6 faces. Tabulated
// once per N for the life of the process (a sky's cubemap is made every hour of a year from
// the same sub-texel grid); safe to call from many threads.
const std::vector<double>& cubemap_solid_angles(int n);
// Unit directions of every texel centre (index as cubemap_texel_index), tabulated and shared
// the same way.
const std::vector<Vec3>& cubemap_texel_directions(int n);

// Face and (s, t) of a direction (need not be unit; must be non-zero). Ties between axes go
// to x, then y, then z.
CubemapCoord cubemap_coord(Vec3 dir);
// The texel containing a direction.
CubemapTexel cubemap_texel(int n, Vec3 dir);

// c_lm = Σ_texels value · Y_lm(centre) · Ω for l < order: texels hold 6·N² values in the
// layout above (per-texel averages of the function, e.g. radiance). Error O(1/N²) for smooth
// functions. The weights Y_lm(centre) · Ω are tabulated once per (order, N) for the process.
std::vector<double> sh_project_cubemap(int order, int n, std::span<const double> texels);
std::vector<Rgb> sh_project_cubemap(int order, int n, std::span<const Rgb> texels);

}  // namespace relight

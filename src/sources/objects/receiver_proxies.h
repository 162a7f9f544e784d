// Proxies for vertices far from a movable object. What an object changes in a room vertex's
// gather — the light it reflects there and the light it hides — varies over a length of the order
// of the vertex's distance to it: far from the object it is smooth, and tracing every vertex's rays
// there is wasted. Iwasaki et al. 2007 make it cheap with radiance fields on concentric spheres
// around each object (§3.1); relight keeps its traced rows near the object and, farther than a few
// proxy spacings, interpolates them from a sparse set of proxy vertices — the way irradiance
// caching (Ward, Rubinstein, Clear 1988, §2) reuses a sparse set of gathers over smooth indirect
// light.
//
// The objects' vertices likewise, each object apart: a rigid move keeps its proxies and weights.
//
// Proxies: the vertices are binned in cubic cells of `spacing`; in each cell, vertices of one
// group (the room, or one object) and one surface (normals within 25°, within a quarter spacing
// of one plane) form a cluster whose member nearest its mean is the proxy. A vertex's stencil:
// up to four proxies of its group within 1.5 spacings on its surface (normals within 25°, a
// quarter spacing off its tangent plane), weighted (1 − d / 1.5 spacing)², its own cluster's
// proxy always among them; the weights sum to 1. A proxy's stencil is itself. Pinned by
// tests/sources/objects/receiver_proxies_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/runtime_scene.h"
#include "math/vec3.h"

namespace relight {

struct ReceiverProxies {
  double spacing = 0;
  std::vector<std::uint32_t> proxies;   // vertices, ascending
  std::vector<std::int32_t> proxy_of;   // per vertex: its index in `proxies`, −1 when not one
  std::vector<std::uint32_t> first{0};  // per vertex, then the end: [first[v], first[v + 1])
  std::vector<std::uint32_t> stencil;   // indices into `proxies`
  std::vector<float> weights;           // per stencil entry; a vertex's sum to 1
};

// The room's bounding-box diagonal over 64: 0.2 m in a 10 × 3 × 8 m office.
double default_proxy_spacing(std::span<const Vec3> points);

// `group` per vertex: vertices of different groups never share a proxy.
ReceiverProxies build_receiver_proxies(std::span<const Vec3> points, std::span<const Vec3> normals,
                                       std::span<const std::uint32_t> group, double spacing);

// Whether a vertex at `point` takes its row toward the object in `sphere` from its proxies: it
// is not a proxy and lies `distance` spacings or more outside the sphere.
bool takes_proxy_row(const ReceiverProxies& proxies, std::size_t vertex, Vec3 point,
                     const BoundingSphere& sphere, double distance);

// For every layer l and vertex v with use[l][v] set: out[3v..3v+2] += Σ weight ·
// values[3 (l P + j) ..] over v's stencil (P proxies; `values` holds 3 floats per proxy per
// layer). One pass over the vertices.
void spread_from_proxies(const ReceiverProxies& proxies,
                         std::span<const std::span<const std::uint8_t>> use,
                         std::span<const float> values, std::span<float> out);

}  // namespace relight

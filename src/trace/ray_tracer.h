// Ray casting through Embree 3: one BVH over a set of triangles,
// single-ray rtcIntersect1 / rtcOccluded1 and a batch of closest hits through rtcIntersect1M,
// safe to call from many threads at once (callers parallelise with oneTBB). Returned triangle
// ids are the caller's.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "math/vec3.h"
#include "scene/triangle_soup.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace relight {

inline constexpr std::uint32_t kNoHit = std::numeric_limits<std::uint32_t>::max();

struct Ray {
  Vec3 origin;
  Vec3 direction;  // need not be unit; t is in units of |direction|
  double t_near = 0;
  double t_far = std::numeric_limits<double>::infinity();
};

struct RayHit {
  std::uint32_t triangle = kNoHit;  // the caller's id of the hit triangle
  double t = 0;
  double u = 0, v = 0;  // barycentrics of vertices 1 and 2; vertex 0 has 1 - u - v
  bool hit() const { return triangle != kNoHit; }
};

class RayTracer {
 public:
  // Builds the BVH over `triangles` (indices into `positions`); hit ids are ids[i]
  // for triangles[i]. An empty set is valid and never hits.
  RayTracer(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
            const std::vector<std::uint32_t>& ids);
  ~RayTracer();
  RayTracer(RayTracer&&) noexcept;
  RayTracer& operator=(RayTracer&&) noexcept;
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  RayHit intersect(const Ray& ray) const;
  // The closest hits of many rays at once (Embree's ray stream, flagged incoherent: the
  // gather operator's 64 cosine rays of a receiver at 0.70–0.73 of a plain rtcIntersect1
  // loop's rate against 0.61–0.62 one by one; flagged coherent, 0.41): hits[i] for rays[i].
  // Throws std::invalid_argument when the sizes differ. Pinned by
  // tests/trace/ray_tracer_test.cpp (the same hits as single rays).
  void intersect(std::span<const Ray> rays, std::span<RayHit> hits) const;
  bool occluded(const Ray& ray) const;
  // Whether each ray from `origin` along directions[i] (t in (0, ∞)) is blocked, in packets of
  // eight (rtcOccluded8, flagged coherent: one point's view of nearby directions, as a
  // direction tree's leaves in order). Throws std::invalid_argument when the sizes differ.
  // Pinned by tests/trace/ray_tracer_test.cpp (the same answers as single rays).
  void occluded_from(Vec3 origin, std::span<const Vec3> directions,
                     std::span<std::uint8_t> blocked) const;
  std::size_t triangle_count() const { return ids_.size(); }

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
  std::vector<std::uint32_t> ids_;
};

// The tracers that block light together: the static room, and the movable objects as a
// lighting state places them (sources/objects/placed_objects.h), when any. Converts from one
// tracer, so code that traces the room alone reads the same.
class Occluders {
 public:
  Occluders(const RayTracer& room) : room_(&room) {}  // NOLINT(google-explicit-constructor)
  Occluders(const RayTracer& room, const RayTracer* objects) : room_(&room), objects_(objects) {}

  bool occluded(const Ray& ray) const {
    return room_->occluded(ray) || (objects_ != nullptr && objects_->occluded(ray));
  }
  std::size_t triangle_count() const {
    return room_->triangle_count() + (objects_ != nullptr ? objects_->triangle_count() : 0);
  }
  const RayTracer& room() const { return *room_; }
  const RayTracer* objects() const { return objects_; }

 private:
  const RayTracer* room_;
  const RayTracer* objects_ = nullptr;
};

// Ids 0 … n−1: a tracer built with them reports each hit triangle by its own index.
std::vector<std::uint32_t> sequential_ids(std::size_t n);

// Start point for a secondary ray leaving a surface at p with unit normal n, pushed off
// the surface to avoid self-intersection in Embree's single precision.
Vec3 offset_from_surface(Vec3 p, Vec3 n);

}  // namespace relight

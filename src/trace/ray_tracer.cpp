#include "trace/ray_tracer.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>

namespace relight {

struct RayTracer::Handles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Handles() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

void check(RTCDevice device, const char* what) {
  const RTCError e = rtcGetDeviceError(device);
  if (e != RTC_ERROR_NONE) {
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                             std::to_string(static_cast<int>(e)) + ")");
  }
}

RTCRay to_embree(const Ray& r) {
  RTCRay ray{};
  ray.org_x = static_cast<float>(r.origin.x);
  ray.org_y = static_cast<float>(r.origin.y);
  ray.org_z = static_cast<float>(r.origin.z);
  ray.dir_x = static_cast<float>(r.direction.x);
  ray.dir_y = static_cast<float>(r.direction.y);
  ray.dir_z = static_cast<float>(r.direction.z);
  ray.tnear = static_cast<float>(r.t_near);
  ray.tfar =
      std::isinf(r.t_far) ? std::numeric_limits<float>::infinity() : static_cast<float>(r.t_far);
  ray.mask = 0xFFFFFFFFu;
  ray.flags = 0;
  return ray;
}

}  // namespace

RayTracer::RayTracer(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
                     const std::vector<std::uint32_t>& ids)
    : handles_(std::make_unique<Handles>()), ids_(ids) {
  if (ids_.size() != triangles.size()) throw std::invalid_argument("RayTracer: ids size mismatch");
  handles_->device = rtcNewDevice(nullptr);
  if (!handles_->device) throw std::runtime_error("Embree: cannot create a device");
  handles_->scene = rtcNewScene(handles_->device);
  rtcSetSceneBuildQuality(handles_->scene, RTC_BUILD_QUALITY_HIGH);
  // Watertight triangle tests: without it about 1 ray in 10^5 slips through a shared
  // edge, leaking light out of closed rooms (measured by the gather operator's tests).
  rtcSetSceneFlags(handles_->scene, RTC_SCENE_FLAG_ROBUST);
  if (!triangles.empty()) {
    RTCGeometry geometry = rtcNewGeometry(handles_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), positions.size()));
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), triangles.size()));
    check(handles_->device, "allocating geometry buffers");
    for (std::size_t i = 0; i < positions.size(); ++i) {
      vertices[3 * i + 0] = static_cast<float>(positions[i].x);
      vertices[3 * i + 1] = static_cast<float>(positions[i].y);
      vertices[3 * i + 2] = static_cast<float>(positions[i].z);
    }
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      for (int k = 0; k < 3; ++k) indices[3 * i + k] = triangles[i][k];
    }
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(handles_->scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(handles_->scene);
  check(handles_->device, "building the BVH");
}

RayTracer::~RayTracer() = default;
RayTracer::RayTracer(RayTracer&&) noexcept = default;
RayTracer& RayTracer::operator=(RayTracer&&) noexcept = default;

RayHit RayTracer::intersect(const Ray& r) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray = to_embree(r);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(handles_->scene, &context, &rh);
  RayHit hit;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
  hit.triangle = ids_[rh.hit.primID];
  hit.t = rh.ray.tfar;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  return hit;
}

void RayTracer::intersect(std::span<const Ray> rays, std::span<RayHit> hits) const {
  if (rays.size() != hits.size()) throw std::invalid_argument("RayTracer: rays and hits differ");
  constexpr std::size_t kStream = 64;
  RTCRayHit stream[kStream];
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  for (std::size_t first = 0; first < rays.size(); first += kStream) {
    const std::size_t count = std::min(kStream, rays.size() - first);
    for (std::size_t i = 0; i < count; ++i) {
      stream[i] = RTCRayHit{};
      stream[i].ray = to_embree(rays[first + i]);
      stream[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
      stream[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect1M(handles_->scene, &context, stream, static_cast<unsigned>(count),
                   sizeof(RTCRayHit));
    for (std::size_t i = 0; i < count; ++i) {
      const RTCRayHit& rh = stream[i];
      RayHit& hit = hits[first + i];
      hit = RayHit{};
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
      hit.triangle = ids_[rh.hit.primID];
      hit.t = rh.ray.tfar;
      hit.u = rh.hit.u;
      hit.v = rh.hit.v;
    }
  }
}

bool RayTracer::occluded(const Ray& r) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = to_embree(r);
  rtcOccluded1(handles_->scene, &context, &ray);
  return ray.tfar < 0;  // Embree sets tfar = -inf on an occlusion
}

void RayTracer::occluded_from(Vec3 origin, std::span<const Vec3> directions,
                              std::span<std::uint8_t> blocked) const {
  if (directions.size() != blocked.size()) {
    throw std::invalid_argument("RayTracer: directions and answers differ");
  }
  constexpr std::size_t kPacket = 8;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  alignas(32) RTCRay8 packet{};
  alignas(32) int valid[kPacket];
  for (std::size_t i = 0; i < kPacket; ++i) {
    packet.org_x[i] = static_cast<float>(origin.x);
    packet.org_y[i] = static_cast<float>(origin.y);
    packet.org_z[i] = static_cast<float>(origin.z);
    packet.mask[i] = 0xFFFFFFFFu;
  }
  for (std::size_t first = 0; first < directions.size(); first += kPacket) {
    const std::size_t count = std::min(kPacket, directions.size() - first);
    for (std::size_t i = 0; i < kPacket; ++i) {
      const Vec3 d = directions[first + std::min(i, count - 1)];
      packet.dir_x[i] = static_cast<float>(d.x);
      packet.dir_y[i] = static_cast<float>(d.y);
      packet.dir_z[i] = static_cast<float>(d.z);
      packet.tnear[i] = 0.0f;
      packet.tfar[i] = std::numeric_limits<float>::infinity();
      valid[i] = i < count ? -1 : 0;
    }
    rtcOccluded8(valid, handles_->scene, &context, &packet);
    for (std::size_t i = 0; i < count; ++i) blocked[first + i] = packet.tfar[i] < 0 ? 1 : 0;
  }
}

std::vector<std::uint32_t> sequential_ids(std::size_t n) {
  std::vector<std::uint32_t> ids(n);
  std::iota(ids.begin(), ids.end(), 0u);
  return ids;
}

Vec3 offset_from_surface(Vec3 p, Vec3 n) {
  const double scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0});
  return p + n * (2e-5 * scale);
}

}  // namespace relight

#include "sources/emitters/nearfield_lighting.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "math/sh.h"
#include "sources/emitters/adaptive_sampling.h"
#include "sources/emitters/inverse_distance_reconstruction.h"
#include "sources/emitters/lbg_placement.h"
#include "sources/emitters/valid_domain_reconstruction.h"
#include "trace/ray_tracer.h"

namespace relight {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

NearfieldMethod parse_nearfield_method(const std::string& name) {
  if (name == "adaptive") return NearfieldMethod::kAdaptive;
  if (name == "icp") return NearfieldMethod::kIcp;
  if (name == "truth") return NearfieldMethod::kTruth;
  throw std::invalid_argument("unknown near-field method \"" + name +
                              "\" (expected adaptive, icp or truth)");
}

const char* nearfield_method_name(NearfieldMethod method) {
  switch (method) {
    case NearfieldMethod::kAdaptive:
      return "adaptive";
    case NearfieldMethod::kIcp:
      return "icp";
    case NearfieldMethod::kTruth:
      return "truth";
  }
  return "?";
}

NearfieldScene::NearfieldScene(std::vector<Vec3> receivers, int order,
                               std::vector<Vec3> occluder_positions,
                               std::vector<Triangle> occluder_triangles)
    : receivers_(std::move(receivers)),
      order_(order),
      bvh_(build_receiver_bvh(receivers_)),
      occluder_positions_(std::move(occluder_positions)),
      occluder_triangles_(std::move(occluder_triangles)),
      occluders_(occluder_positions_, occluder_triangles_,
                 sequential_ids(occluder_triangles_.size())) {
  if (order < 1) throw std::invalid_argument("near-field: order must be >= 1");
}

namespace {

// The bounding sphere of each lit emitter as placed, and the planes of its triangles.
struct LitEmitters {
  std::vector<EmitterBound> bounds;
  std::vector<EmitterFace> faces;
};

LitEmitters lit_emitters(const PlacedEmitters& emitters) {
  const std::size_t count = emitters.radiance.size();
  std::vector<Vec3> lo(count, Vec3{1e300, 1e300, 1e300}), hi(count, Vec3{-1e300, -1e300, -1e300});
  for (std::size_t t = 0; t < emitters.triangles.size(); ++t) {
    const std::uint32_t e = emitters.emitter_of_triangle[t];
    for (const std::uint32_t v : emitters.triangles[t]) {
      lo[e] = min(lo[e], emitters.positions[v]);
      hi[e] = max(hi[e], emitters.positions[v]);
    }
  }
  LitEmitters out;
  std::vector<std::size_t> index(count, count);
  for (std::size_t e = 0; e < count; ++e) {
    if (max_component(emitters.radiance[e]) <= 0 || lo[e].x > hi[e].x) continue;
    index[e] = out.bounds.size();
    out.bounds.push_back(
        {(lo[e] + hi[e]) * 0.5, 0.5 * length(hi[e] - lo[e]), luminance(emitters.radiance[e])});
  }
  for (std::size_t t = 0; t < emitters.triangles.size(); ++t) {
    const std::size_t e = index[emitters.emitter_of_triangle[t]];
    if (e == count) continue;
    out.faces.push_back({emitters.positions[emitters.triangles[t][0]], emitters.normals[t], e});
  }
  return out;
}

}  // namespace

NearfieldResult NearfieldScene::light(const PlacedEmitters& emitters,
                                      const NearfieldSettings& settings) const {
  if (settings.max_samples < 1) throw std::invalid_argument("near-field: max_samples must be >= 1");
  const RayTracer tracer(emitters.positions, emitters.triangles,
                         sequential_ids(emitters.triangles.size()));
  IncidentRadianceSettings incident;
  incident.face_size = settings.face_size;
  incident.order = order_;
  const bool occlude = settings.scene_occlusion && occluders_.triangle_count() > 0;
  const auto sample_at = [&](Vec3 x) {
    const RayTracer* occluders = occlude && !inside_geometry(x) ? &occluders_ : nullptr;
    return sample_incident_radiance(x, tracer, emitters.triangle_radiance, emitters.normals,
                                    occluders, incident);
  };
  const std::size_t k = static_cast<std::size_t>(sh_count(order_));
  const std::size_t n = receivers_.size();
  NearfieldResult out;
  out.sh.assign(n * k, Rgb{});
  switch (settings.method) {
    case NearfieldMethod::kAdaptive: {
      auto start = Clock::now();
      LitEmitters lit = lit_emitters(emitters);
      AdaptiveSampling a = sample_adaptively(
          bvh_, n, sample_at,
          {settings.epsilon, settings.max_samples, std::move(lit.bounds), std::move(lit.faces)});
      out.sampling_seconds = seconds_since(start);
      out.evaluations = a.evaluations;
      start = Clock::now();
      const LinearOctree octree = build_sample_octree(a.samples, receivers_);
      reconstruct_valid_domain(a.samples, octree, receivers_, a.sample_of_receiver, out.sh);
      out.reconstruction_seconds = seconds_since(start);
      out.samples = std::move(a.samples);
      break;
    }
    case NearfieldMethod::kIcp: {
      auto start = Clock::now();
      const std::vector<Vec3> positions = lbg_sample_positions(
          receivers_, static_cast<int>(std::min(settings.max_samples, n)), settings.seed);
      out.placement_seconds = seconds_since(start);
      start = Clock::now();
      out.samples.resize(positions.size());
      tbb::parallel_for(std::size_t{0}, positions.size(), [&](std::size_t s) {
        out.samples[s] = {positions[s], 0, sample_at(positions[s]).sh};
      });
      out.evaluations = positions.size();
      out.sampling_seconds = seconds_since(start);
      start = Clock::now();
      reconstruct_inverse_distance(out.samples, receivers_, out.sh, settings.icp_exponent);
      out.reconstruction_seconds = seconds_since(start);
      break;
    }
    case NearfieldMethod::kTruth: {
      const auto start = Clock::now();
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
        for (std::size_t r = range.begin(); r != range.end(); ++r) {
          const IncidentRadiance in = sample_at(receivers_[r]);
          std::copy(in.sh.begin(), in.sh.end(),
                    out.sh.begin() + static_cast<std::ptrdiff_t>(r * k));
        }
      });
      out.evaluations = n;
      out.sampling_seconds = seconds_since(start);
      out.samples.resize(n);  // one a receiver (positions only: the coefficients are in `sh`)
      for (std::size_t r = 0; r < n; ++r) out.samples[r].position = receivers_[r];
      break;
    }
  }
  return out;
}

bool NearfieldScene::inside_geometry(Vec3 x) const {
  int back = 0;
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {-1.0, 1.0}) {
      Vec3 dir{0, 0, 0};
      dir[axis] = sign;
      const RayHit hit = occluders_.intersect({x, dir});
      if (!hit.hit()) continue;
      const Triangle& t = occluder_triangles_[hit.triangle];
      const Vec3 a = occluder_positions_[t[0]];
      const Vec3 n = cross(occluder_positions_[t[1]] - a, occluder_positions_[t[2]] - a);
      back += dot(n, dir) > 0;
    }
  }
  return back >= 4;
}

void nearfield_irradiance(std::span<const float> transfer, std::span<const Rgb> sh, std::size_t k,
                          std::span<float> out) {
  const std::size_t n = out.size() / 3;
  if (transfer.size() != n * k || sh.size() != n * k) {
    throw std::invalid_argument("nearfield_irradiance: sizes disagree");
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      Rgb e;
      for (std::size_t c = 0; c < k; ++c) e += sh[r * k + c] * transfer[r * k + c];
      out[3 * r] = static_cast<float>(e.r);
      out[3 * r + 1] = static_cast<float>(e.g);
      out[3 * r + 2] = static_cast<float>(e.b);
    }
  });
}

double rms_difference(std::span<const float> a, std::span<const float> b, std::size_t count) {
  if (a.size() < 3 * count || b.size() < 3 * count) {
    throw std::invalid_argument("rms_difference: fields too small");
  }
  if (count == 0) return 0;
  double sum = 0;
  for (std::size_t i = 0; i < 3 * count; ++i) {
    const double d = static_cast<double>(a[i]) - b[i];
    sum += d * d;
  }
  return std::sqrt(sum / (3.0 * count));
}

}  // namespace relight

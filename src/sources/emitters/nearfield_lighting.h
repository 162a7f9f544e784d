// Near-field lighting of a precomputed scene (Sun 2005 Fig. 3.1): at run time, with the emitters
// where the lighting state puts them, sample the incident radiance, reconstruct its SH vector l_p
// at every receiver and shade E_p = t_p · l_p with the stored transfer (its interreflection:
// sources/emitters/emitter_lighting.h). Three ways to choose the samples, in the same code so they
// compare fairly:
//  * adaptive — Sun 2005: the oracle-driven BVH traversal (Alg. 3.4, Eq. 3.3) and valid-domain
//    reconstruction through the linear octree (§3.3.5, Eq. 2.13 with b = 1);
//  * icp — the baseline it compares against (Sloan et al. 2002): `max_samples` points placed by
//    LBG/ICP clustering of the receivers (computed here, timed apart as placement) and global
//    inverse-distance interpolation over all samples (Eq. 2.12–2.13, b = 2);
//  * truth — a sample at every receiver.
//
// The incident radiance at a sample is that of the emitters, emitters occluding each other, as
// Sun 2005 renders it (a cubemap of the emitters, §3.3.4): the static scene's shadowing is
// in the transfer vectors (V(p, ω) within `nearfield_shadow_distance`, §3.2.1), exact at each
// receiver. `scene_occlusion` lets the static scene occlude the emitters at each sample too
// (the long-range shadows beyond that distance); a sample position is a mean of receivers and
// may lie inside a closed object (a dragon's body) — a point from which most of six axis rays
// meet back faces is taken to be inside, and there only the emitters occlude. Measured on the
// dragon (docs/performance.md, "Near-field"), occlusion at the samples disagrees with the
// receivers they are interpolated to and the adaptive method loses its advantage, so it is off
// by default.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "light/emitter_placement.h"
#include "sources/emitters/incident_radiance.h"
#include "sources/emitters/incident_sample.h"
#include "sources/emitters/receiver_bvh.h"
#include "trace/ray_tracer.h"

namespace relight {

enum class NearfieldMethod { kAdaptive, kIcp, kTruth };

// "adaptive", "icp", "truth"; std::invalid_argument otherwise.
NearfieldMethod parse_nearfield_method(const std::string& name);
const char* nearfield_method_name(NearfieldMethod method);

struct NearfieldSettings {
  NearfieldMethod method = NearfieldMethod::kAdaptive;
  double epsilon = 0.01;           // adaptive: the oracle's bound
  std::size_t max_samples = 4096;  // adaptive: the cap; icp: the number of samples
  int face_size = 16;              // cubemap texels per face side at each sample
  double icp_exponent = 2;         // b of Eq. 2.13 for the icp baseline
  bool scene_occlusion = false;    // the static scene occludes emitters at samples (see above)
  std::uint64_t seed = 1;          // icp placement
};

struct NearfieldResult {
  std::vector<Rgb> sh;  // receivers × K reconstructed incident radiance
  std::vector<IncidentSample> samples;
  std::size_t evaluations = 0;   // incident radiance samples taken
  double placement_seconds = 0;  // icp: the LBG clustering (Sun 2005 does it off-line)
  double sampling_seconds = 0;   // traversal and sampling
  double reconstruction_seconds = 0;
};

// The receivers of a precomputed scene and what sampling them needs, built once.
class NearfieldScene {
 public:
  // `receivers`: the positions shaded (vertices, then sensors); order: SH bands l < order;
  // the static scene's opaque triangles occlude (`scene_occlusion`).
  NearfieldScene(std::vector<Vec3> receivers, int order, std::vector<Vec3> occluder_positions = {},
                 std::vector<Triangle> occluder_triangles = {});

  NearfieldResult light(const PlacedEmitters& emitters, const NearfieldSettings& settings) const;

  std::size_t receiver_count() const { return receivers_.size(); }
  int order() const { return order_; }

 private:
  std::vector<Vec3> receivers_;
  int order_;
  ReceiverBvh bvh_;
  std::vector<Vec3> occluder_positions_;
  std::vector<Triangle> occluder_triangles_;
  RayTracer occluders_;

  // Most of six axis rays from x meet back faces of the static scene.
  bool inside_geometry(Vec3 x) const;
};

// The direct E per receiver, 3 floats each: Σ_k t_k l_k. `transfer`: receivers × K.
void nearfield_irradiance(std::span<const float> transfer, std::span<const Rgb> sh, std::size_t k,
                          std::span<float> out);

// Root-mean-square difference of two RGB fields (3 floats per element), over the first `count`
// elements.
double rms_difference(std::span<const float> a, std::span<const float> b, std::size_t count);

}  // namespace relight

// Where to sample the incident radiance (Sun 2005 §3.3.2–3.3.3, Algorithm 3.4):
// a breadth-first traversal of the receiver BVH from the root. At each node the incident
// radiance is sampled at the node's sample position x and the oracle
//     e = r · |l_x| / H_d²                                                  (Eq. 3.3)
// estimates the error of reconstructing the whole node from that one sample (r the node's
// radius, |l_x| the norm of the sampled coefficients, H_d the harmonic mean distance to the
// emitters). A node whose e is within the user's bound ε (or a leaf) keeps its sample, with a
// valid domain of radius r; otherwise its two children are traversed. A node nearer to an
// emitter than its own radius is always refined (beyond the thesis): its one sample cannot
// stand for it — above a one-sided panel the sample sees nothing (|l_x| = 0, e = 0) while the
// receivers below it are lit, and the oracle's 1/H_d² model fails next to an emitter
// (tests/sources/emitters/nearfield_lighting_test.cpp, a panel over a table). Likewise a node
// whose sample sees no emitter is refined while some of its receivers may lie in front of an
// emitter's face (a wall whose mean point is above a downward panel). The traversal also
// stops splitting when the samples would exceed the user's cap. Each level of the traversal
// is sampled in parallel; the decisions are taken in breadth-first order, so the result does
// not depend on the number of threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "sources/emitters/incident_radiance.h"
#include "sources/emitters/incident_sample.h"
#include "sources/emitters/receiver_bvh.h"

namespace relight {

// A lit emitter's bounding sphere.
struct EmitterBound {
  Vec3 centre;
  double radius = 0;
  double luminance = 0;  // cd/m² (Y)
};

// A lit emitter triangle's plane: it emits toward dot(normal, x − point) > 0.
struct EmitterFace {
  Vec3 point, normal;
  std::size_t emitter = 0;  // its EmitterBound
};

struct AdaptiveSamplingSettings {
  double epsilon = 0.01;               // the oracle's bound (units of r·|l|/H_d²: cd/m² per m)
  std::size_t max_samples = 4096;      // cap on kept samples (≥ 1)
  std::vector<EmitterBound> emitters;  // nodes nearer than their radius are refined
  // A node whose sample sees no emitter is refined while some of its receivers may lie in
  // front of one of these (the sample may sit behind a one-sided emitter, or above it) and
  // that emitter could make the oracle exceed ε (an emitter too small for the cubemap far
  // away cannot).
  std::vector<EmitterFace> faces;
};

struct AdaptiveSampling {
  std::vector<IncidentSample> samples;            // the kept ones
  std::vector<std::uint32_t> node_of_sample;      // BVH node each sample belongs to
  std::vector<std::uint32_t> sample_of_receiver;  // the sample whose node holds the receiver
  std::size_t evaluations = 0;  // incident-radiance samples taken (kept and refined)
};

using IncidentSampler = std::function<IncidentRadiance(Vec3)>;

double oracle(double radius, const IncidentRadiance& sample);

// Whether some emitter's bounding sphere comes nearer to the node's sample position than the
// node's radius.
bool near_emitter(const ReceiverBvhNode& node, const std::vector<EmitterBound>& emitters);

// Whether some receiver of the node (within twice its radius of its sample position) may lie
// in front of one of the faces of an emitter whose oracle there could exceed ε: r · L · Ω / d²
// with Ω = πR²/d² of its bounding sphere (d at least R).
bool may_be_lit_unseen(const ReceiverBvhNode& node, const AdaptiveSamplingSettings& settings);

AdaptiveSampling sample_adaptively(const ReceiverBvh& bvh, std::size_t receivers,
                                   const IncidentSampler& sampler,
                                   const AdaptiveSamplingSettings& settings);

}  // namespace relight

#include "sources/emitters/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <tbb/parallel_for.h>

namespace relight {

double oracle(double radius, const IncidentRadiance& sample) {
  const double h = sample.harmonic_mean_distance;
  if (!std::isfinite(h)) return 0;  // no emitter seen: nothing to vary
  return radius * sh_luminance_norm(sample.sh) / (h * h);
}

bool near_emitter(const ReceiverBvhNode& node, const std::vector<EmitterBound>& emitters) {
  for (const EmitterBound& e : emitters) {
    if (length(node.sample_position - e.centre) - e.radius < node.radius) return true;
  }
  return false;
}

bool may_be_lit_unseen(const ReceiverBvhNode& node, const AdaptiveSamplingSettings& settings) {
  for (const EmitterFace& f : settings.faces) {
    if (dot(f.normal, node.sample_position - f.point) <= -2 * node.radius) continue;
    const EmitterBound& e = settings.emitters.at(f.emitter);
    const double d = std::max(length(node.sample_position - e.centre), e.radius);
    const double potential =
        node.radius * e.luminance * kPi * e.radius * e.radius / (d * d * d * d);
    if (potential > settings.epsilon) return true;
  }
  return false;
}

AdaptiveSampling sample_adaptively(const ReceiverBvh& bvh, std::size_t receivers,
                                   const IncidentSampler& sampler,
                                   const AdaptiveSamplingSettings& settings) {
  if (settings.max_samples < 1) throw std::invalid_argument("near-field: max_samples must be >= 1");
  AdaptiveSampling out;
  out.sample_of_receiver.assign(receivers, 0);
  if (bvh.nodes.empty()) return out;
  std::vector<std::uint32_t> frontier{0};
  std::vector<IncidentRadiance> sampled;
  while (!frontier.empty()) {
    sampled.assign(frontier.size(), {});
    tbb::parallel_for(std::size_t{0}, frontier.size(), [&](std::size_t f) {
      sampled[f] = sampler(bvh.nodes[frontier[f]].sample_position);
    });
    out.evaluations += frontier.size();
    std::vector<std::uint32_t> next;
    for (std::size_t f = 0; f < frontier.size(); ++f) {
      const ReceiverBvhNode& node = bvh.nodes[frontier[f]];
      // Every node still to decide, and every child queued, ends as at least one sample.
      const std::size_t committed = out.samples.size() + (frontier.size() - f - 1) + next.size();
      const bool refine =
          !node.leaf() && committed + 2 <= settings.max_samples &&
          (oracle(node.radius, sampled[f]) > settings.epsilon ||
           near_emitter(node, settings.emitters) ||
           (sampled[f].emitter_solid_angle <= 0 && may_be_lit_unseen(node, settings)));
      if (refine) {
        next.push_back(static_cast<std::uint32_t>(node.left));
        next.push_back(static_cast<std::uint32_t>(node.right));
        continue;
      }
      const auto index = static_cast<std::uint32_t>(out.samples.size());
      out.samples.push_back({node.sample_position, node.radius, std::move(sampled[f].sh)});
      out.node_of_sample.push_back(frontier[f]);
      for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
        out.sample_of_receiver[bvh.order[k]] = index;
      }
    }
    frontier = std::move(next);
  }
  return out;
}

}  // namespace relight

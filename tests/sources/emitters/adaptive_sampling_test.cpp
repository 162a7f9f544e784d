// sources/emitters/adaptive_sampling.h (Sun 2005 Algorithm 3.4, Eq. 3.3): a far emitter is sampled
// once at the root; a near one refines where the oracle says; a smaller ε takes more samples; the
// cap holds; every receiver maps to the kept sample of the node holding it.
#include <gtest/gtest.h>

#include "scene/primitives.h"
#include "sources/emitters/adaptive_sampling.h"

namespace relight {
namespace {

// A 1 m × 1 m grid of receivers in the y = 0 plane.
std::vector<Vec3> grid(int n) {
  std::vector<Vec3> p;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) p.push_back({(i + 0.5) / n, 0, (j + 0.5) / n});
  }
  return p;
}

struct EmitterAbove {
  std::vector<Vec3> receivers = grid(32);
  ReceiverBvh bvh = build_receiver_bvh(receivers);
  TriangleSoup sphere;
  RayTracer emitters;
  Rgb radiance{1000, 1000, 1000};

  explicit EmitterAbove(Vec3 centre)
      : sphere(make_sphere(centre, 0.1, Facing::kOutward, 2, 0)),
        emitters(sphere.positions, sphere.triangles,
                 std::vector<std::uint32_t>(sphere.triangles.size(), 0)) {}

  AdaptiveSampling run(double epsilon, std::size_t cap = 4096) const {
    IncidentRadianceSettings s;
    s.face_size = 8;
    return sample_adaptively(bvh, receivers.size(),
                             [&](Vec3 x) {
                               return sample_incident_radiance(x, emitters, std::span(&radiance, 1),
                                                               {}, nullptr, s);
                             },
                             {epsilon, cap, {}, {}});
  }
};

TEST(AdaptiveSampling, FarEmitterOneSampleNearEmitterRefinesLocally) {
  const double epsilon = 0.5;
  const EmitterAbove far({0.5, 30, 0.5});  // 30 object radii away
  const AdaptiveSampling f = far.run(epsilon);
  EXPECT_EQ(f.samples.size(), 1u);
  EXPECT_EQ(f.evaluations, 1u);
  const EmitterAbove near({0.1, 0.15, 0.1});  // just above one corner
  const AdaptiveSampling n = near.run(epsilon);
  EXPECT_GT(n.samples.size(), 8u);
  // Denser near the emitter: the mean valid-domain radius of samples in the corner quarter is
  // smaller than in the opposite quarter.
  double r_near = 0, r_far = 0;
  int c_near = 0, c_far = 0;
  for (const IncidentSample& s : n.samples) {
    if (s.position.x < 0.5 && s.position.z < 0.5) r_near += s.radius, ++c_near;
    if (s.position.x > 0.5 && s.position.z > 0.5) r_far += s.radius, ++c_far;
  }
  ASSERT_GT(c_near, 0);
  ASSERT_GT(c_far, 0);
  EXPECT_LT(r_near / c_near, r_far / c_far);
  // A smaller bound takes more samples; the cap holds.
  EXPECT_GT(near.run(epsilon / 4).samples.size(), n.samples.size());
  EXPECT_LE(near.run(1e-9, 50).samples.size(), 50u);
  // Each receiver's sample is that of the kept node holding it.
  for (std::size_t s = 0; s < n.samples.size(); ++s) {
    const ReceiverBvhNode& node = near.bvh.nodes[n.node_of_sample[s]];
    for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
      EXPECT_EQ(n.sample_of_receiver[near.bvh.order[k]], s);
    }
  }
}

TEST(AdaptiveSampling, OracleIsRadiusTimesNormOverSquaredHarmonicMean) {
  IncidentRadiance in;
  in.sh = {{3, 3, 3}, {4, 4, 4}};
  in.harmonic_mean_distance = 2;
  EXPECT_NEAR(oracle(0.5, in), 0.5 * 5 / 4, 1e-12);
  in.harmonic_mean_distance = std::numeric_limits<double>::infinity();
  EXPECT_EQ(oracle(0.5, in), 0);
}

}  // namespace
}  // namespace relight

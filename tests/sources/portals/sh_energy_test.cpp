// portal_sh_energy (Yue et al. 2009's Eq. 4–5) on synthetic blocked transfer whose
// per-order maxima are known in closed form: orthogonal columns (the largest squared norm
// over N_v), rank one (|u|²·|w|² / N_v), order 0 (the mean square), a dense matrix against
// an independent SVD; shares and cumulative shares; sensors after the vertices ignored.
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "engine/transfer_blocks.h"
#include "sources/portals/sh_energy.h"

namespace relight {
namespace {

constexpr int kOrder = 3;  // bases 0 | 1..3 | 4..8
constexpr std::size_t kVertices = 100;
constexpr std::size_t kReceivers = 130;  // 30 sensors after the vertices (three blocks)

struct Synthetic {
  Eigen::MatrixXf r, g, b;
  std::vector<float> blocks;
  PortalTransferView view() const {
    PortalTransferView v;
    v.name = "synthetic";
    v.indirect.f32 = blocks;
    return v;
  }
};

// Channel g is 2 × r (energies ×4), b is zero; sensor rows hold large values that must be
// ignored.
Synthetic make_synthetic(const Eigen::MatrixXf& vertex_rows) {
  Synthetic s;
  s.r = Eigen::MatrixXf::Constant(kReceivers, kOrder * kOrder, 1000.0f);
  s.r.topRows(kVertices) = vertex_rows;
  s.g = 2 * s.r;
  s.b = Eigen::MatrixXf::Zero(kReceivers, kOrder * kOrder);
  s.blocks = pack_blocks({s.r, s.g, s.b});
  return s;
}

Eigen::MatrixXf closed_form_rows() {
  Eigen::MatrixXf t = Eigen::MatrixXf::Zero(kVertices, kOrder * kOrder);
  for (std::size_t v = 0; v < kVertices; ++v) {
    const auto i = static_cast<Eigen::Index>(v);
    t(i, 0) = (v % 2 == 0) ? 1.0f : -3.0f;  // order 0: mean square (1 + 9) / 2 = 5
    // Order 1: disjoint supports, hence orthogonal columns with squared norms
    // 4·10 = 40, 9·20 = 180 (across the block boundary at 64), 1·50 = 50.
    if (v < 10) t(i, 1) = 2.0f;
    if (v >= 50 && v < 70) t(i, 2) = 3.0f;
    if (v >= 30 && v < 50) t(i, 3) = 1.0f;
    if (v >= 70) t(i, 3) = 1.0f;
    // Order 2: rank one, u_v · w_m with w = (1, -2, 0, 3, 1) (|w|² = 15).
    const float u = static_cast<float>(v % 7) - 3.0f;
    const float w[5] = {1, -2, 0, 3, 1};
    for (int m = 0; m < 5; ++m) t(i, 4 + m) = u * w[m];
  }
  return t;
}

double rank_one_energy() {
  double u2 = 0;
  for (std::size_t v = 0; v < kVertices; ++v) {
    const double u = static_cast<double>(v % 7) - 3.0;
    u2 += u * u;
  }
  return u2 * 15.0 / kVertices;
}

TEST(PortalShEnergy, ClosedFormMaximaPerOrder) {
  const Synthetic s = make_synthetic(closed_form_rows());
  const std::vector<ShOrderEnergy> e = portal_sh_energy(s.view(), kVertices, kReceivers, kOrder);
  ASSERT_EQ(e.size(), 3u);
  const double expected[3] = {5.0, 180.0 / kVertices, rank_one_energy()};
  for (int l = 0; l < kOrder; ++l) {
    const ShOrderEnergy& o = e[static_cast<std::size_t>(l)];
    EXPECT_EQ(o.l, l);
    EXPECT_NEAR(o.energy[0], expected[l], 1e-6 * expected[l]) << "l " << l;
    EXPECT_NEAR(o.energy[1], 4 * expected[l], 4e-6 * expected[l]) << "l " << l;
    EXPECT_EQ(o.energy[2], 0.0) << "l " << l;
  }
}

TEST(PortalShEnergy, SharesAndCumulativeShares) {
  const Synthetic s = make_synthetic(closed_form_rows());
  const std::vector<ShOrderEnergy> e = portal_sh_energy(s.view(), kVertices, kReceivers, kOrder);
  const double energies[3] = {5.0, 1.8, rank_one_energy()};
  const double total = energies[0] + energies[1] + energies[2];
  double cumulative = 0;
  for (int l = 0; l < kOrder; ++l) {
    const ShOrderEnergy& o = e[static_cast<std::size_t>(l)];
    cumulative += energies[l] / total;
    for (int c = 0; c < 2; ++c) {  // the same shares in r and g (g = 2 r)
      EXPECT_NEAR(o.share[c], energies[l] / total, 1e-6) << "l " << l << " c " << c;
      EXPECT_NEAR(o.cumulative[c], cumulative, 1e-6) << "l " << l << " c " << c;
    }
    EXPECT_EQ(o.share[2], 0.0);  // no energy at all: shares 0, not NaN
    EXPECT_EQ(o.cumulative[2], 0.0);
  }
  EXPECT_EQ(e.back().cumulative[0], 1.0);
  EXPECT_EQ(e.back().cumulative[1], 1.0);
}

TEST(PortalShEnergy, DenseOrderMatchesLargestSingularValue) {
  std::mt19937 rng(7);
  std::normal_distribution<float> normal;
  Eigen::MatrixXf t(kVertices, kOrder * kOrder);
  for (Eigen::Index i = 0; i < t.size(); ++i) t.data()[i] = normal(rng);
  const Synthetic s = make_synthetic(t);
  const std::vector<ShOrderEnergy> e = portal_sh_energy(s.view(), kVertices, kReceivers, kOrder);
  for (int l = 0; l < kOrder; ++l) {
    const Eigen::MatrixXd tl = t.middleCols(l * l, 2 * l + 1).cast<double>();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(tl);
    const double sigma = svd.singularValues()(0);
    const double expected = sigma * sigma / kVertices;
    EXPECT_NEAR(e[static_cast<std::size_t>(l)].energy[0], expected, 1e-5 * expected) << l;
    // No unit vector does better (Eq. 5 is a maximum): try a few random ones.
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd c(2 * l + 1);
      for (Eigen::Index m = 0; m < c.size(); ++m) c(m) = normal(rng);
      c.normalize();
      EXPECT_LE((tl * c).squaredNorm() / kVertices, expected * (1 + 1e-9));
    }
  }
}

TEST(PortalShEnergy, OnlyTheGivenVerticesCount) {
  // Two rows: vertex 0 with t = 1 everywhere, vertex 1 with t = 3. Analysing one vertex
  // gives 1 per order-0 basis; with two, (1 + 9) / 2.
  Eigen::MatrixXf t = Eigen::MatrixXf::Ones(kVertices, kOrder * kOrder);
  t.row(1).setConstant(3.0f);
  const Synthetic s = make_synthetic(t);
  EXPECT_NEAR(portal_sh_energy(s.view(), 1, kReceivers, kOrder)[0].energy[0], 1.0, 1e-9);
  EXPECT_NEAR(portal_sh_energy(s.view(), 2, kReceivers, kOrder)[0].energy[0], 5.0, 1e-6);
  // Order 1 of one vertex with t = (1, 1, 1): |t|² = 3 along c = t / |t|.
  EXPECT_NEAR(portal_sh_energy(s.view(), 1, kReceivers, kOrder)[1].energy[0], 3.0, 1e-6);
  for (const ShOrderEnergy& o : portal_sh_energy(s.view(), 0, kReceivers, kOrder)) {
    EXPECT_EQ(o.energy[0], 0.0);
    EXPECT_EQ(o.cumulative[0], 0.0);
  }
}

TEST(PortalShEnergy, RejectsInconsistentSizes) {
  const Synthetic s = make_synthetic(closed_form_rows());
  EXPECT_THROW(portal_sh_energy(s.view(), kVertices, kReceivers, kOrder + 1),
               std::invalid_argument);
  EXPECT_THROW(portal_sh_energy(s.view(), kVertices, kReceivers + 64, kOrder),
               std::invalid_argument);
  EXPECT_THROW(portal_sh_energy(s.view(), kReceivers + 1, kReceivers, kOrder),
               std::invalid_argument);
  EXPECT_THROW(portal_sh_energy(s.view(), kVertices, kReceivers, 0), std::invalid_argument);
}

}  // namespace
}  // namespace relight

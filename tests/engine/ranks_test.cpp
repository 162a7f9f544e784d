// The ranks of one precompute (engine/ranks.h, issue 19) without MPI: the receivers' blocks are
// dealt in turn and cover every receiver once, and ranks run as threads of this process —
// exchanging through memory — share rows exactly and build the gather operator bit for bit as
// one process does. `mpirun` itself is tested in tests/cli/mpi_precompute_test.cpp.
#include "engine/ranks.h"

#include <algorithm>
#include <barrier>
#include <cmath>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/gather_operator.h"
#include "engine/transfer_blocks.h"
#include "scene/primitives.h"

namespace relight {
namespace {

// Ranks that are threads of one process: all_gather meets at a barrier.
class ThreadRanks {
 public:
  explicit ThreadRanks(int size) : sync_(size), slots_(static_cast<std::size_t>(size)) {}

  class Rank final : public RankExchange {
   public:
    Rank(ThreadRanks& all, int rank) : all_(&all), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override { return static_cast<int>(all_->slots_.size()); }
    std::vector<std::vector<std::uint8_t>> all_gather(std::span<const std::uint8_t> mine) override {
      all_->slots_[static_cast<std::size_t>(rank_)].assign(mine.begin(), mine.end());
      all_->sync_.arrive_and_wait();
      std::vector<std::vector<std::uint8_t>> out = all_->slots_;
      all_->sync_.arrive_and_wait();
      return out;
    }
    double exchange_seconds() const override { return 0; }
    std::uint64_t exchange_bytes() const override { return 0; }

   private:
    ThreadRanks* all_;
    int rank_;
  };

 private:
  std::barrier<> sync_;
  std::vector<std::vector<std::uint8_t>> slots_;
};

TEST(RankShares, BlocksAreDealtInTurnAndCoverEveryReceiverOnce) {
  for (int ranks : {1, 2, 3, 7, 40}) {
    ThreadRanks all(ranks);
    std::vector<int> owner((1000 + kBlock - 1) / kBlock, -1);
    std::size_t covered = 0;
    for (int k = 0; k < ranks; ++k) {
      ThreadRanks::Rank rank(all, k);
      const RankShares shares = dealt_blocks(rank, 1000, kBlock);
      std::size_t previous = 0;
      for (const std::size_t b : shares.my_blocks()) {
        ASSERT_LT(b, owner.size());
        EXPECT_EQ(owner[b], -1) << "block " << b << " dealt twice";
        owner[b] = k;
        EXPECT_EQ(b % static_cast<std::size_t>(ranks), static_cast<std::size_t>(k));
        if (b != shares.my_blocks().front()) {
          EXPECT_GT(b, previous);
        }
        previous = b;
      }
      covered += shares.my_receivers();
    }
    EXPECT_EQ(covered, 1000u) << ranks << " ranks";
    EXPECT_EQ(std::count(owner.begin(), owner.end(), -1), 0);
  }
  SingleProcess alone;
  EXPECT_THROW(dealt_blocks(alone, 10, 0), std::invalid_argument);
}

TEST(RankExchange, TwoRanksAsThreadsBuildTheGatherOperatorBitForBitAsOneProcess) {
  Scene scene;
  scene.materials = {{"wall"}};
  scene.geometry = make_box({0, 0, 0}, {4, 3, 5}, Facing::kInward, 0);
  scene.geometry.append(make_box({1, 0, 1}, {2, 1, 2}, Facing::kOutward, 0));
  for (int i = 0; i < 90; ++i) {  // sensors cost 4× a vertex's rays below
    std::string name = "s";
    name += std::to_string(i);
    scene.sensors.push_back({name, {{0.2 + 0.04 * i, 0.8, 2.5}}, {0, 1, 0}});
  }
  PreparationSettings settings;
  settings.max_edge = 0.4;
  const PreparedMesh mesh = prepare_mesh(scene.geometry, settings);
  const TracedScene traced = build_traced_scene(mesh, scene.materials);
  const Receivers receivers = make_receivers(scene, mesh);
  ASSERT_GT(receivers.size(), 4 * kBlock);

  const GatherOperator one = build_gather_operator(receivers, mesh, traced, 32, 128, 5, false);
  ThreadRanks ranks(2);
  std::vector<GatherOperator> two(2);
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k) {
    threads.emplace_back([&, k] {
      ThreadRanks::Rank rank(ranks, k);
      const RankShares shares = dealt_blocks(rank, receivers.size(), kBlock);
      two[static_cast<std::size_t>(k)] =
          build_gather_operator(receivers, mesh, traced, 32, 128, 5, false, &shares);
    });
  }
  for (std::thread& t : threads) t.join();
  for (const GatherOperator& g : two) {
    ASSERT_EQ(g.matrix.nonZeros(), one.matrix.nonZeros());
    EXPECT_EQ(g.rays, one.rays);
    EXPECT_TRUE(std::equal(g.matrix.outerIndexPtr(), g.matrix.outerIndexPtr() + g.matrix.rows() + 1,
                           one.matrix.outerIndexPtr()));
    EXPECT_TRUE(std::equal(g.matrix.innerIndexPtr(), g.matrix.innerIndexPtr() + g.matrix.nonZeros(),
                           one.matrix.innerIndexPtr()));
    EXPECT_TRUE(std::equal(g.matrix.valuePtr(), g.matrix.valuePtr() + g.matrix.nonZeros(),
                           one.matrix.valuePtr()));
  }
}

TEST(RankExchange, ShareRowsFillsEveryRanksRowsOfAMatrixAndAVector) {
  // 150 receivers in blocks of 64 among 4 ranks: the fourth has none.
  ThreadRanks ranks(4);
  std::vector<Eigen::MatrixXf> matrices(4);
  std::vector<std::vector<double>> vectors(4);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&, k] {
      ThreadRanks::Rank rank(ranks, k);
      const RankShares shares = dealt_blocks(rank, 150, 64);
      Eigen::MatrixXf m = Eigen::MatrixXf::Zero(150, 4);
      std::vector<double> v(2 * 150, 0.0);
      for (const std::size_t b : shares.my_blocks()) {
        for (std::size_t r = shares.first(b); r < shares.last(b); ++r) {
          for (int c = 0; c < 4; ++c) m(static_cast<Eigen::Index>(r), c) = float(r * 10 + c);
          v[2 * r] = double(r);
          v[2 * r + 1] = -double(r);
        }
      }
      share_rows(shares, m);
      share_rows(shares, 2, v);
      matrices[static_cast<std::size_t>(k)] = std::move(m);
      vectors[static_cast<std::size_t>(k)] = std::move(v);
    });
  }
  for (std::thread& t : threads) t.join();
  for (int k = 0; k < 4; ++k) {
    for (Eigen::Index r = 0; r < 150; ++r) {
      for (int c = 0; c < 4; ++c) ASSERT_EQ(matrices[k](r, c), float(r * 10 + c)) << "rank " << k;
      ASSERT_EQ(vectors[k][2 * r], double(r));
      ASSERT_EQ(vectors[k][2 * r + 1], -double(r));
    }
  }
}

}  // namespace
}  // namespace relight

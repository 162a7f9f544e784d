// The ranks of one precompute (engine/ranks.h) without MPI: the receivers' blocks are dealt in turn
// and cover every receiver once, and ranks run as threads of this process — exchanging through
// memory — share rows exactly and build the gather operator bit for bit as one process does.
// `mpirun` itself is tested in tests/cli/mpi_precompute_test.cpp.
#include "engine/ranks.h"

#include <algorithm>
#include <barrier>
#include <cmath>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "engine/bounce_solver.h"
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

// A box room with a box inside and 90 sensors, its receivers more than four blocks.
Scene rank_scene() {
  Scene scene;
  scene.materials = {{"wall"}};
  scene.materials[0].albedo = {0.7, 0.5, 0.3};
  scene.geometry = make_box({0, 0, 0}, {4, 3, 5}, Facing::kInward, 0);
  scene.geometry.append(make_box({1, 0, 1}, {2, 1, 2}, Facing::kOutward, 0));
  for (int i = 0; i < 90; ++i) {  // sensors cost 4× a vertex's rays below
    std::string name = "s";
    name += std::to_string(i);
    scene.sensors.push_back({name, {{0.2 + 0.04 * i, 0.8, 2.5}}, {0, 1, 0}});
  }
  return scene;
}

PreparedMesh rank_mesh(const Scene& scene) {
  PreparationSettings settings;
  settings.max_edge = 0.4;
  return prepare_mesh(scene.geometry, settings);
}

struct RankRoom {
  Scene scene = rank_scene();
  PreparedMesh mesh = rank_mesh(scene);
  TracedScene traced = build_traced_scene(mesh, scene.materials);
  Receivers receivers = make_receivers(scene, mesh);
};

TEST(RankExchange, TwoRanksAsThreadsBuildTheirRowsOfTheGatherOperatorBitForBitAsOneProcess) {
  const RankRoom room;
  const Receivers& receivers = room.receivers;
  ASSERT_GT(receivers.size(), 4 * kBlock);

  const GatherOperator one =
      build_gather_operator(receivers, room.mesh, room.traced, 32, 128, 5, false);
  ThreadRanks ranks(2);
  std::vector<GatherOperator> two(2);
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k) {
    threads.emplace_back([&, k] {
      ThreadRanks::Rank rank(ranks, k);
      const RankShares shares = dealt_blocks(rank, receivers.size(), kBlock);
      two[static_cast<std::size_t>(k)] =
          build_gather_operator(receivers, room.mesh, room.traced, 32, 128, 5, false, &shares);
    });
  }
  for (std::thread& t : threads) t.join();
  // Each rank holds its own blocks' rows, those of one process bit for bit, the others empty.
  EXPECT_EQ(two[0].matrix.nonZeros() + two[1].matrix.nonZeros(), one.matrix.nonZeros());
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& g = two[k].matrix;
    EXPECT_EQ(two[k].rays, one.rays);
    ASSERT_EQ(g.rows(), one.matrix.rows());
    for (Eigen::Index r = 0; r < g.rows(); ++r) {
      const bool mine = (static_cast<std::size_t>(r) / kBlock) % 2 == k;
      const int* go = g.outerIndexPtr();
      const int* oo = one.matrix.outerIndexPtr();
      if (!mine) {
        ASSERT_EQ(go[r + 1], go[r]) << "rank " << k << " row " << r;
        continue;
      }
      ASSERT_EQ(go[r + 1] - go[r], oo[r + 1] - oo[r]) << "rank " << k << " row " << r;
      EXPECT_TRUE(std::equal(g.innerIndexPtr() + go[r], g.innerIndexPtr() + go[r + 1],
                             one.matrix.innerIndexPtr() + oo[r]));
      EXPECT_TRUE(std::equal(g.valuePtr() + go[r], g.valuePtr() + go[r + 1],
                             one.matrix.valuePtr() + oo[r]));
    }
  }
}

TEST(RankExchange, ThreeRanksAsThreadsBounceTheirRowsBitForBitAsOneProcess) {
  const RankRoom room;
  const Receivers& receivers = room.receivers;
  const GatherOperator one =
      build_gather_operator(receivers, room.mesh, room.traced, 32, 128, 5, false);
  // Two columns of direct light: a ramp over the receivers and a patch.
  const auto n = static_cast<Eigen::Index>(receivers.size());
  Eigen::MatrixXf direct(n, 2);
  for (Eigen::Index r = 0; r < n; ++r) {
    direct(r, 0) = 1.0f + 0.01f * static_cast<float>(r % 97);
    direct(r, 1) = r % 5 == 0 ? 3.0f : 0.0f;
  }
  const BounceSettings settings;
  const BounceResult alone = solve_bounces(one, receivers, direct, settings, false);
  constexpr int kRanks = 3;
  ThreadRanks ranks(kRanks);
  std::vector<BounceResult> results(kRanks);
  std::vector<std::uint64_t> received(kRanks);
  std::vector<std::thread> threads;
  for (int k = 0; k < kRanks; ++k) {
    threads.emplace_back([&, k] {
      ThreadRanks::Rank rank(ranks, k);
      const RankShares shares = dealt_blocks(rank, receivers.size(), kBlock);
      const GatherOperator g =
          build_gather_operator(receivers, room.mesh, room.traced, 32, 128, 5, false, &shares);
      Eigen::MatrixXf mine(static_cast<Eigen::Index>(shares.my_receivers()), 2);
      for (Eigen::Index l = 0; l < mine.rows(); ++l) {
        mine.row(l) = direct.row(
            static_cast<Eigen::Index>(shares.receiver_of_local_row(static_cast<std::size_t>(l))));
      }
      results[static_cast<std::size_t>(k)] =
          solve_bounces(g, receivers, mine, settings, false, &shares);
    });
  }
  for (std::thread& t : threads) t.join();
  for (int k = 0; k < kRanks; ++k) {
    const BounceResult& r = results[static_cast<std::size_t>(k)];
    EXPECT_EQ(r.bounces, alone.bounces);
    ThreadRanks::Rank rank(ranks, k);
    const RankShares shares = dealt_blocks(rank, receivers.size(), kBlock);
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(r.indirect[c].rows(), static_cast<Eigen::Index>(shares.my_receivers()));
      for (Eigen::Index l = 0; l < r.indirect[c].rows(); ++l) {
        const auto row =
            static_cast<Eigen::Index>(shares.receiver_of_local_row(static_cast<std::size_t>(l)));
        ASSERT_EQ(r.indirect[c](l, 0), alone.indirect[c](row, 0)) << "rank " << k << " row " << row;
        ASSERT_EQ(r.indirect[c](l, 1), alone.indirect[c](row, 1)) << "rank " << k << " row " << row;
      }
    }
  }
}

TEST(RankExchange, BlockRecordsReachRankZeroInTheOrderOfTheBlocks) {
  // 23 blocks of 10 receivers dealt among 3 ranks; records of varying length, two blocks a round.
  constexpr int kRanks = 3;
  ThreadRanks ranks(kRanks);
  std::vector<std::uint8_t> received;
  std::vector<std::size_t> sizes;
  std::vector<std::thread> threads;
  for (int k = 0; k < kRanks; ++k) {
    threads.emplace_back([&, k] {
      ThreadRanks::Rank rank(ranks, k);
      const RankShares shares = dealt_blocks(rank, 225, 10);
      const std::vector<std::size_t> mine = shares.my_blocks();
      std::vector<std::uint8_t> record;
      const RecordSink sink = [&](std::span<const std::uint8_t> r) {
        received.insert(received.end(), r.begin(), r.end());
        sizes.push_back(r.size());
      };
      gather_block_records(
          shares,
          [&](std::size_t i) {
            record.assign(mine[i] % 4, static_cast<std::uint8_t>(mine[i]));
            return std::span<const std::uint8_t>(record);
          },
          2, k == 0 ? &sink : nullptr);
    });
  }
  for (std::thread& t : threads) t.join();
  ASSERT_EQ(sizes.size(), 23u);
  std::size_t at = 0;
  for (std::size_t b = 0; b < 23; ++b) {
    ASSERT_EQ(sizes[b], b % 4) << "block " << b;
    for (std::size_t i = 0; i < sizes[b]; ++i) ASSERT_EQ(received[at + i], b);
    at += sizes[b];
  }
}

TEST(RankExchange, AllToAllHandsEachRankThePiecesMeantForIt) {
  constexpr int kRanks = 3;
  ThreadRanks ranks(kRanks);
  std::vector<std::vector<std::vector<std::uint8_t>>> got(kRanks);
  std::vector<std::thread> threads;
  for (int k = 0; k < kRanks; ++k) {
    threads.emplace_back([&, k] {
      ThreadRanks::Rank rank(ranks, k);
      std::vector<std::vector<std::uint8_t>> to(kRanks);
      // Rank k sends rank j (k + 1) · j bytes of value 10k + j.
      for (int j = 0; j < kRanks; ++j) {
        to[static_cast<std::size_t>(j)].assign(static_cast<std::size_t>((k + 1) * j),
                                               static_cast<std::uint8_t>(10 * k + j));
      }
      got[static_cast<std::size_t>(k)] = rank.all_to_all(std::move(to));
    });
  }
  for (std::thread& t : threads) t.join();
  for (int j = 0; j < kRanks; ++j) {
    ASSERT_EQ(got[j].size(), std::size_t{kRanks});
    for (int k = 0; k < kRanks; ++k) {
      EXPECT_EQ(got[j][k], std::vector<std::uint8_t>(static_cast<std::size_t>((k + 1) * j),
                                                     static_cast<std::uint8_t>(10 * k + j)))
          << "from " << k << " to " << j;
    }
  }
  EXPECT_THROW(SingleProcess().all_to_all({}), std::invalid_argument);
}

TEST(RankExchange, ShareBlockRecordsFillsEveryRanksBlocks) {
  // 150 receivers in blocks of 64 among 4 ranks: the fourth has none.
  ThreadRanks ranks(4);
  std::vector<std::vector<std::vector<std::uint32_t>>> records(4);
  std::vector<std::thread> threads;
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&, k] {
      ThreadRanks::Rank rank(ranks, k);
      const RankShares shares = dealt_blocks(rank, 150, 64);
      std::vector<std::vector<std::uint32_t>> mine(shares.block_count());
      for (const std::size_t b : shares.my_blocks()) mine[b].assign(b + 1, std::uint32_t(10 * b));
      share_block_records(
          shares,
          [&](std::size_t b, std::vector<std::uint8_t>& bytes) {
            put_values<std::uint32_t>(bytes, mine[b]);
          },
          [&](std::size_t b, std::span<const std::uint8_t> theirs, std::size_t& at) {
            mine[b] = take_values<std::uint32_t>(theirs, at);
          });
      records[static_cast<std::size_t>(k)] = std::move(mine);
    });
  }
  for (std::thread& t : threads) t.join();
  for (int k = 0; k < 4; ++k) {
    ASSERT_EQ(records[k].size(), 3u);
    for (std::size_t b = 0; b < 3; ++b) {
      EXPECT_EQ(records[k][b], std::vector<std::uint32_t>(b + 1, std::uint32_t(10 * b)))
          << "rank " << k << " block " << b;
    }
  }
}

TEST(RankShares, LocalRowsAreTheRanksBlocksOneAfterAnother) {
  // 150 receivers in blocks of 64 among 2 ranks: rank 0 holds blocks 0 and 2 (the short one).
  ThreadRanks ranks(2);
  ThreadRanks::Rank zero(ranks, 0);
  const RankShares shares = dealt_blocks(zero, 150, 64);
  EXPECT_EQ(shares.my_receivers(), 64u + 22u);
  for (std::size_t l = 0; l < shares.my_receivers(); ++l) {
    const std::size_t r = shares.receiver_of_local_row(l);
    EXPECT_EQ(r, l < 64 ? l : 128 + (l - 64));
    EXPECT_EQ(shares.owner(r), 0);
    EXPECT_EQ(shares.local_row(r), l);
  }
  EXPECT_EQ(shares.owner(64), 1);
  EXPECT_EQ(shares.my_receivers_below(100), 64u);
  EXPECT_EQ(shares.my_receivers_below(140), 64u + 12u);
}

}  // namespace
}  // namespace relight

// The ranks of `mpirun -n N relight precompute` over Open MPI: the exchange the precompute's stages
// ask for (engine/ranks.h) as MPI collectives on MPI_COMM_WORLD. MPI is started only when a
// launcher started this process: `relight precompute` alone never touches MPI and needs no
// launcher. Pinned by tests/cli/mpi_precompute_test.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/ranks.h"

namespace relight {

// True when an MPI launcher (mpirun, mpiexec, srun) started this process: its environment names
// a rank (Open MPI's OMPI_COMM_WORLD_RANK, PMIx's PMIX_RANK, PMI's PMI_RANK).
bool launched_by_mpi();

// MPI_Init on construction, MPI_Finalize on destruction; one per process.
class MpiRanks final : public RankExchange {
 public:
  MpiRanks();
  ~MpiRanks() override;
  MpiRanks(const MpiRanks&) = delete;
  MpiRanks& operator=(const MpiRanks&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  // Sizes first, then each rank's bytes broadcast from it in pieces of at most 1 GiB (MPI's
  // counts are int).
  std::vector<std::vector<std::uint8_t>> all_gather(std::span<const std::uint8_t> mine) override;
  // Sizes first (MPI_Alltoall), then N − 1 rounds of MPI_Sendrecv, in round r to rank + r and
  // from rank − r, in pieces of at most 1 GiB: each rank receives only its own pieces.
  std::vector<std::vector<std::uint8_t>> all_to_all(
      std::vector<std::vector<std::uint8_t>> to) override;
  // Sizes (MPI_Gather), then each rank's bytes sent to rank 0 in pieces of at most 1 GiB.
  std::vector<std::vector<std::uint8_t>> gather_to_root(
      std::span<const std::uint8_t> mine) override;
  double exchange_seconds() const override { return exchange_seconds_; }
  std::uint64_t exchange_bytes() const override { return exchange_bytes_; }
  // Ranks on this machine (MPI_COMM_TYPE_SHARED): they share its cores.
  int ranks_here() const { return ranks_here_; }
  // Ends every rank's process (MPI_Abort): for a failure of some ranks while the others may
  // wait in an exchange.
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0, size_ = 1, ranks_here_ = 1;
  double exchange_seconds_ = 0;
  std::uint64_t exchange_bytes_ = 0;
};

}  // namespace relight

#include "cli/mpi_ranks.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>

// The C API only: without these, mpi.h pulls in the deprecated C++ bindings.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

namespace relight {

namespace {

constexpr std::size_t kPiece = std::size_t{1} << 30;  // bytes per broadcast

void check(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

}  // namespace

bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

MpiRanks::MpiRanks() {
  check(MPI_Init(nullptr, nullptr), "MPI_Init");
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
  MPI_Comm here = MPI_COMM_NULL;
  check(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &here),
        "MPI_Comm_split_type");
  check(MPI_Comm_size(here, &ranks_here_), "MPI_Comm_size");
  MPI_Comm_free(&here);
}

MpiRanks::~MpiRanks() {
  MPI_Finalize();
}

std::vector<std::vector<std::uint8_t>> MpiRanks::all_gather(std::span<const std::uint8_t> mine) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::uint64_t> sizes(static_cast<std::size_t>(size_));
  const std::uint64_t my_size = mine.size();
  check(MPI_Allgather(&my_size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD),
        "MPI_Allgather");
  std::vector<std::vector<std::uint8_t>> out(static_cast<std::size_t>(size_));
  for (int k = 0; k < size_; ++k) {
    std::vector<std::uint8_t>& bytes = out[static_cast<std::size_t>(k)];
    if (k == rank_) {
      bytes.assign(mine.begin(), mine.end());
    } else {
      bytes.resize(static_cast<std::size_t>(sizes[static_cast<std::size_t>(k)]));
      exchange_bytes_ += bytes.size();
    }
    for (std::size_t at = 0; at < bytes.size(); at += kPiece) {
      const int count = static_cast<int>(std::min(kPiece, bytes.size() - at));
      check(MPI_Bcast(bytes.data() + at, count, MPI_BYTE, k, MPI_COMM_WORLD), "MPI_Bcast");
    }
  }
  exchange_seconds_ +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void MpiRanks::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);  // MPI_Abort does not return; if it did, this process ends anyway
}

}  // namespace relight

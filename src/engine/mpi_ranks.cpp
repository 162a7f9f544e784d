#include "engine/mpi_ranks.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

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

// Posts the non-blocking receives (into `bytes`) or sends (from it) of a buffer in pieces of at
// most kPiece bytes, MPI's counts being int; the peer posts the same pieces, matched in order.
void post_receives(std::span<std::uint8_t> bytes, int source, int tag,
                   std::vector<MPI_Request>& requests) {
  for (std::size_t at = 0; at < bytes.size(); at += kPiece) {
    requests.emplace_back();
    check(MPI_Irecv(bytes.data() + at, static_cast<int>(std::min(kPiece, bytes.size() - at)),
                    MPI_BYTE, source, tag, MPI_COMM_WORLD, &requests.back()),
          "MPI_Irecv");
  }
}

void post_sends(std::span<const std::uint8_t> bytes, int dest, int tag,
                std::vector<MPI_Request>& requests) {
  for (std::size_t at = 0; at < bytes.size(); at += kPiece) {
    requests.emplace_back();
    check(MPI_Isend(bytes.data() + at, static_cast<int>(std::min(kPiece, bytes.size() - at)),
                    MPI_BYTE, dest, tag, MPI_COMM_WORLD, &requests.back()),
          "MPI_Isend");
  }
}

void wait_all(std::vector<MPI_Request>& requests) {
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE),
        "MPI_Waitall");
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

std::vector<std::vector<std::uint8_t>> MpiRanks::all_to_all(
    std::vector<std::vector<std::uint8_t>> to) {
  if (to.size() != static_cast<std::size_t>(size_)) {
    throw std::invalid_argument("rank exchange: all_to_all needs one piece per rank");
  }
  const auto start = std::chrono::steady_clock::now();
  const auto n = static_cast<std::size_t>(size_);
  std::vector<std::uint64_t> send_sizes(n), receive_sizes(n);
  for (std::size_t k = 0; k < n; ++k) send_sizes[k] = to[k].size();
  check(MPI_Alltoall(send_sizes.data(), 1, MPI_UINT64_T, receive_sizes.data(), 1, MPI_UINT64_T,
                     MPI_COMM_WORLD),
        "MPI_Alltoall");
  std::vector<std::vector<std::uint8_t>> from(n);
  from[static_cast<std::size_t>(rank_)] = std::move(to[static_cast<std::size_t>(rank_)]);
  for (int r = 1; r < size_; ++r) {
    const int dest = (rank_ + r) % size_, source = (rank_ - r + size_) % size_;
    const std::vector<std::uint8_t>& out = to[static_cast<std::size_t>(dest)];
    std::vector<std::uint8_t>& in = from[static_cast<std::size_t>(source)];
    in.resize(static_cast<std::size_t>(receive_sizes[static_cast<std::size_t>(source)]));
    exchange_bytes_ += in.size();
    // Each side knows the other's size, so both post the same pieces (matched in order).
    std::vector<MPI_Request> requests;
    post_receives(in, source, 0, requests);
    post_sends(out, dest, 0, requests);
    wait_all(requests);
  }
  exchange_seconds_ +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return from;
}

std::vector<std::vector<std::uint8_t>> MpiRanks::gather_to_root(
    std::span<const std::uint8_t> mine) {
  const auto start = std::chrono::steady_clock::now();
  const auto n = static_cast<std::size_t>(size_);
  const std::uint64_t my_size = mine.size();
  std::vector<std::uint64_t> sizes(n);
  check(MPI_Gather(&my_size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, 0, MPI_COMM_WORLD),
        "MPI_Gather");
  std::vector<std::vector<std::uint8_t>> out;
  std::vector<MPI_Request> requests;
  if (rank_ == 0) {
    out.resize(n);
    out[0].assign(mine.begin(), mine.end());
    for (std::size_t k = 1; k < n; ++k) {
      out[k].resize(static_cast<std::size_t>(sizes[k]));
      exchange_bytes_ += out[k].size();
      post_receives(out[k], static_cast<int>(k), 1, requests);
    }
  } else {
    post_sends(mine, 0, 1, requests);
  }
  wait_all(requests);
  exchange_seconds_ +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void MpiRanks::abort(int code) const {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);  // MPI_Abort does not return; if it did, this process ends anyway
}

}  // namespace relight

#include "distributed/communicator.hpp"

#include <algorithm>
#include <cstdlib>

#include <mpi.h>

namespace oasis::distributed {
namespace {

// Pieces of one message: far below MPI's int count limit, and small enough that a piece in
// flight adds little to a rank's peak memory.
constexpr std::size_t kPieceBytes = std::size_t{1} << 28;

std::size_t pieces(std::size_t bytes) {
  return (bytes + kPieceBytes - 1) / kPieceBytes;
}

int piece_length(std::size_t bytes, std::size_t piece) {
  const std::size_t begin = piece * kPieceBytes;
  return begin >= bytes ? 0 : static_cast<int>(std::min(kPieceBytes, bytes - begin));
}

}  // namespace

Communicator::Communicator(int& argc, char**& argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  rank_ = static_cast<std::uint32_t>(rank);
  size_ = static_cast<std::uint32_t>(size);
}

Communicator::~Communicator() {
  MPI_Finalize();
}

// Pairwise: in step k every rank sends to rank + k and receives from rank - k, so each step
// is a permutation, and a sent buffer is freed before the next step.
std::vector<Bytes> Communicator::exchange(std::vector<Bytes>& outgoing) const {
  outgoing.resize(size_);
  std::vector<std::uint64_t> send_sizes(size_);
  std::vector<std::uint64_t> receive_sizes(size_);
  for (std::uint32_t q = 0; q < size_; ++q)
    send_sizes[q] = outgoing[q].size();
  MPI_Alltoall(send_sizes.data(), 1, MPI_UINT64_T, receive_sizes.data(), 1, MPI_UINT64_T,
               MPI_COMM_WORLD);
  std::vector<Bytes> incoming(size_);
  incoming[rank_] = std::move(outgoing[rank_]);
  outgoing[rank_] = Bytes();
  for (std::uint32_t step = 1; step < size_; ++step) {
    const std::uint32_t to = (rank_ + step) % size_;
    const std::uint32_t from = (rank_ + size_ - step) % size_;
    Bytes& sent = outgoing[to];
    Bytes& received = incoming[from];
    received.resize(receive_sizes[from]);
    // Each side counts its own pieces: as many receives as the sender sends pieces.
    std::vector<MPI_Request> requests;
    for (std::size_t piece = 0; piece < pieces(received.size()); ++piece) {
      MPI_Irecv(received.data() + piece * kPieceBytes, piece_length(received.size(), piece),
                MPI_BYTE, static_cast<int>(from), 0, MPI_COMM_WORLD, &requests.emplace_back());
    }
    for (std::size_t piece = 0; piece < pieces(sent.size()); ++piece) {
      MPI_Isend(sent.data() + piece * kPieceBytes, piece_length(sent.size(), piece), MPI_BYTE,
                static_cast<int>(to), 0, MPI_COMM_WORLD, &requests.emplace_back());
    }
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    sent = Bytes();
  }
  return incoming;
}

std::vector<std::string> Communicator::all_gather(std::string_view mine) const {
  std::vector<Bytes> outgoing(size_);
  for (std::uint32_t q = 0; q < size_; ++q)
    outgoing[q].assign(mine.begin(), mine.end());
  std::vector<Bytes> incoming = exchange(outgoing);
  std::vector<std::string> result(size_);
  for (std::uint32_t q = 0; q < size_; ++q)
    result[q].assign(incoming[q].begin(), incoming[q].end());
  return result;
}

std::vector<std::uint64_t> Communicator::all_gather(std::uint64_t mine) const {
  std::vector<std::uint64_t> result(size_);
  MPI_Allgather(&mine, 1, MPI_UINT64_T, result.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
  return result;
}

std::uint64_t Communicator::sum(std::uint64_t mine) const {
  std::uint64_t result = 0;
  MPI_Allreduce(&mine, &result, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
  return result;
}

std::uint64_t Communicator::max(std::uint64_t mine) const {
  std::uint64_t result = 0;
  MPI_Allreduce(&mine, &result, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
  return result;
}

void Communicator::barrier() const {
  MPI_Barrier(MPI_COMM_WORLD);
}

void Communicator::abort(int status) const {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::_Exit(status);  // MPI_Abort does not return; this tells the compiler so
}

}  // namespace oasis::distributed

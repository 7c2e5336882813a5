#include "talus/parallel/communicator.h"

#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace talus {

namespace {
// mpirun (Open MPI's launcher, or PMIx under Slurm's srun) leaves these in a rank's
// environment; without them the process is alone and never touches MPI.
bool launched_by_mpirun() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") || std::getenv("PMI_RANK");
}

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI error in ") + what);
}

void finalize_at_exit() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}
}  // namespace

const Communicator& Communicator::world() {
  static const Communicator comm = [] {
    if (!launched_by_mpirun()) return Communicator(0, 1, false);
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) {
      int provided = 0;
      // Threads of a rank (OpenMP) never call MPI: only the master thread communicates.
      check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
      std::atexit(finalize_at_exit);
    }
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    return Communicator(rank, size, true);
  }();
  return comm;
}

const Communicator& Communicator::alone() {
  static const Communicator comm(0, 1, false);
  return comm;
}

double Communicator::max(double x) const {
  if (!mpi_) return x;
  double r = x;
  check(MPI_Allreduce(&x, &r, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  return r;
}

double Communicator::sum(double x) const {
  if (!mpi_) return x;
  double r = x;
  check(MPI_Allreduce(&x, &r, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return r;
}

std::uint64_t Communicator::sum(std::uint64_t x) const {
  if (!mpi_) return x;
  std::uint64_t r = x;
  check(MPI_Allreduce(&x, &r, 1, MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  return r;
}

bool Communicator::any(bool x) const {
  if (!mpi_) return x;
  int in = x ? 1 : 0, r = in;
  check(MPI_Allreduce(&in, &r, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD), "MPI_Allreduce");
  return r != 0;
}

void Communicator::sum_in_place(std::vector<double>& values) const {
  if (!mpi_ || values.empty()) return;
  check(MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM,
                      MPI_COMM_WORLD),
        "MPI_Allreduce");
}

void Communicator::barrier() const {
  if (mpi_) check(MPI_Barrier(MPI_COMM_WORLD), "MPI_Barrier");
}

std::vector<std::byte> Communicator::exchange(const std::vector<std::byte>& out, int to, int from, int tag) const {
  if (!mpi_) return from == rank_ ? out : std::vector<std::byte>{};
  if (to == rank_ && from == rank_) return out;
  if (to < 0) to = MPI_PROC_NULL;
  if (from < 0) from = MPI_PROC_NULL;
  // Sizes first, so that the receiver can size its buffer; then the bytes.
  std::uint64_t out_size = out.size(), in_size = 0;
  check(MPI_Sendrecv(&out_size, 1, MPI_UINT64_T, to, tag, &in_size, 1, MPI_UINT64_T, from, tag, MPI_COMM_WORLD,
                     MPI_STATUS_IGNORE),
        "MPI_Sendrecv");
  std::vector<std::byte> in(in_size);
  check(MPI_Sendrecv(out.data(), static_cast<int>(out_size), MPI_BYTE, to, tag + 1, in.data(),
                     static_cast<int>(in_size), MPI_BYTE, from, tag + 1, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Sendrecv");
  return in;
}

void Communicator::exchange_sized(const std::vector<std::byte>& out, int to, int from, int tag,
                                  std::vector<std::byte>& in) const {
  if (!mpi_ || (to == rank_ && from == rank_)) {
    if (from == rank_) in = out;
    return;
  }
  if (to < 0) to = MPI_PROC_NULL;
  if (from < 0) from = MPI_PROC_NULL;
  check(MPI_Sendrecv(out.data(), static_cast<int>(out.size()), MPI_BYTE, to, tag, in.data(), static_cast<int>(in.size()),
                     MPI_BYTE, from, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Sendrecv");
}

std::vector<std::byte> Communicator::all_gather(const std::vector<std::byte>& mine) const {
  if (!mpi_) return mine;
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(size_), displs(size_, 0);
  check(MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD), "MPI_Allgather");
  for (int r = 1; r < size_; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<std::byte> all(static_cast<std::size_t>(displs.back() + counts.back()));
  check(MPI_Allgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, MPI_COMM_WORLD),
        "MPI_Allgatherv");
  return all;
}

std::vector<std::byte> Communicator::gather(const std::vector<std::byte>& mine, int root) const {
  if (!mpi_) return mine;
  // Message by message, each in pieces under 2^31 bytes (MPI counts are int), so the total on
  // the root may pass 2 GiB: a checkpoint of 10^7 particles does.
  constexpr std::size_t kPiece = std::size_t{1} << 30;
  constexpr int kTag = 7100;
  if (rank_ != root) {
    const std::uint64_t n = mine.size();
    check(MPI_Send(&n, 1, MPI_UINT64_T, root, kTag, MPI_COMM_WORLD), "MPI_Send");
    for (std::size_t at = 0; at < mine.size(); at += kPiece)
      check(MPI_Send(mine.data() + at, static_cast<int>(std::min(kPiece, mine.size() - at)), MPI_BYTE, root, kTag,
                     MPI_COMM_WORLD),
            "MPI_Send");
    return {};
  }
  std::vector<std::byte> all;
  for (int r = 0; r < size_; ++r) {
    if (r == root) {
      all.insert(all.end(), mine.begin(), mine.end());
      continue;
    }
    std::uint64_t n = 0;
    check(MPI_Recv(&n, 1, MPI_UINT64_T, r, kTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE), "MPI_Recv");
    const std::size_t from = all.size();
    all.resize(from + n);
    for (std::size_t at = 0; at < n; at += kPiece)
      check(MPI_Recv(all.data() + from + at, static_cast<int>(std::min<std::size_t>(kPiece, n - at)), MPI_BYTE, r, kTag,
                     MPI_COMM_WORLD, MPI_STATUS_IGNORE),
            "MPI_Recv");
  }
  return all;
}

}  // namespace talus

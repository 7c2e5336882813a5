// talus-comm-bench: what a message between two ranks costs on this machine, the input of the
// scaling model in docs/scaling.md. Run with two ranks:
//   mpirun -n 2 build/talus-comm-bench
// Prints METRIC lines: ping-pong latency and bandwidth, and the time of a halo exchange (each
// rank sends its ghosts' state to both neighbours of a ring and receives theirs, as a domain
// decomposition along one axis does every step) against the number of ghosts.
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

// Best of `reps` timings of `body` (seconds), all ranks in step.
template <class Body>
double best_time(int reps, Body body) {
  double best = 1e30;
  for (int r = 0; r < reps; ++r) {
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    body();
    best = std::min(best, MPI_Wtime() - t0);
  }
  double worst_rank = 0;  // a step waits for the slowest rank
  MPI_Allreduce(&best, &worst_rank, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return worst_rank;
}

// One round trip of `bytes` between ranks 0 and 1, `trips` times; seconds per one-way message.
double ping_pong(int rank, std::size_t bytes, int trips) {
  std::vector<char> buffer(std::max<std::size_t>(bytes, 1));
  const double t = best_time(5, [&] {
    for (int k = 0; k < trips; ++k) {
      if (rank == 0) {
        MPI_Send(buffer.data(), static_cast<int>(bytes), MPI_CHAR, 1, 0, MPI_COMM_WORLD);
        MPI_Recv(buffer.data(), static_cast<int>(bytes), MPI_CHAR, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      } else if (rank == 1) {
        MPI_Recv(buffer.data(), static_cast<int>(bytes), MPI_CHAR, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        MPI_Send(buffer.data(), static_cast<int>(bytes), MPI_CHAR, 0, 0, MPI_COMM_WORLD);
      }
    }
  });
  return t / (2.0 * trips);
}

// Halo exchange of `ghosts` particles of `doubles` values each to each of both ring neighbours,
// packed from and unpacked into particle arrays by index lists, as an engine would; seconds.
double halo_exchange(int rank, int size, std::size_t ghosts, int doubles, int steps) {
  const std::size_t owned = 4 * ghosts + 1024;
  std::vector<double> state(owned * doubles, 1.0), ghost_state(2 * ghosts * doubles);
  std::vector<std::size_t> send_index(ghosts);
  for (std::size_t g = 0; g < ghosts; ++g) send_index[g] = (g * 7919) % owned;  // scattered, as after sorting
  std::vector<double> send_lo(ghosts * doubles), send_hi(ghosts * doubles);
  const int lo = (rank + size - 1) % size, hi = (rank + 1) % size;
  const int count = static_cast<int>(ghosts * doubles);
  return best_time(5, [&] {
    for (int s = 0; s < steps; ++s) {
      for (std::size_t g = 0; g < ghosts; ++g)
        for (int c = 0; c < doubles; ++c) {
          send_lo[g * doubles + c] = state[send_index[g] * doubles + c];
          send_hi[g * doubles + c] = state[send_index[g] * doubles + c];
        }
      MPI_Sendrecv(send_lo.data(), count, MPI_DOUBLE, lo, 1, ghost_state.data(), count, MPI_DOUBLE, hi, 1,
                   MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      MPI_Sendrecv(send_hi.data(), count, MPI_DOUBLE, hi, 2, ghost_state.data() + count, count, MPI_DOUBLE, lo, 2,
                   MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
  }) / steps;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size < 2) {
    if (rank == 0) std::fprintf(stderr, "talus-comm-bench: run with two ranks: mpirun -n 2 talus-comm-bench\n");
    MPI_Finalize();
    return 2;
  }
  const double latency = ping_pong(rank, 8, 2000);
  const std::size_t big = 8u << 20;
  const double big_time = ping_pong(rank, big, 20);
  if (rank == 0) {
    std::printf("METRIC comm_latency %.3f us\n", latency * 1e6);
    std::printf("METRIC comm_bandwidth %.3f GB/s\n", big / big_time / 1e9);
  }
  // Forward: position, velocity, angular velocity (9 doubles); with orientation 13. Reverse:
  // force and torque (6 doubles). N ghosts go to each neighbour, so a rank receives 2N.
  for (int doubles : {9, 6}) {
    for (std::size_t ghosts : {100u, 1000u, 4000u, 16000u, 64000u}) {
      const double t = halo_exchange(rank, size, ghosts, doubles, 50);
      if (rank == 0)
        std::printf("METRIC comm_halo_%s_%zu %.3f us (%.4f us per ghost received)\n",
                    doubles == 9 ? "forward" : "reverse", ghosts, t * 1e6, t * 1e6 / (2.0 * ghosts));
    }
  }
  MPI_Finalize();
  return 0;
}

#pragma once
// The ranks a run is spread over: Open MPI's world communicator when the process was started by
// mpirun, otherwise a single rank that needs no MPI at all (the binary runs without a launcher).
// Messages are byte buffers; a rank sending to itself copies.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace talus {

class Communicator {
 public:
  // The process's communicator: MPI's world if launched by mpirun (initialised on first use,
  // finalised at exit), else one rank.
  static const Communicator& world();
  // One rank that never asks MPI anything, under mpirun too: the ranks of a world that is not
  // distributed.
  static const Communicator& alone();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool distributed() const { return size_ > 1; }

  double max(double x) const;
  double sum(double x) const;
  std::uint64_t sum(std::uint64_t x) const;
  bool any(bool x) const;
  void sum_in_place(std::vector<double>& values) const;  ///< element-wise over ranks
  void barrier() const;

  // Sends `out` to rank `to` while receiving from rank `from` (a matched pair of one exchange
  // along a ring: every rank calls it with the same tag). Returns what arrived. A rank of -1
  // is nobody: nothing is sent, or nothing arrives.
  std::vector<std::byte> exchange(const std::vector<std::byte>& out, int to, int from, int tag) const;
  // The same when the receiver knows how many bytes come (the halo's every-step exchanges): one
  // message each way into `in`, sized by the caller.
  void exchange_sized(const std::vector<std::byte>& out, int to, int from, int tag, std::vector<std::byte>& in) const;
  // Every rank's bytes, concatenated in rank order, on every rank.
  std::vector<std::byte> all_gather(const std::vector<std::byte>& mine) const;
  // The same on rank `root` only (the others get nothing back): what one writer needs, without
  // a copy of everything on every rank.
  std::vector<std::byte> gather(const std::vector<std::byte>& mine, int root) const;

 private:
  Communicator(int rank, int size, bool mpi) : rank_(rank), size_(size), mpi_(mpi) {}
  int rank_ = 0, size_ = 1;
  bool mpi_ = false;
};

// Appends trivially copyable values to a byte buffer, and reads them back in order.
class ByteWriter {
 public:
  explicit ByteWriter(std::vector<std::byte>& out) : out_(out) {}
  template <class T> void put(const T& value) {
    const std::size_t at = out_.size();
    out_.resize(at + sizeof(T));
    std::memcpy(out_.data() + at, &value, sizeof(T));
  }
 private:
  std::vector<std::byte>& out_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::vector<std::byte>& in) : in_(in) {}
  template <class T> T get() {
    T value;
    std::memcpy(&value, in_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  bool done() const { return at_ >= in_.size(); }
 private:
  const std::vector<std::byte>& in_;
  std::size_t at_ = 0;
};

}  // namespace talus

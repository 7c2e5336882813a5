#pragma once
// The checkpoints of a results folder, in DIR/checkpoints/:
//   checkpoint_<step>.h5   the last `keep` checkpoints (step zero-padded to 10 digits)
//   latest.h5              a symbolic link to the newest
// Every file is complete: a checkpoint is written to a temporary name and renamed, and the
// link is replaced by renaming a new one over it. Temporaries left by a killed run
// (`*.tmp.<pid>`) are never taken for checkpoints and are removed by the next run.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "talus/io/checkpoint_file.h"

namespace talus {

class CheckpointSeries {
 public:
  CheckpointSeries(std::filesystem::path results_dir, std::size_t keep);

  // Writes checkpoint_<step>.h5, points latest.h5 at it, drops the oldest beyond `keep`.
  void write(const io::Checkpoint& checkpoint);
  // A checkpoint of the same run that another rank writes: counted as written here, so every
  // rank of a distributed run decides alike when the last one is due.
  void count_written_elsewhere(std::uint64_t step);

  const std::filesystem::path& directory() const { return dir_; }
  std::size_t written() const { return written_; }
  std::uintmax_t last_bytes() const { return last_bytes_; }
  std::uint64_t last_step() const { return last_step_; }

  // The complete checkpoints of a checkpoints folder, oldest (lowest step) first.
  static std::vector<std::filesystem::path> list(const std::filesystem::path& checkpoints_dir);
  // DIR/checkpoints/latest.h5 of a results folder.
  static std::filesystem::path latest(const std::filesystem::path& results_dir);
  static std::string file_name(std::uint64_t step);

 private:
  std::filesystem::path dir_;
  std::size_t keep_;
  std::size_t written_ = 0;
  std::uintmax_t last_bytes_ = 0;
  std::uint64_t last_step_ = 0;
};

}  // namespace talus

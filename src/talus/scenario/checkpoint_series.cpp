#include "talus/scenario/checkpoint_series.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <regex>

#include "talus/io/posix_file.h"

namespace talus {

namespace {

namespace fs = std::filesystem;

const std::regex& checkpoint_name() {
  static const std::regex name(R"(checkpoint_(\d+)\.h5)");
  return name;
}

bool is_temporary(const std::string& name) { return name.find(".h5.tmp.") != std::string::npos; }

}  // namespace

std::string CheckpointSeries::file_name(std::uint64_t step) {
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint_%010llu.h5", static_cast<unsigned long long>(step));
  return name;
}

fs::path CheckpointSeries::latest(const fs::path& results_dir) { return results_dir / "checkpoints" / "latest.h5"; }

std::vector<fs::path> CheckpointSeries::list(const fs::path& dir) {
  std::vector<std::pair<std::uint64_t, fs::path>> found;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    std::smatch m;
    if (entry.is_regular_file() && std::regex_match(name, m, checkpoint_name()))
      found.emplace_back(std::stoull(m[1].str()), entry.path());
  }
  std::sort(found.begin(), found.end());
  std::vector<fs::path> out;
  for (auto& f : found) out.push_back(f.second);
  return out;
}

CheckpointSeries::CheckpointSeries(fs::path results_dir, std::size_t keep)
    : dir_(std::move(results_dir) / "checkpoints"), keep_(std::max<std::size_t>(1, keep)) {
  fs::create_directories(dir_);
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir_, ec))
    if (is_temporary(entry.path().filename().string())) fs::remove(entry.path(), ec);
}

void CheckpointSeries::write(const io::Checkpoint& checkpoint) {
  const std::string name = file_name(checkpoint.world.steps);
  const fs::path file = dir_ / name;
  io::write_checkpoint(file, checkpoint);

  // latest.h5: a new link renamed over the old one, so it always names a complete file.
  const fs::path link = latest(dir_.parent_path());
  const fs::path temp = link.string() + ".tmp." + std::to_string(::getpid());
  std::error_code ec;
  fs::remove(temp, ec);
  fs::create_symlink(name, temp);
  io::rename_durably(temp, link);

  const std::vector<fs::path> all = list(dir_);
  for (std::size_t k = 0; k + keep_ < all.size(); ++k)
    if (all[k].filename() != name) fs::remove(all[k], ec);

  last_bytes_ = fs::file_size(file);
  last_step_ = checkpoint.world.steps;
  ++written_;
}

void CheckpointSeries::count_written_elsewhere(std::uint64_t step) {
  last_step_ = step;
  ++written_;
}

}  // namespace talus

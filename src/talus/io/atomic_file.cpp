#include "talus/io/atomic_file.h"

#include <stdexcept>
#include <unistd.h>
#include <utility>

namespace talus::io {

namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

// Same directory as the target, so the final rename stays within one file system (and is
// atomic); the pid keeps two processes writing the same target from sharing a temporary.
std::filesystem::path temp_name(const std::filesystem::path& target) {
  return target.string() + ".tmp." + std::to_string(::getpid());
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target)
    : target_(std::move(target)), temp_(temp_name(target_)), file_(temp_) {}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : target_(std::move(other.target_)),
      temp_(std::exchange(other.temp_, {})),
      file_(std::move(other.file_)),
      buffer_(std::move(other.buffer_)),
      committed_(other.committed_) {}

AtomicFile::~AtomicFile() {
  // Also reached when commit() itself failed half-way: the temporary must not linger.
  if (committed_ || temp_.empty()) return;
  file_ = PosixFile();  // close before unlinking
  std::error_code ignored;
  std::filesystem::remove(temp_, ignored);
}

void AtomicFile::write(std::string_view bytes) {
  if (committed_) throw std::logic_error("AtomicFile: write after commit to " + target_.string());
  buffer_.append(bytes);
  if (buffer_.size() >= kFlushBytes) flush();
}

void AtomicFile::flush() {
  file_.write_all(buffer_);
  buffer_.clear();
}

void AtomicFile::commit() {
  if (committed_) return;
  flush();
  file_.sync();
  file_.close();
  rename_durably(temp_, target_);
  committed_ = true;
}

void atomic_write(const std::filesystem::path& target, std::string_view bytes) {
  AtomicFile file(target);
  file.write(bytes);
  file.commit();
}

}  // namespace talus::io

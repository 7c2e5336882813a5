#pragma once
// All-or-nothing output files (summary.json, checkpoints): bytes go to `TARGET.tmp.<pid>` in
// the same directory, and only commit() flushes, fsyncs and renames it over TARGET. A crash or
// an exception before commit() leaves the previous TARGET untouched (or no TARGET at all),
// never a half-written one; the destructor of an uncommitted file deletes the temporary.
#include <filesystem>
#include <string>
#include <string_view>

#include "talus/io/posix_file.h"

namespace talus::io {

class AtomicFile {
 public:
  // Opens the temporary; throws std::system_error if it cannot be created.
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&&) = delete;  // would abandon this file silently
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();  // not committed: removes the temporary, TARGET is untouched

  void write(std::string_view bytes);  // buffered; may throw std::system_error
  // Flush, fsync, rename over TARGET, fsync the directory. Afterwards nothing may be written.
  void commit();

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temp_path() const { return temp_; }
  bool committed() const { return committed_; }

 private:
  void flush();

  std::filesystem::path target_;
  std::filesystem::path temp_;  ///< empty once moved from
  PosixFile file_;
  std::string buffer_;  ///< pending bytes, written in large chunks
  bool committed_ = false;
};

// Writes `bytes` to `target` through an AtomicFile and commits.
void atomic_write(const std::filesystem::path& target, std::string_view bytes);

}  // namespace talus::io

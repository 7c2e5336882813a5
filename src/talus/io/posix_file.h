#pragma once
// A write-only POSIX file descriptor that writes everything or throws, and can be fsynced:
// the one place the io folder talks to the OS, so AtomicFile and CsvWriter share the
// error handling. Errors are std::system_error with "PATH: what failed: reason".
#include <filesystem>
#include <string_view>

namespace talus::io {

class PosixFile {
 public:
  PosixFile() = default;
  // Creates or truncates `path` for writing (mode 0666 minus umask).
  explicit PosixFile(std::filesystem::path path);
  PosixFile(PosixFile&& other) noexcept;
  PosixFile& operator=(PosixFile&& other) noexcept;
  PosixFile(const PosixFile&) = delete;
  PosixFile& operator=(const PosixFile&) = delete;
  ~PosixFile();  // closes quietly; call close() to see errors

  bool is_open() const { return fd_ >= 0; }
  const std::filesystem::path& path() const { return path_; }

  void write_all(std::string_view bytes);  // retries short writes and EINTR
  void sync();                             // fsync: the bytes are on disk when it returns
  void close();                            // throws if the kernel reports a deferred write error

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// rename(2) `from` over `to` (atomic within one file system), then fsync the directory so
// the new name itself survives a power cut.
void rename_durably(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace talus::io

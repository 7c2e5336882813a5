#pragma once
// A small layer over the HDF5 C API (Debian libhdf5-dev) for checkpoints: numeric datasets of
// one or two dimensions, text, and string or integer attributes on the root group.
//
// Hdf5Writer builds the file in memory (the core driver) and hands back its bytes, so the file
// reaches the disk through io::AtomicFile like every other result: all or nothing. Every
// dataset carries a 64-bit FNV-1a checksum of its bytes, which Hdf5Reader checks, so a flipped
// bit in a stored array is an error rather than a silently different run.
//
// Errors are std::runtime_error naming the file and the dataset; HDF5's own error stack
// printing is switched off.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace talus::io {

class Hdf5Writer {
 public:
  Hdf5Writer();
  ~Hdf5Writer();
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  // `path` like "world/particles/position"; groups on the way are created. `columns` > 1
  // makes a rows x columns dataset (values row-major).
  void write(const std::string& path, std::span<const double> values, std::size_t columns = 1);
  void write(const std::string& path, std::span<const std::uint64_t> values, std::size_t columns = 1);
  void write(const std::string& path, std::span<const std::uint32_t> values, std::size_t columns = 1);
  void write(const std::string& path, std::span<const std::int32_t> values, std::size_t columns = 1);
  void write(const std::string& path, std::span<const std::uint16_t> values, std::size_t columns = 1);
  void write_text(const std::string& path, std::string_view text);
  void attribute(const std::string& name, std::string_view value);
  void attribute(const std::string& name, std::int64_t value);

  // The complete file.
  std::vector<char> image();

 private:
  void write_raw(const std::string& path, const void* data, std::size_t count, std::size_t columns,
                 std::int64_t file_type, std::int64_t memory_type, std::size_t element_bytes);
  std::int64_t file_ = -1;
};

class Hdf5Reader {
 public:
  // Throws std::runtime_error "PATH: not an HDF5 file" (or unreadable) for anything else.
  explicit Hdf5Reader(const std::filesystem::path& path);
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  bool has(const std::string& path) const;
  // Rows of a dataset of `columns` columns (throws if it has another shape).
  std::size_t rows(const std::string& path, std::size_t columns = 1) const { return count(path, columns) / columns; }
  // Reads a dataset written with the same element type and `columns`; checks its checksum.
  std::vector<double> read_double(const std::string& path, std::size_t columns = 1) const;
  std::vector<std::uint64_t> read_u64(const std::string& path, std::size_t columns = 1) const;
  std::vector<std::uint32_t> read_u32(const std::string& path, std::size_t columns = 1) const;
  std::vector<std::int32_t> read_i32(const std::string& path, std::size_t columns = 1) const;
  std::vector<std::uint16_t> read_u16(const std::string& path, std::size_t columns = 1) const;
  std::string read_text(const std::string& path) const;
  // Rows [first, first + count) of a dataset of `columns` columns: one rank's share of a state
  // joined from ranks. The checksum covers the whole dataset, so a share is not checked; the
  // rank that reads the file whole checks it.
  struct Rows {
    std::size_t first = 0, count = 0;
  };
  std::vector<double> read_double_rows(const std::string& path, std::size_t columns, Rows rows) const;
  std::vector<std::uint32_t> read_u32_rows(const std::string& path, std::size_t columns, Rows rows) const;
  std::vector<std::int32_t> read_i32_rows(const std::string& path, std::size_t columns, Rows rows) const;
  std::vector<std::uint16_t> read_u16_rows(const std::string& path, std::size_t columns, Rows rows) const;
  bool has_attribute(const std::string& name) const;
  std::string string_attribute(const std::string& name) const;
  std::int64_t int_attribute(const std::string& name) const;

  const std::filesystem::path& path() const { return path_; }

 private:
  void read_raw(const std::string& path, void* out, std::size_t element_bytes, std::size_t count,
                std::int64_t memory_type) const;
  void read_rows_raw(const std::string& path, void* out, std::size_t element_bytes, std::size_t columns, Rows rows,
                     std::int64_t memory_type) const;
  std::size_t count(const std::string& path, std::size_t columns) const;
  [[noreturn]] void fail(const std::string& what) const;

  std::filesystem::path path_;
  std::int64_t file_ = -1;
};

// FNV-1a, 64 bits: the checksum stored with each dataset.
std::uint64_t fnv1a64(const void* data, std::size_t bytes);

}  // namespace talus::io

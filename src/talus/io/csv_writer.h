#pragma once
// Time series as CSV: a header row, then one row per sample, every number in the shortest
// form that reads back to the same bits.
//
// Crash behaviour: while the run goes on the rows go to `PATH.partial`; close() fsyncs it and
// renames it to PATH. So PATH only ever holds a complete series - either this run's or, if
// this run dies first, the previous run's file untouched. The `.partial` file is left behind
// by an unfinished run (destroyed without close(), e.g. by an exception, or killed), holding
// the rows up to its last flush, for post-mortems. Rows are flushed to the kernel every
// `flush_rows` rows or `flush_seconds` of wall time, so `tail -f` shows progress and a
// killed process loses at most that much; only close() fsyncs.
#include <chrono>
#include <concepts>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "talus/io/posix_file.h"

namespace talus::io {

// One cell: any arithmetic value or text. Integers keep their exact value; text with a comma,
// quote or line break is quoted per RFC 4180.
class CsvCell {
 public:
  CsvCell(double v) : value_(v) {}
  CsvCell(float v) : value_(static_cast<double>(v)) {}
  template <std::signed_integral I>
  CsvCell(I v) : value_(static_cast<std::int64_t>(v)) {}
  template <std::unsigned_integral I>
  CsvCell(I v) : value_(static_cast<std::uint64_t>(v)) {}
  CsvCell(std::string_view v) : value_(v) {}
  CsvCell(const char* v) : value_(std::string_view(v)) {}
  CsvCell(const std::string& v) : value_(std::string_view(v)) {}

  void append_to(std::string& out) const;

 private:
  std::variant<double, std::int64_t, std::uint64_t, std::string_view> value_;
};

class CsvWriter {
 public:
  struct Options {
    std::size_t flush_rows = 1000;  ///< flush after this many rows...
    double flush_seconds = 5.0;     ///< ...or this much wall time (s), whichever comes first
  };

  // Creates (truncates) PATH.partial and writes the header. Throws std::system_error.
  CsvWriter(std::filesystem::path path, std::vector<std::string> columns);
  CsvWriter(std::filesystem::path path, std::vector<std::string> columns, Options options);
  CsvWriter(CsvWriter&&) noexcept = default;
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  ~CsvWriter();  // without close(): flushes, keeps PATH.partial, leaves PATH alone

  // One row; the number of cells must equal the number of columns (std::invalid_argument).
  void row(std::initializer_list<CsvCell> cells);
  void row(std::span<const CsvCell> cells);
  void row(std::span<const double> values);

  // Flushes, fsyncs and renames PATH.partial to PATH. No rows may follow.
  void close();

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path partial_path() const;
  std::size_t rows_written() const { return rows_; }

 private:
  void end_row();
  void flush();

  std::filesystem::path path_;
  std::size_t columns_ = 0;
  Options options_;
  PosixFile file_;
  std::string buffer_;
  std::size_t rows_ = 0;
  std::size_t rows_since_flush_ = 0;
  std::chrono::steady_clock::time_point last_flush_;
  bool closed_ = false;
};

}  // namespace talus::io

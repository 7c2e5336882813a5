#include "talus/io/csv_writer.h"

#include <stdexcept>

#include "talus/io/number_format.h"

namespace talus::io {

namespace {

void append_text(std::string& out, std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) {
    out += text;
    return;
  }
  out += '"';
  for (char c : text) {
    if (c == '"') out += '"';  // RFC 4180: a quote inside a quoted field is doubled
    out += c;
  }
  out += '"';
}

}  // namespace

void CsvCell::append_to(std::string& out) const {
  if (const auto* d = std::get_if<double>(&value_)) {
    append_double(out, *d);
  } else if (const auto* i = std::get_if<std::int64_t>(&value_)) {
    append_int(out, *i);
  } else if (const auto* u = std::get_if<std::uint64_t>(&value_)) {
    out += std::to_string(*u);
  } else {
    append_text(out, std::get<std::string_view>(value_));
  }
}

CsvWriter::CsvWriter(std::filesystem::path path, std::vector<std::string> columns)
    : CsvWriter(std::move(path), std::move(columns), Options{}) {}

CsvWriter::CsvWriter(std::filesystem::path path, std::vector<std::string> columns, Options options)
    : path_(std::move(path)),
      columns_(columns.size()),
      options_(options),
      file_(partial_path()),
      last_flush_(std::chrono::steady_clock::now()) {
  if (columns.empty()) throw std::invalid_argument("CsvWriter: no columns for " + path_.string());
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i) buffer_ += ',';
    append_text(buffer_, columns[i]);
  }
  buffer_ += '\n';
  flush();  // a header on disk at once tells the user the run has started writing
}

CsvWriter::~CsvWriter() {
  if (closed_ || !file_.is_open()) return;
  try {
    flush();
  } catch (...) {
    // Destructors must not throw; the rows lost are the unflushed tail of a failed run.
  }
}

std::filesystem::path CsvWriter::partial_path() const { return path_.string() + ".partial"; }

void CsvWriter::row(std::initializer_list<CsvCell> cells) {
  row(std::span<const CsvCell>(cells.begin(), cells.size()));
}

void CsvWriter::row(std::span<const CsvCell> cells) {
  if (closed_) throw std::logic_error("CsvWriter: row after close of " + path_.string());
  if (cells.size() != columns_)
    throw std::invalid_argument("CsvWriter: " + std::to_string(cells.size()) + " cells for " +
                                std::to_string(columns_) + " columns in " + path_.string());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) buffer_ += ',';
    cells[i].append_to(buffer_);
  }
  end_row();
}

void CsvWriter::row(std::span<const double> values) {
  if (closed_) throw std::logic_error("CsvWriter: row after close of " + path_.string());
  if (values.size() != columns_)
    throw std::invalid_argument("CsvWriter: " + std::to_string(values.size()) + " cells for " +
                                std::to_string(columns_) + " columns in " + path_.string());
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) buffer_ += ',';
    append_double(buffer_, values[i]);
  }
  end_row();
}

void CsvWriter::end_row() {
  buffer_ += '\n';
  ++rows_;
  // steady_clock::now() costs tens of nanoseconds (vDSO), nothing next to a row's formatting.
  if (++rows_since_flush_ >= options_.flush_rows ||
      std::chrono::duration<double>(std::chrono::steady_clock::now() - last_flush_).count() >=
          options_.flush_seconds)
    flush();
}

void CsvWriter::flush() {
  file_.write_all(buffer_);
  buffer_.clear();
  rows_since_flush_ = 0;
  last_flush_ = std::chrono::steady_clock::now();
}

void CsvWriter::close() {
  if (closed_) return;
  flush();
  file_.sync();
  file_.close();
  rename_durably(partial_path(), path_);
  closed_ = true;
}

}  // namespace talus::io

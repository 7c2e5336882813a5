// CsvWriter: round-trip precision, quoting, and the .partial-then-rename life cycle.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

#include "talus/io/csv_writer.h"
#include "talus/io/number_format.h"

namespace fs = std::filesystem;
using namespace talus::io;

namespace {

class IoCsv : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("talus_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::vector<std::string> lines(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  }

  fs::path dir_;
};

double parse_double(std::string_view s) {
  double v = 0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

}  // namespace

TEST(IoNumberFormat, ShortestRoundTrip) {
  EXPECT_EQ(format_double(0.1), "0.1");
  EXPECT_EQ(format_double(-3.0), "-3");
  EXPECT_EQ(format_double(1.0 / 3.0), "0.3333333333333333");
  EXPECT_EQ(format_double(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(format_int(-9007199254740993), "-9007199254740993");
}

TEST_F(IoCsv, RoundTripsEveryBit) {
  const fs::path path = dir_ / "timeseries.csv";
  std::vector<double> values;
  double x = 0.1;
  for (int i = 0; i < 200; ++i, x = x * 1.37 + 1e-3 / (i + 1)) values.push_back(i % 2 ? x : -x);
  values.push_back(5e-324);
  values.push_back(std::numeric_limits<double>::max());
  {
    CsvWriter csv(path, {"step", "value", "note"});
    for (std::size_t i = 0; i < values.size(); ++i)
      csv.row({i, values[i], i == 0 ? "first, \"quoted\"" : ""});
    csv.close();
  }
  const auto rows = lines(path);
  ASSERT_EQ(rows.size(), values.size() + 1);
  EXPECT_EQ(rows[0], "step,value,note");
  EXPECT_EQ(rows[1], "0,-0.1,\"first, \"\"quoted\"\"\"");
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string& row = rows[i + 1];
    const auto a = row.find(','), b = row.find(',', a + 1);
    EXPECT_EQ(row.substr(0, a), std::to_string(i));
    EXPECT_EQ(parse_double(std::string_view(row).substr(a + 1, b - a - 1)), values[i]) << row;
  }
  EXPECT_FALSE(fs::exists(dir_ / "timeseries.csv.partial"));
}

TEST_F(IoCsv, PartialWhileRunningRenamedAtClose) {
  const fs::path path = dir_ / "ts.csv";
  CsvWriter csv(path, {"t", "e"}, CsvWriter::Options{.flush_rows = 2, .flush_seconds = 60});
  csv.row(std::vector<double>{0.0, 1.5});
  csv.row(std::vector<double>{0.5, 2.5});  // second row: flushed
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(lines(dir_ / "ts.csv.partial"), (std::vector<std::string>{"t,e", "0,1.5", "0.5,2.5"}));
  csv.close();
  EXPECT_EQ(lines(path), (std::vector<std::string>{"t,e", "0,1.5", "0.5,2.5"}));
  EXPECT_FALSE(fs::exists(dir_ / "ts.csv.partial"));
}

TEST_F(IoCsv, InterruptedRunKeepsPreviousFile) {
  const fs::path path = dir_ / "ts.csv";
  {
    CsvWriter first(path, {"t"});
    first.row({1.0});
    first.close();
  }
  {
    CsvWriter second(path, {"t"});
    second.row({2.0});
  }  // destroyed without close(), as when the run throws
  EXPECT_EQ(lines(path), (std::vector<std::string>{"t", "1"}));
  EXPECT_EQ(lines(dir_ / "ts.csv.partial"), (std::vector<std::string>{"t", "2"}));
}

TEST_F(IoCsv, WrongCellCountIsRejected) {
  CsvWriter csv(dir_ / "x.csv", {"a", "b"});
  EXPECT_THROW(csv.row({1.0}), std::invalid_argument);
}

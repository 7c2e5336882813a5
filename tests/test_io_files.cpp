// AtomicFile / atomic_write, write_json and prepare_results_dir.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

#include "talus/io/atomic_file.h"
#include "talus/io/input_error.h"
#include "talus/io/json_file.h"
#include "talus/io/results_dir.h"

namespace fs = std::filesystem;
using namespace talus::io;

namespace {

// A fresh empty directory per test, removed afterwards.
class IoFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("talus_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  fs::path dir_;
};

}  // namespace

TEST_F(IoFiles, AtomicWriteReplacesTarget) {
  const fs::path target = dir_ / "summary.json";
  atomic_write(target, "old");
  atomic_write(target, "new contents");
  EXPECT_EQ(slurp(target), "new contents");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);
}

TEST_F(IoFiles, UncommittedWriterLeavesOldFileIntact) {
  const fs::path target = dir_ / "checkpoint.bin";
  atomic_write(target, "complete previous checkpoint");
  {
    AtomicFile file(target);
    file.write("half of a new checkp");
    EXPECT_TRUE(fs::exists(file.temp_path()));
    EXPECT_EQ(file.temp_path().parent_path(), dir_);
    EXPECT_EQ(file.temp_path().filename().string(),
              "checkpoint.bin.tmp." + std::to_string(::getpid()));
  }  // destroyed before commit(), as when an exception unwinds
  EXPECT_EQ(slurp(target), "complete previous checkpoint");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 1);
}

TEST_F(IoFiles, UncommittedWriterCreatesNothing) {
  { AtomicFile file(dir_ / "never.csv"); file.write("x"); }
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(IoFiles, AtomicWriteLargePayload) {
  std::string big(3'000'000, 'a');  // crosses the internal buffer size
  big.back() = 'z';
  atomic_write(dir_ / "big", big);
  EXPECT_EQ(slurp(dir_ / "big"), big);
}

TEST_F(IoFiles, AtomicWriteIntoMissingDirectoryThrows) {
  EXPECT_THROW(atomic_write(dir_ / "no" / "such" / "file", "x"), std::system_error);
}

TEST_F(IoFiles, JsonRoundTripsDoubles) {
  const double third = 1.0 / 3.0;
  const nlohmann::json value = {{"tenth", 0.1},
                                {"third", third},
                                {"tiny", 5e-324},
                                {"big", 1.7976931348623157e308},
                                {"count", 42},
                                {"nan", std::numeric_limits<double>::quiet_NaN()}};
  write_json(dir_ / "summary.json", value);
  const std::string text = slurp(dir_ / "summary.json");
  EXPECT_NE(text.find("\"tenth\": 0.1,"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
  const auto back = nlohmann::json::parse(text);
  EXPECT_EQ(back["third"].get<double>(), third);
  EXPECT_EQ(back["tiny"].get<double>(), 5e-324);
  EXPECT_EQ(back["big"].get<double>(), 1.7976931348623157e308);
  EXPECT_EQ(back["count"].get<int>(), 42);
  EXPECT_TRUE(back["nan"].is_null());
}

TEST_F(IoFiles, ResultsDirCreatedWithParents) {
  const fs::path out = dir_ / "a" / "b" / "run1";
  prepare_results_dir(out, false);
  EXPECT_TRUE(fs::is_directory(out));
  prepare_results_dir(out, false);  // existing but empty is fine
}

TEST_F(IoFiles, ResultsDirRefusesNonEmptyUnlessOverwrite) {
  const fs::path out = dir_ / "run";
  prepare_results_dir(out, false);
  atomic_write(out / "summary.json", "{}");
  try {
    prepare_results_dir(out, false);
    FAIL() << "non-empty folder accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              out.string() + ": output folder exists and is not empty; choose another folder, "
                             "or pass --overwrite to write into it (files of the same name are "
                             "replaced)");
  }
  EXPECT_NO_THROW(prepare_results_dir(out, true));
  EXPECT_TRUE(fs::exists(out / "summary.json"));  // overwrite never deletes
}

TEST_F(IoFiles, ResultsDirThatIsAFileIsRefused) {
  atomic_write(dir_ / "file", "x");
  EXPECT_THROW(prepare_results_dir(dir_ / "file", true), InputError);
}

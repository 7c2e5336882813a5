// [chute.flow_state] and [chute.coarse_graining]: defaults from the paper (Weinhart et al. 2012,
// Sects. 6-7) and bad input reported as FILE:LINE: KEY: message.
#include <gtest/gtest.h>

#include "talus/io/scenario_file.h"
#include "talus/scenario/chute_study.h"

namespace talus {
namespace {

ChuteStudyConfig read(const std::string& text) {
  const io::ScenarioFile f = io::ScenarioFile::from_string(text, "chute.toml");
  return read_chute_study(f, 0.005, 2100, 20, 1, 6 / M_PI);
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ChuteStudyConfig, PaperDefaults) {
  const ChuteStudyConfig c = read("[chute.coarse_graining]\nstart = 2000.0\n");
  EXPECT_TRUE(c.coarse_grain);
  EXPECT_DOUBLE_EQ(c.interval, 0.0025);  // t_c / 2 (Sect. 7)
  EXPECT_EQ(c.width, 0.25);
  EXPECT_EQ(c.end, 2100);
  EXPECT_EQ(c.criteria.arrest_ratio, 1e-5);  // Sect. 6
  EXPECT_EQ(c.criteria.arrest_time, 500);
  EXPECT_LT(c.z_min, -1.0 - 0.75 + 1e-12);  // below the basal contacts by a cutoff
  EXPECT_GE((c.z_max - c.z_min) / (c.points - 1), 0.0);
  EXPECT_LE((c.z_max - c.z_min) / (c.points - 1), 0.25 * c.width + 1e-12);
  EXPECT_FALSE(read("").coarse_grain);
}

TEST(ChuteStudyConfig, BadInputNamesFileLineAndKey) {
  EXPECT_EQ(error_of("[chute.coarse_graining]\nwidth = -1.0\n"),
            "chute.toml:2: chute.coarse_graining.width: must be positive, got -1");
  EXPECT_NE(error_of("[chute.coarse_graining]\nstart = 100.0\nend = 50.0\n").find("chute.toml:3: chute.coarse_graining.end"),
            std::string::npos);
  EXPECT_NE(error_of("[chute.coarse_graining]\nfunction = \"gauss\"\n").find("chute.toml:2: chute.coarse_graining.function"),
            std::string::npos);
}

}  // namespace
}  // namespace talus

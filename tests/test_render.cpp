// `talus render` draws the particles where they are: one sphere at a known place, seen from
// above, darkens the pixels around its centre and nowhere far from it.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

std::string shell(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
  pclose(pipe);
  return out;
}

TEST(Render, OneSphereAppearsWhereItIs) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "talus_render_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "one.toml") << R"([run]
end_time = 0.001
vtk_interval = 0.001
[domain]
lo = [0.0, 0.0, 0.0]
hi = [0.1, 0.1, 0.1]
gravity = [0.0, 0.0, 0.0]
[box]
lo = [0.0, 0.0, 0.0]
hi = [0.1, 0.1, 0.1]
[species.ball]
density = 2500
radius = 0.01
[contact]
normal_stiffness = 1e4
normal_restitution = 0.5
[[particles]]
species = "ball"
position = [0.03, 0.07, 0.05]
)";
  const std::string talus = std::string(TALUS_BINARY_DIR) + "/talus";
  ASSERT_EQ(std::system((talus + " run " + (dir / "one.toml").string() + " --quiet --out " + (dir / "out").string()).c_str()), 0);
  ASSERT_EQ(std::system((talus + " render " + (dir / "out").string() + " --view top --out " + (dir / "top.png").string() +
                         " > /dev/null").c_str()), 0);
  // Where are the dark pixels? Axes are found from the box outline: the plot spans [0, 0.1]^2.
  const std::string probe = R"(/usr/bin/python3 -c "
import matplotlib.image as im, numpy as np, sys
a = im.imread(sys.argv[1])[:, :, :3]
black = a.max(axis=2) < 0.2
# The axes frame: the black rows and columns that run along most of the frame.
spine_rows = np.where(black.sum(axis=1) > 0.3 * black.shape[1])[0]
spine_cols = np.where(black.sum(axis=0) > 0.3 * black.shape[0])[0]
top, bottom, left, right = spine_rows.min(), spine_rows.max(), spine_cols.min(), spine_cols.max()
# The resting particle is drawn in the darkest colour of viridis (purple).
rows, cols = np.where((a[:, :, 0] > 0.2) & (a[:, :, 0] < 0.4) & (a[:, :, 1] < 0.15) & (a[:, :, 2] > 0.25))
r, c = rows.mean(), cols.mean()
print((c - left) / (right - left) * 0.1, (bottom - r) / (bottom - top) * 0.1)
" )" + (dir / "top.png").string();
  double x = -1, y = -1;
  ASSERT_EQ(std::sscanf(shell(probe).c_str(), "%lf %lf", &x, &y), 2);
  EXPECT_NEAR(x, 0.03, 0.004);  // a few pixels of the 0.1 m wide plot
  EXPECT_NEAR(y, 0.07, 0.004);
}

}  // namespace

// SourceMarks::files: every data file a scene reads is recorded, resolved against the scene's
// folder, so that `raycast serve` can watch it (docs/serve.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "../support/cli_runner.h"
#include "io/image.h"
#include "load/loader.h"

namespace raycast {
namespace {

using test::write;

std::string binary_ply_triangle() {
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float v[9] = {0, 0, 5, 1, 0, 5, 0, 1, 5};
  ply.append(reinterpret_cast<const char*>(v), sizeof v);
  const unsigned char n = 3;
  const int f[3] = {0, 1, 2};
  ply.append(reinterpret_cast<const char*>(&n), 1);
  ply.append(reinterpret_cast<const char*>(f), sizeof f);
  return ply;
}

TEST(DataFiles, EveryFileReadIsRecorded) {
  const std::string dir = test::temp_dir().string();
  write("tri.ply", binary_ply_triangle());
  write("ball.xyz", "0 0 0\n");
  const float grid[8] = {0, 0, 0, 0, 0, 0, 0, 1};
  write("g.raw", std::string(reinterpret_cast<const char*>(grid), sizeof grid));
  write("g.json", R"({"dims": [2, 2, 2], "min": [0, 0, 0], "max": [1, 1, 1]})");
  Image texture(2, 2);
  save_png(texture, dir + "/tex.png");
  const Scene s = load_scene_text(
      "materials:\n  t: {texture: {image: {file: tex.png}}}\n"
      "objects:\n"
      "  - mesh: {file: tri.ply}\n"
      "  - isosurface: {particles: ball.xyz, smoothing_length: 1, iso: 0.01, cell_size: 0.25}\n"
      "  - isosurface: {grid: g.raw, iso: 0.5}\n"
      "  - sphere: {center: [0, 0, 0], radius: 1}\n    material: t\n",
      "t.yaml", dir);
  std::vector<std::string> expected;
  for (const char* name : {"tex.png", "tri.ply", "ball.xyz", "g.raw", "g.json"})
    expected.push_back((test::temp_dir() / name).string());
  std::vector<std::string> got = s.marks.files;
  EXPECT_EQ(got, expected);
}

TEST(DataFiles, AnalyticSceneReadsNone) {
  const Scene s = load_scene_text("objects:\n  - sphere: {center: [0, 0, 0], radius: 1}\n");
  EXPECT_TRUE(s.marks.files.empty());
}

}  // namespace
}  // namespace raycast

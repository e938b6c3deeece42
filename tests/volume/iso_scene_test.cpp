// The iso-surface as a solid of the scene: CSG, transforms, instancing, `cast --all`, positioned
// errors from its data files, and `render --frames`.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/cli_runner.h"
#include "io/scene_error.h"
#include "load/frame_pattern.h"
#include "load/loader.h"

namespace raycast {
namespace {

using test::write;

// One particle at the origin: with h = 1, V = 1, rho0 = 1 and iso = W(1.25) its surface is
// (nearly) the sphere of radius 1.25.
const char* kBall =
    "isosurface: {particles: ball.xyz, smoothing_length: 1, rest_density: 1, "
    "particle_volume: 1, iso: 0.0335718, cell_size: 0.05}";
constexpr double kRadius = 1.25;

Scene load(const std::string& objects) {
  write("ball.xyz", "0 0 0\n");
  const std::string text = "objects:\n" + objects;
  return load_scene_text(text, "t.yaml", test::temp_dir().string());
}

TEST(IsoScene, TransformAndInstance_MoveTheSurface) {
  const Scene s = load("  - " + std::string(kBall) +
                       "\n    transform: [{scale: 2}, {translate: [10, 0, 0]}]\n");
  SceneHit h;
  ASSERT_TRUE(s.intersect(Ray{{0, 0, 0}, {1, 0, 0}}, h));
  EXPECT_NEAR(h.local.t, 10 - 2 * kRadius, 2e-3);
  const SurfaceInfo si = s.surface(Ray{{0, 0, 0}, {1, 0, 0}}, h);
  EXPECT_NEAR(si.n.x, -1, 1e-3);
  const Scene inst = load(
      "  - use: blob\n    transform: [{translate: [0, 5, 0]}]\n"
      "  - use: blob\n    transform: [{translate: [0, -5, 0]}]\n"
      "library:\n  blob:\n    " +
      std::string(kBall) + "\n");
  ASSERT_TRUE(inst.intersect(Ray{{0, 0, 0}, {0, 1, 0}}, h));
  EXPECT_NEAR(h.local.t, 5 - kRadius, 1e-3);
  ASSERT_TRUE(inst.intersect(Ray{{0, 0, 0}, {0, -1, 0}}, h));
  EXPECT_NEAR(h.local.t, 5 - kRadius, 1e-3);
  EXPECT_TRUE(inst.occluded(Ray{{0, 0, 0}, {0, 1, 0}, 0, 4}));
  EXPECT_FALSE(inst.occluded(Ray{{0, 0, 0}, {0, 1, 0}, 0, 3}));
}

TEST(IsoScene, CsgDifference_CutsTheBlob) {
  const Scene s = load("  - difference:\n      - " + std::string(kBall) +
                       "\n      - box: {min: [-2, -2, -2], max: [0, 2, 2]}\n");
  std::vector<Crossing> all;
  s.intersect_all(Ray{{-5, 0, 0}, {1, 0, 0}}, all);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_NEAR(all[0].t, 5, 1e-12);  // the box's face x = 0
  EXPECT_NEAR(all[1].t, 5 + kRadius, 1e-3);
  const Scene u = load("  - intersection:\n      - " + std::string(kBall) +
                       "\n      - box: {min: [-2, -2, -2], max: [0, 2, 2]}\n");
  SceneHit h;
  ASSERT_TRUE(u.intersect(Ray{{-5, 0.1, 0}, {1, 0, 0}}, h));
  EXPECT_NEAR(h.local.t, 5 - std::sqrt(kRadius * kRadius - 0.01), 1e-3);
}

TEST(IsoScene, DataFileErrors_NameTheDataFile) {
  write("bad.xyz", "0 0 0\n1 x 2\n");
  try {
    load_scene_text("objects:\n  - isosurface: {particles: bad.xyz, smoothing_length: 1}\n",
                    "t.yaml", test::temp_dir().string());
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(e.file().find("bad.xyz"), std::string::npos);
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 3);
  }
  const std::pair<const char*, int> cases[] = {
      {"{smoothing_length: 1}", 3},  // neither particles nor grid
      {"{particles: ball.xyz}", 3},  // no smoothing_length
      {"{particles: ball.xyz, smoothing_length: -1}", 3},
      {"{particles: ball.xyz, smoothing_length: 1, iso: -1}", 3},
      {"{particles: ball.xyz, smoothing_length: 1, cell_size: 1, resolution: [3, 3, 3]}", 3},
      {"{particles: ball.xyz, smoothing_length: 1, resolution: [3, 1, 3]}", 3},
      {"{particles: ball.xyz, smoothing_length: 1, cell_size: 0.00001}", 3},  // too large
      {"{particles: ball.xyz, smoothing_length: 1, colour: 1}", 3},           // unknown key
      {"{particles: 'ball_{frame:4x}.xyz', smoothing_length: 1}", 3},
      {"{grid: g.raw}", 3},  // no iso
      {"{grid: g.dat, iso: 1}", 3},
  };
  for (const auto& [shape, line] : cases) {
    try {
      load(std::string("  - isosurface: ") + shape + "\n");
      ADD_FAILURE() << shape;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.file(), "t.yaml") << shape;
      EXPECT_EQ(e.line(), line - 1) << e.what();
      EXPECT_GT(e.column(), 0) << e.what();
    }
  }
}

TEST(FramePattern, Expands) {
  EXPECT_EQ(expand_frame_pattern("a_{frame:04d}.ply", 7), "a_0007.ply");
  EXPECT_EQ(expand_frame_pattern("{frame}/{frame:2d}", 123), "123/123");
  EXPECT_EQ(expand_frame_pattern("f{frame:3d}", 5), "f  5");
  EXPECT_EQ(expand_frame_pattern("plain.ply", 5), "plain.ply");
  EXPECT_THROW(expand_frame_pattern("{frame:x}", 1), std::invalid_argument);
  EXPECT_THROW(expand_frame_pattern("{frame", 1), std::invalid_argument);
  EXPECT_THROW(expand_frame_pattern("{frame:00d}", 1), std::invalid_argument);
  EXPECT_TRUE(has_frame_pattern("x{frame}"));
  EXPECT_FALSE(has_frame_pattern("x{fram}"));
}

TEST(IsoCli, CastAllAndFrames) {
  write("p_0000.xyz", "0 0 0\n");
  write("p_0002.xyz", "0 0 0\n0.5 0 0\n");  // frame 1 is missing
  const std::string scene = write(
      "frames.yaml",
      "image: {width: 16, height: 12}\nobjects:\n  - isosurface: {particles: 'p_{frame:04d}.xyz', "
      "smoothing_length: 1, rest_density: 1, particle_volume: 1, iso: 0.0335718, cell_size: "
      "0.1}\n");
  const std::string rays = write("rays.txt", "-5 0 0 1 0 0\n0 0 0 1 0 0\n");
  const test::Outcome all = test::run("cast '" + scene + "' --all --rays '" + rays + "'");
  ASSERT_EQ(all.code, 0) << all.err;
  EXPECT_EQ(all.out.substr(0, 2), "2 ");
  EXPECT_EQ(all.out.substr(all.out.find('\n') + 1, 2), "1 ");  // from inside: the exit only
  const std::string out = (test::temp_dir() / "img_{frame:03d}.png").string();
  const test::Outcome r = test::run("render '" + scene + "' --frames 0-2 -o '" + out + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("frame 1 (2/3) failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("p_0001.xyz"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 of 3 frames rendered"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(test::temp_dir() / "img_000.png"));
  EXPECT_FALSE(std::filesystem::exists(test::temp_dir() / "img_001.png"));
  EXPECT_TRUE(std::filesystem::exists(test::temp_dir() / "img_002.png"));
  EXPECT_EQ(test::run("render '" + scene + "' --frames 0-2 -o x.png").code, 2);  // no pattern
  EXPECT_EQ(test::run("render '" + scene + "' --frames 3-1 -o 'x{frame}.png'").code, 2);
}

}  // namespace
}  // namespace raycast

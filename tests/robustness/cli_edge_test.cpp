// Edge cases through the raycast binary (RAYCAST_BINARY): empty, binary and directory scenes, empty
// and malformed ray files, oversized images, zero counts, bad meshes. Each must exit 0 or 2 with a
// clear message; never crash (a signal) or hang.
#include <gtest/gtest.h>

#include "../support/cli_runner.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using raycast::test::Outcome;
using raycast::test::read;
using raycast::test::run;
using raycast::test::temp_dir;
using raycast::test::write;

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

const char* const kBox = "objects:\n  - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n";

TEST(RobustCli, EmptySceneFile_ExitsTwoNamingIt) {
  const std::string scene = write("empty.yaml", "");
  const Outcome r = run("info '" + scene + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, scene + ": the scene is empty")) << r.err;
  const Outcome c = run("cast '" + scene + "' --rays '" + write("one.txt", "0 0 -5 0 0 1\n") + "'");
  EXPECT_EQ(c.code, 2) << c.err;
}

TEST(RobustCli, DirectoryAsScene_ExitsTwoNamingIt) {
  const std::string dir = (temp_dir() / "a_folder").string();
  fs::create_directories(dir);
  const Outcome r = run("info '" + dir + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, dir)) << r.err;
}

TEST(RobustCli, BinaryGarbageScene_ExitsTwoNamingIt) {
  std::string garbage;
  std::uint32_t x = 12345;
  for (int i = 0; i < 4096; ++i) {
    x = x * 1664525u + 1013904223u;
    garbage.push_back(static_cast<char>(x >> 24));
  }
  const std::string scene = write("garbage.yaml", garbage);
  const Outcome r = run("info '" + scene + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, scene)) << r.err;
  const std::string nul =
      write("nul.yaml", std::string("objects:\n  - sphere: {radius: 1}\0\0\0", 36));
  const Outcome n = run("info '" + nul + "'");
  EXPECT_TRUE(n.code == 0 || n.code == 2) << n.err;
}

TEST(RobustCli, Cast_EmptyRayFile_AnswersNothing) {
  const Outcome r =
      run("cast '" + write("box.yaml", kBox) + "' --rays '" + write("empty.txt", "") + "'");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const Outcome b = run("cast '" + write("box.yaml", kBox) + "' --binary --rays '" +
                        write("empty.bin", "") + "'");
  EXPECT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(b.out, "");
}

TEST(RobustCli, Cast_BadRayLines_ExitTwoNamingTheLine) {
  const std::string scene = write("box.yaml", kBox);
  struct Case {
    const char* rays;
    const char* where;
  };
  const Case cases[] = {
      {"nan 0 -5 0 0 1\n", ":1:"},
      {"0 0 -5 nan 0 1\n", ":1:"},
      {"0 0 -5 0 0 1\n1e999 0 -5 0 0 1\n", ":2:"},
      {"0 0 -5 0 0 1e999\n", ":1:"},
      {"0 0 -5 0 0 1 0 1 2\n", ":1:"},
      {"0 0 -5 0 0 1 abc\n", ":1:"},
      {"0 0 -5 0 0 1garbage\n", ":1:"},
      {"0 0 -5 0 0 1 nan\n", ":1:"},
      {"0 0 -5 0 0 1 5 1\n", ":1:"},  // tmin > tmax
      // Outside the rays' domain (geometry/ray.h is_valid): |o|^2 or |d|^2 over- or underflows.
      {"1e300 1e300 1e300 -1 -1 -1\n", ":1:1: ray out of range"},
      {"0 0 -5 0 0 1e300\n", ":1:1: ray direction must be finite and non-zero"},
      {"0 0 -5 0 0 1e-160\n", ":1:1: ray out of range"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.rays);
    const std::string rays = write("bad.txt", c.rays);
    const Outcome r = run("cast '" + scene + "' --rays '" + rays + "'");
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, rays + c.where)) << r.err;
  }
}

TEST(RobustCli, Cast_SevenNumbersAndExtremeIntervals_Answer) {
  const std::string scene = write("box.yaml", kBox);
  const std::string rays = write("ok.txt",
                                 "0 0 -5 0 0 1 0\n"
                                 "0 0 -5 0 0 1 4 4\n"
                                 "0 0 -5 0 0 1 -inf inf\n"
                                 "0 0 -5 0 0 1 0 0\n"
                                 "1e150 1e150 1e150 -1 -1 -1\n"
                                 "0 0 -5 1e-300 1e-300 1\n"
                                 "0 0 -5 -0 -0 1e150\n");
  const Outcome r = run("cast '" + scene + "' --rays '" + rays + "'");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 7) << r.out;
  EXPECT_EQ(r.out.substr(0, 2), "4 ") << r.out;
}

TEST(RobustCli, Render_HugeImage_RefusedBeforeAllocating) {
  const std::string scene = write("box.yaml", kBox);
  const std::string out = (temp_dir() / "o.png").string();
  const Outcome side =
      run("render '" + scene + "' -o '" + out + "' --width 100000 --height 100000");
  EXPECT_EQ(side.code, 2) << side.err;
  EXPECT_TRUE(contains(side.err, "--width must be in [1, 65536]")) << side.err;
  // Each side within bounds, the product (2^32 pixels) not.
  const Outcome area = run("render '" + scene + "' -o '" + out + "' --width 65536 --height 65536");
  EXPECT_EQ(area.code, 2) << area.err;
  EXPECT_TRUE(contains(area.err, "268435456 pixels")) << area.err;
  EXPECT_LT(area.seconds, 10);
  // The same through the scene file: a positioned error.
  const std::string big =
      write("big.yaml", std::string(kBox) + "image: {width: 65536, height: 65536}\n");
  const Outcome file = run("render '" + big + "' -o '" + out + "'");
  EXPECT_EQ(file.code, 2) << file.err;
  EXPECT_TRUE(
      contains(file.err, big + ":3:8: image.width * image.height must be at most 268435456"))
      << file.err;
  // The scene's size overridden on one side only.
  const std::string wide =
      write("wide.yaml", std::string(kBox) + "image: {width: 65536, height: 16}\n");
  const Outcome one = run("render '" + wide + "' -o '" + out + "' --height 65536");
  EXPECT_EQ(one.code, 2) << one.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(RobustCli, Render_ZeroCounts_ExitTwo) {
  const std::string scene = write("box.yaml", kBox);
  const std::string out = (temp_dir() / "z.png").string();
  for (const char* flag : {"--spp 0", "--threads -1", "--threads 4097", "--width 0", "--height -3",
                           "--spp 99999999999"}) {
    SCOPED_TRACE(flag);
    const Outcome r = run("render '" + scene + "' -o '" + out + "' " + flag);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_FALSE(r.err.empty());
  }
}

TEST(RobustCli, HugeSamplesInScene_PositionedError) {
  const std::string scene =
      write("s.yaml", std::string(kBox) + "image: {samples: 99999999999999}\n");
  const Outcome r = run("info '" + scene + "'");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(contains(r.err, scene + ":3:")) << r.err;
}

TEST(RobustCli, BadMeshes_PositionedErrors) {
  struct Case {
    const char* name;
    std::string yaml;
  };
  const Case cases[] = {
      {"nan vertex",
       "objects:\n  - mesh: {vertices: [[0, 0, 0], [1, .nan, 0], [0, 1, 0]], triangles: [[0, 1, "
       "2]]}\n"},
      {"inf vertex",
       "objects:\n  - mesh: {vertices: [[0, 0, 0], [1, .inf, 0], [0, 1, 0]], triangles: [[0, 1, "
       "2]]}\n"},
      {"index out of range",
       "objects:\n  - mesh: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], triangles: [[0, 1, "
       "3]]}\n"},
      {"negative index",
       "objects:\n  - mesh: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], triangles: [[0, -1, "
       "2]]}\n"},
      {"huge index",
       "objects:\n  - mesh: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], triangles: [[0, "
       "99999999999999, 2]]}\n"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string scene = write("mesh.yaml", c.yaml);
    const Outcome r = run("info '" + scene + "'");
    EXPECT_EQ(r.code, 2) << r.out << r.err;
    EXPECT_TRUE(contains(r.err, scene + ":2:")) << r.err;
  }
  // The same in a file: the error names the mesh file.
  const std::string obj = write("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
  const Outcome f =
      run("info '" + write("objmesh.yaml", "objects:\n  - mesh: {file: nan.obj}\n") + "'");
  EXPECT_EQ(f.code, 2) << f.out << f.err;
  // Used to load as "1 degenerate triangles dropped": assimp's vertex joining merged the NaN away.
  EXPECT_TRUE(contains(f.err, "objmesh.yaml:2:18: mesh.file 'nan.obj': ")) << f.err;
  EXPECT_TRUE(contains(f.err, "nan.obj:2:5: expected a finite number, got 'nan'")) << f.err;
  const std::string range = write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  const Outcome g =
      run("info '" + write("rangemesh.yaml", "objects:\n  - mesh: {file: range.obj}\n") + "'");
  EXPECT_EQ(g.code, 2) << g.out << g.err;
}

TEST(RobustCli, DegenerateTriangles_DroppedAndCounted) {
  const std::string scene =
      write("degen.yaml",
            "objects:\n  - mesh: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [2, 0, 0]], "
            "triangles: [[0, 1, 2], [0, 0, 1], [0, 1, 3], [2, 2, 2]]}\n");
  const Outcome r = run("info '" + scene + "'");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "3 degenerate triangles dropped")) << r.out;
  const Outcome c = run("cast '" + scene + "' --rays '" +
                        write("r.txt", "0.2 0.2 1 0 0 -1\n2 0 1 0 0 -1\n") + "'");
  EXPECT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(c.out.substr(0, 2), "1 ") << c.out;
}

TEST(RobustCli, EmptyAndOneTriangleMeshes) {
  // An empty mesh loads (0 triangles) and every ray misses it.
  const std::string empty = write("e.yaml", "objects:\n  - mesh: {vertices: [], triangles: []}\n");
  const Outcome e = run("info '" + empty + "'");
  EXPECT_EQ(e.code, 0) << e.err;
  EXPECT_TRUE(contains(e.out, "triangles: 0 in 1 meshes")) << e.out;
  const Outcome ec = run("cast '" + empty + "' --rays '" + write("r0.txt", "0 0 5 0 0 -1\n") + "'");
  EXPECT_EQ(ec.code, 0) << ec.err;
  EXPECT_EQ(ec.out.substr(0, 4), "inf ") << ec.out;
  const std::string all_degenerate = write("d.yaml",
                                           "objects:\n  - mesh: {vertices: [[0, 0, 0], [1, 0, 0], "
                                           "[2, 0, 0]], triangles: [[0, 1, 2]]}\n");
  const Outcome d =
      run("cast '" + all_degenerate + "' --rays '" + write("r.txt", "0.5 0 1 0 0 -1\n") + "'");
  EXPECT_EQ(d.code, 0) << d.err;  // its only triangle is dropped: every ray misses
  EXPECT_EQ(d.out.substr(0, 4), "inf ") << d.out;
  const std::string one = write("one.yaml",
                                "objects:\n  - mesh: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "
                                "triangles: [[0, 1, 2]]}\n");
  const Outcome o =
      run("cast '" + one + "' --rays '" + write("r1.txt", "0.25 0.25 1 0 0 -1\n") + "'");
  EXPECT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out.substr(0, 2), "1 ") << o.out;
}

}  // namespace

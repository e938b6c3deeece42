// End-to-end tests through the raycast binary (RAYCAST_BINARY), on scenes and rays written to a
// temporary folder.
#include <gtest/gtest.h>

#include "../support/cli_runner.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

using raycast::test::Outcome;
using raycast::test::read;
using raycast::test::run;
using raycast::test::write;

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

std::vector<double> numbers(const std::string& line) {
  std::vector<double> v;
  std::istringstream in(line);
  for (std::string tok; in >> tok;) v.push_back(std::strtod(tok.c_str(), nullptr));
  return v;
}

const char* kBoxScene = R"(objects:
  - box: {min: [-1, -1, -1], max: [1, 1, 1]}
  - sphere: {center: [5, 0, 0], radius: 1}
)";

const char* kMiss = "inf nan nan nan nan nan nan nan nan -1 -1";

TEST(Cli, Help_ExitsZeroAndListsCommands) {
  const Outcome r = run("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("cast"), std::string::npos);
  EXPECT_NE(r.out.find("info"), std::string::npos);
  const Outcome c = run("cast --help");
  EXPECT_EQ(c.code, 0);
  EXPECT_NE(c.out.find("--any"), std::string::npos);
  EXPECT_NE(c.out.find("--binary"), std::string::npos);
}

TEST(Cli, NoCommandOrUnknownOption_ExitsTwo) {
  EXPECT_EQ(run("").code, 2);
  EXPECT_EQ(run("cast --bogus x.yaml").code, 2);
  const std::string scene = write("box.yaml", kBoxScene);
  EXPECT_EQ(run("cast --any --all '" + scene + "' </dev/null").code, 2);
}

TEST(Cli, Version_PrintsVersionAndBuild) {
  const Outcome r = run("--version");
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out.rfind("raycast 0.", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("build"), std::string::npos) << r.out;
}

TEST(Cli, UnknownCommand_NamedWithTheNearestOne) {
  const Outcome r = run("rendr");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown command 'rendr' (did you mean 'render'?)"), std::string::npos)
      << r.err;
  const Outcome far = run("frobnicate");
  EXPECT_EQ(far.code, 2);
  EXPECT_NE(far.err.find("unknown command 'frobnicate'; run"), std::string::npos) << far.err;
}

TEST(Cli, UnknownOption_NamedWithTheNearestOne) {
  const Outcome r = run("render --widht 10");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("raycast render: unknown option '--widht' (did you mean '--width'?)"),
            std::string::npos)
      << r.err;
  const Outcome extra = run("info a.yaml b.yaml");
  EXPECT_EQ(extra.code, 2);
  EXPECT_NE(extra.err.find("unexpected argument 'b.yaml'"), std::string::npos) << extra.err;
}

TEST(Cli, Cast_WritesOneRowPerRayInInputOrder) {
  const std::string scene = write("box.yaml", kBoxScene);
  const std::string rays = write("rays.txt",
                                 "# comment line\n"
                                 "0 0 -5 0 0 1\n"
                                 "\n"
                                 "0 5 0 1 0 0\n"
                                 "   5 0 -5 0 0 2   \n"
                                 "0 0 -5 0 0 1 0 3.5\n"
                                 "0 0 -5 0 0 1 4 4\n");
  const Outcome r = run("cast '" + scene + "' --rays '" + rays + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = lines(r.out);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0], "4 0 0 -1 0 0 -1 0.5 0.5 0 -1");
  EXPECT_EQ(rows[1], kMiss);
  const auto s = numbers(rows[2]);  // sphere at (5, 0, 0) from z = -5 with |d| = 2: t = 2
  ASSERT_EQ(s.size(), 11u);
  EXPECT_EQ(s[0], 2);
  EXPECT_EQ(s[3], -1);
  EXPECT_EQ(s[6], -1);
  EXPECT_EQ(s[9], 1);
  EXPECT_EQ(s[10], -1);
  EXPECT_EQ(rows[3], kMiss);                           // tmax 3.5 stops short of the box
  EXPECT_EQ(rows[4], "4 0 0 -1 0 0 -1 0.5 0.5 0 -1");  // tmin = tmax = t: inclusive
}

TEST(Cli, CastFromStdin_SameAsFromFile) {
  const std::string scene = write("box.yaml", kBoxScene);
  const std::string rays = write("rays.txt", "0 0 -5 0 0 1\n");
  const Outcome r = run("cast '" + scene + "' <'" + rays + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "4 0 0 -1 0 0 -1 0.5 0.5 0 -1\n");
}

TEST(Cli, CastAny_WritesOneOrZero) {
  const std::string scene = write("box.yaml", kBoxScene);
  const std::string rays = write(
      "rays.txt", "0 0 -5 0 0 1\n0 5 0 1 0 0\n0 0 -5 0 0 1 0 3.9\n0 0 -5 0 0 1 0 4\n0 0 0 1 0 0\n");
  const Outcome r = run("cast --any '" + scene + "' --rays '" + rays + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "1\n0\n0\n1\n1\n");
}

TEST(Cli, CastAll_ListsEveryCrossingInOrder) {
  const std::string scene = write("box.yaml", kBoxScene);
  const std::string rays = write("rays.txt", "-5 0 0 1 0 0\n0 5 0 1 0 0\n-5 0 0 1 0 0 5 9\n");
  const Outcome r = run("cast --all '" + scene + "' --rays '" + rays + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = lines(r.out);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], "4 4 -1 0 0 0 6 1 0 0 0 9 -1 0 0 1 11 1 0 0 1");
  EXPECT_EQ(rows[1], "0");
  EXPECT_EQ(rows[2], "2 6 1 0 0 0 9 -1 0 0 1");
}

TEST(Cli, CastAll_OpenSurfacesCrossOnce) {
  const std::string scene = write("open.yaml", R"(objects:
  - triangle: {vertices: [[0, 0, 0], [2, 0, 0], [0, 2, 0]]}
  - disk: {radius: 1, height: -2}
  - parallelogram: {origin: [-1, -1, -4], u: [0, 2, 0], v: [2, 0, 0]}
)");
  const std::string rays = write("rays.txt", "0.5 0.5 5 0 0 -1\n");
  const Outcome r = run("cast --all '" + scene + "' --rays '" + rays + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "3 5 0 0 1 0 7 0 0 1 1 9 0 0 -1 2\n");
  const Outcome n = run("cast '" + scene + "' --rays '" + rays + "'");
  EXPECT_EQ(n.out, "5 0.5 0.5 0 0 0 1 0.25 0.25 0 -1\n");
}

TEST(Cli, CastBinary_RoundTripsTheTextAnswers) {
  const std::string scene = write("box.yaml", kBoxScene);
  const std::vector<std::vector<double>> rays = {{0, 0, -5, 0, 0, 1, 0, INFINITY},
                                                 {0, 5, 0, 1, 0, 0, 0, INFINITY},
                                                 {0.3, -0.2, -5, 0.1, 0.05, 1, 0, INFINITY},
                                                 {5.5, 0.2, 7, 0, 0, -3, 0, INFINITY}};
  std::string bin, text;
  for (const auto& r : rays) {
    bin.append(reinterpret_cast<const char*>(r.data()), 8 * sizeof(double));
    char buf[256];
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", r[0], r[1],
                  r[2], r[3], r[4], r[5], r[6], r[7]);
    text += buf;
  }
  const std::string bin_path = write("rays.bin", bin), text_path = write("rays.txt", text);
  const Outcome t = run("cast '" + scene + "' --rays '" + text_path + "'");
  ASSERT_EQ(t.code, 0) << t.err;
  const Outcome b = run("cast --binary '" + scene + "' --rays '" + bin_path + "'");
  ASSERT_EQ(b.code, 0) << b.err;
  ASSERT_EQ(b.out.size(), rays.size() * 11 * sizeof(double));
  std::vector<double> got(rays.size() * 11);
  std::memcpy(got.data(), b.out.data(), b.out.size());
  const auto rows = lines(t.out);
  ASSERT_EQ(rows.size(), rays.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto want = numbers(rows[i]);
    ASSERT_EQ(want.size(), 11u);
    for (int k = 0; k < 11; ++k) {
      if (std::isnan(want[k]))
        EXPECT_TRUE(std::isnan(got[i * 11 + k])) << "ray " << i << " column " << k;
      else
        EXPECT_EQ(got[i * 11 + k], want[k]) << "ray " << i << " column " << k;
    }
  }
  EXPECT_EQ(got[11 * 1 + 0], INFINITY);
  EXPECT_EQ(got[11 * 1 + 9], -1);
  // A truncated record is an error naming the ray.
  const Outcome bad =
      run("cast --binary '" + scene + "' --rays '" + write("short.bin", bin.substr(0, 100)) + "'");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("ray 2: truncated record"), std::string::npos) << bad.err;
}

TEST(Cli, MalformedRayLine_ExitsTwoNamingTheLine) {
  const std::string scene = write("box.yaml", kBoxScene);
  const std::string rays = write("bad.txt", "0 0 -5 0 0 1\n# fine\n0 0 x 0 0 1\n");
  const Outcome r = run("cast '" + scene + "' --rays '" + rays + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find(rays + ":3:5: expected a number"), std::string::npos) << r.err;
  const Outcome few = run("cast '" + scene + "' --rays '" + write("few.txt", "1 2 3 4 5\n") + "'");
  EXPECT_EQ(few.code, 2);
  EXPECT_NE(few.err.find(":1:1: expected ox oy oz dx dy dz [tmin [tmax]], got 5 numbers"),
            std::string::npos)
      << few.err;
  const Outcome zero =
      run("cast '" + scene + "' --rays '" + write("zero.txt", "\n\n0 0 0 0 0 0\n") + "'");
  EXPECT_EQ(zero.code, 2);
  EXPECT_NE(zero.err.find(":3:1: ray direction must be finite and non-zero"), std::string::npos)
      << zero.err;
  const Outcome nan =
      run("cast '" + scene + "' --rays '" + write("nan.txt", "nan 0 0 1 0 0\n") + "'");
  EXPECT_EQ(nan.code, 2);
  EXPECT_NE(nan.err.find(":1:1: ray origin must be finite"), std::string::npos) << nan.err;
}

TEST(Cli, MissingOrBadScene_ExitsTwoWithPosition) {
  const Outcome r = run("cast /nonexistent/scene.yaml </dev/null");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("/nonexistent/scene.yaml: cannot open the scene file"), std::string::npos)
      << r.err;
  const std::string bad = write("bad.yaml", "objects:\n  - sphere: {radius: -1}\n");
  const Outcome b = run("info '" + bad + "'");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find(bad + ":2:22: sphere.radius must be > 0, got -1"), std::string::npos)
      << b.err;
  const Outcome missing_rays =
      run("cast '" + write("box.yaml", kBoxScene) + "' --rays /nonexistent/rays.txt");
  EXPECT_EQ(missing_rays.code, 2);
}

TEST(Cli, Info_ReportsObjectsByTypeAndBounds) {
  const std::string scene = write("box.yaml", kBoxScene);
  const Outcome r = run("info '" + scene + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("entries: 2\nobjects: 2\n  box: 1\n  sphere: 1\n"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("bounds: [-1, -1, -1] - [6, 1, 1]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("acceleration: top-level BVH"), std::string::npos) << r.out;
}

}  // namespace

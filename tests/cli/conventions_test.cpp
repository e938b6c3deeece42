// The CLI conventions of docs/cli.md: `-` for standard input and output, one meaning of
// `--threads 0`, outputs checked before any work (exit 1), a warning for a scene with no lights.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../support/cli_runner.h"

namespace {

using raycast::test::Outcome;
using raycast::test::read;
using raycast::test::run;
using raycast::test::temp_dir;
using raycast::test::write;

const char* const kLitSphere =
    "image: {width: 16, height: 12, samples: 1}\n"
    "lights:\n  - {type: point, position: [5, 5, -5], color: [1, 1, 1], intensity: 1.0}\n"
    "objects:\n  - sphere: {center: [0, 0, 0], radius: 1}\n";

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(CliConventions, SceneFromStandardInput_SameAsFromFile) {
  const std::string scene = write("lit.yaml", kLitSphere);
  const std::string rays = write("rays.txt", "0 0 -5 0 0 1\n3 3 -5 0 0 1\n");
  const Outcome from_file = run("cast '" + scene + "' --rays '" + rays + "'");
  const Outcome from_stdin = run("cast - --rays '" + rays + "' < '" + scene + "'");
  ASSERT_EQ(from_file.code, 0) << from_file.err;
  EXPECT_EQ(from_stdin.code, 0) << from_stdin.err;
  EXPECT_EQ(from_stdin.out, from_file.out);
  EXPECT_TRUE(contains(from_file.out, "4 "));  // t = 4 for the first ray
  // A mistake in a scene read from stdin is positioned in "<stdin>".
  const std::string bad = write("bad.yaml", "objects:\n  - sphere: {radius: -1}\n");
  const Outcome b = run("info - < '" + bad + "'");
  EXPECT_EQ(b.code, 2);
  EXPECT_TRUE(contains(b.err, "<stdin>:2:")) << b.err;
}

TEST(CliConventions, SceneAndRaysBothOnStandardInput_IsAnError) {
  const std::string scene = write("lit2.yaml", kLitSphere);
  for (const char* rays : {"", " --rays -"}) {
    const Outcome r = run(std::string("cast -") + rays + " < '" + scene + "'");
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(contains(r.err, "cannot both come from standard input")) << r.err;
  }
}

TEST(CliConventions, RenderToStandardOutput_IsThePngTheFileGets) {
  const std::string scene = write("lit3.yaml", kLitSphere);
  const std::string file = (temp_dir() / "lit3.png").string();
  const Outcome to_file = run("render '" + scene + "' -o '" + file + "'");
  ASSERT_EQ(to_file.code, 0) << to_file.err;
  const Outcome to_stdout = run("render '" + scene + "' -o -");
  ASSERT_EQ(to_stdout.code, 0) << to_stdout.err;
  EXPECT_EQ(to_stdout.out.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(to_stdout.out, read(file));
  EXPECT_TRUE(contains(to_stdout.err, "-> <stdout>")) << to_stdout.err;
  // AOVs and frames write files beside -o: refused with -.
  EXPECT_EQ(run("render '" + scene + "' -o - --aov depth").code, 2);
  EXPECT_EQ(run("render '" + scene + "' -o - --frames 0-1").code, 2);
}

TEST(CliConventions, UnwritableOutput_ExitOneBeforeRendering) {
  const std::string scene = write("lit4.yaml", kLitSphere);
  const std::string missing_dir = (temp_dir() / "no_such_dir" / "out.png").string();
  // Huge samples would take minutes: the check must come first.
  const Outcome r =
      run("render '" + scene + "' --spp 65536 --width 2000 --height 2000 -o '" + missing_dir + "'");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "no_such_dir")) << r.err;
  EXPECT_LT(r.seconds, 20);
  const Outcome dir = run("render '" + scene + "' -o '" + temp_dir().string() + "'");
  EXPECT_EQ(dir.code, 2) << dir.err;  // no extension: a bad option, not an unwritable file
  const Outcome frames = run("render '" + scene + "' --frames 0-1 -o '" +
                             (temp_dir() / "nope" / "f_{frame}.png").string() + "'");
  EXPECT_EQ(frames.code, 1) << frames.err;
  // The check leaves no file behind, and an existing file is not touched until the image is ready.
  const std::string out = (temp_dir() / "fresh.png").string();
  EXPECT_EQ(run("render '" + scene + "' -o '" + out + "' --width 0").code, 2);
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliConventions, ThreadsZero_MeansAllCoresInRender) {
  const std::string scene = write("lit5.yaml", kLitSphere);
  const std::string out = (temp_dir() / "t0.png").string();
  const Outcome r = run("render '" + scene + "' -o '" + out + "' --threads 0");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(run("render '" + scene + "' -o '" + out + "' --threads -1").code, 2);
}

TEST(CliConventions, NoLights_WarnsUnderWhitted) {
  const std::string dark = write("dark.yaml",
                                 "image: {width: 8, height: 6, samples: 1}\n"
                                 "objects:\n  - sphere: {radius: 1}\n");
  const std::string out = (temp_dir() / "dark.png").string();
  const Outcome r = run("render '" + dark + "' -o '" + out + "'");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "warning: the scene has no lights")) << r.err;
  const Outcome normal = run("render '" + dark + "' -o '" + out + "' --integrator normal");
  EXPECT_FALSE(contains(normal.err, "no lights")) << normal.err;
  EXPECT_FALSE(contains(run("render '" + write("lit6.yaml", kLitSphere) + "' -o '" + out + "'").err,
                        "no lights"));
}

}  // namespace

namespace {

TEST(CliConventions, BenchOnAScene_WithoutMeshes_ReportsNoPerTriangleFigures) {
  const std::string scene = write("bench.yaml", kLitSphere);
  const Outcome text = run("bench '" + scene + "' --repeat 1 --threads 1");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_TRUE(contains(text.out, "scene: ")) << text.out;
  EXPECT_FALSE(contains(text.out, "bytes/triangle")) << text.out;
  const Outcome json = run("bench '" + scene + "' --repeat 1 --threads 1 --json");
  ASSERT_EQ(json.code, 0) << json.err;
  EXPECT_TRUE(contains(json.out, "\"raycast_bytes_per_tri\": null")) << json.out;
}

TEST(CliConventions, BenchTuningNumbers_NaNOrOutOfRange_ExitTwo) {
  for (const char* option : {"--split-budget", "--split-min-ratio", "--traversal-cost"})
    for (const char* value : {"nan", "-1", "inf"}) {
      const Outcome r =
          run(std::string("bench --procedural sphere:1000 --repeat 1 ") + option + " " + value);
      EXPECT_EQ(r.code, 2) << option << " " << value;
      EXPECT_TRUE(contains(r.err, option)) << r.err;
    }
}

}  // namespace

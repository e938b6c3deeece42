// `raycast compare`: the figures, --threshold's exit codes, --json, --diff, sizes that differ.
#include <gtest/gtest.h>

#include <string>

#include "../support/cli_runner.h"

namespace {

using raycast::test::Outcome;
using raycast::test::run;
using raycast::test::temp_dir;
using raycast::test::write;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Renders a tiny scene at w x h, with the sphere at x = shift, to NAME.png; returns the path.
std::string render(const std::string& name, double shift, int w = 16, int h = 12) {
  const std::string scene = write(name + ".yaml",
                                  "lights:\n  - {type: point, position: [0, 5, 5]}\n"
                                  "camera: {position: [0, 0, 5], look_at: [0, 0, 0]}\n"
                                  "objects:\n  - sphere: {center: [" +
                                      std::to_string(shift) + ", 0, 0], radius: 1}\n");
  const std::string png = (temp_dir() / (name + ".png")).string();
  const Outcome r = run("render '" + scene + "' -o '" + png + "' --width " + std::to_string(w) +
                        " --height " + std::to_string(h));
  EXPECT_EQ(r.code, 0) << r.err;
  return png;
}

TEST(Compare, SameImage_IsZeroAndClose) {
  const std::string a = render("same", 0);
  const Outcome r = run("compare '" + a + "' '" + a + "' --threshold 0");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "block-4 mean abs diff 0.000, mean 0.000, max 0")) << r.out;
  EXPECT_TRUE(has(r.out, "close (threshold 0)")) << r.out;
}

TEST(Compare, MovedSphere_ExitsOneAboveTheThreshold_ZeroBelow) {
  const std::string a = render("left", 0), b = render("right", 0.8);
  const Outcome far = run("compare '" + a + "' '" + b + "' --threshold 0.5 --json");
  EXPECT_EQ(far.code, 1) << far.out << far.err;
  EXPECT_TRUE(has(far.out, "\"close\": false")) << far.out;
  EXPECT_TRUE(has(far.out, "\"block\": 4")) << far.out;
  const Outcome near = run("compare '" + a + "' '" + b + "' --threshold 255 --block 2");
  EXPECT_EQ(near.code, 0) << near.out << near.err;
  EXPECT_TRUE(has(near.out, "block-2 mean abs diff")) << near.out;
}

TEST(Compare, Diff_WritesTheDifferenceImage) {
  const std::string a = render("d1", 0), b = render("d2", 0.8);
  const std::string diff = (temp_dir() / "diff.png").string();
  const Outcome ab = run("compare '" + a + "' '" + b + "' --diff '" + diff + "' --json");
  EXPECT_EQ(ab.code, 0) << ab.err;
  // Against a black image (the sphere out of view) the difference image shows the same max.
  const std::string black = render("black", 100);
  const Outcome d = run("compare '" + diff + "' '" + black + "' --json");
  const auto max_of = [](const std::string& json) {
    const std::size_t at = json.find("\"max\": ");
    return at == std::string::npos ? -1 : std::stoi(json.substr(at + 7));
  };
  EXPECT_GT(max_of(ab.out), 0) << ab.out;
  EXPECT_EQ(max_of(d.out), max_of(ab.out)) << d.out;
}

TEST(Compare, DifferentSizes_ExitTwo) {
  const std::string a = render("small", 0, 16, 12), b = render("large", 0, 20, 12);
  const Outcome r = run("compare '" + a + "' '" + b + "'");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "sizes differ")) << r.err;
  EXPECT_TRUE(has(r.err, "16x12")) << r.err;
}

TEST(Compare, MissingFile_ExitsTwo) {
  const Outcome r = run("compare /nonexistent/a.png /nonexistent/b.png");
  EXPECT_EQ(r.code, 2);
  EXPECT_TRUE(has(r.err, "/nonexistent/a.png")) << r.err;
}

}  // namespace

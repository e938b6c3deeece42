// `raycast explain` and the recording options of `raycast render` (--stats, the term and cost
// outputs, --heatmap, the --max-depth sweep), run as a user runs them.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/image.h"

namespace raycast {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  int code = -1;
  std::string out;  // standard output, then standard error
};

CliRun run(const std::string& args) {
  CliRun r;
  const std::string command = std::string(RAYCAST_BINARY) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  for (std::size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
    r.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

class ExplainCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("raycast_explain_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string scene(const char* name) {
    return std::string(RAYCAST_SOURCE_DIR) + "/" + name;
  }
  fs::path dir_;
};

TEST_F(ExplainCli, Json_RootColourIsTheRenderedPixel) {
  ASSERT_EQ(run("render -o " + path("demo.pfm") + " --width 32 --height 24 --spp 1").code, 0);
  const Image image = load_pfm(path("demo.pfm"));
  for (const auto& [x, y] : {std::pair{16, 12}, std::pair{3, 20}, std::pair{25, 5}}) {
    const CliRun r = run("explain --pixel " + std::to_string(x) + " " + std::to_string(y) +
                         " --width 32 --height 24 --spp 1 --json");
    ASSERT_EQ(r.code, 0) << r.out;
    const YAML::Node root = YAML::Load(r.out);
    EXPECT_EQ(float(root["color"][0].as<double>()), image.at(x, y).x);
    EXPECT_EQ(float(root["color"][1].as<double>()), image.at(x, y).y);
    EXPECT_EQ(float(root["color"][2].as<double>()), image.at(x, y).z);
    EXPECT_EQ(root["ray"]["kind"].as<std::string>(), "camera");
  }
}

TEST_F(ExplainCli, Text_ShowsTheShadingSum) {
  const CliRun r = run("explain " + scene("scenes/demo.yaml") + " --pixel 320 300");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("camera ray, depth 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("= ambient"), std::string::npos) << r.out;
}

TEST_F(ExplainCli, Svg_IsWritten) {
  const CliRun r =
      run("explain " + scene("scenes/demo.yaml") + " --pixel 320 240 --svg " + path("tree.svg"));
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream in(path("tree.svg"));
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
}

TEST_F(ExplainCli, PixelOutsideTheImage_ExitTwo) {
  const CliRun r = run("explain --pixel 800 0");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.out.find("outside"), std::string::npos) << r.out;
  EXPECT_EQ(run("explain --pixel 1").code, 2);
  EXPECT_EQ(run("explain --pixel 1 1 --json --svg x.svg").code, 2);
}

TEST_F(ExplainCli, PovScene_IsExplained) {
  const std::string pov = path("scene.pov");
  std::ofstream(pov) << "camera { location <0, 1, -4> look_at <0, 0.5, 0> }\n"
                        "light_source { <3, 5, -4> color rgb 1 }\n"
                        "sphere { <0, 0.5, 0>, 0.8 pigment { color rgb <1, 0.2, 0.2> } }\n"
                        "plane { y, 0 pigment { color rgb 1 } }\n";
  const CliRun r = run("explain " + pov + " --pixel 160 120 --width 320 --height 240 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  const YAML::Node root = YAML::Load(r.out);
  EXPECT_TRUE(root["ray"]["hit"].IsMap());
  EXPECT_EQ(root["ray"]["hit"]["shape"].as<std::string>(), "sphere");
}

TEST_F(ExplainCli, NamedObjects_AreNamedInTheTree) {
  const std::string yaml = path("named.yaml");
  std::ofstream(yaml)
      << "camera: {position: [0, 0, -4], look_at: [0, 0, 0], fov: 40}\n"
         "lights: [{type: point, position: [3, 5, -4]}]\n"
         "objects:\n"
         "  - {sphere: {center: [0, 0, 0], radius: 1}, name: \"red \\\"ball\\\"\"}\n";
  CliRun r = run("explain " + yaml + " --pixel 16 12 --width 32 --height 24");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("sphere #0 'red \"ball\"'"), std::string::npos) << r.out;
  r = run("explain " + yaml + " --pixel 16 12 --width 32 --height 24 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(YAML::Load(r.out)["ray"]["hit"]["name"].as<std::string>(), "red \"ball\"");

  const std::string pov = path("named.pov");
  std::ofstream(pov) << "camera { location <0, 0, -4> look_at 0 }\n"
                        "light_source { <3, 5, -4> color rgb 1 }\n"
                        "#declare Ball = sphere { 0, 1 pigment { color rgb 1 } }\n"
                        "object { Ball }\n";
  r = run("explain " + pov + " --pixel 16 12 --width 32 --height 24 --json");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(YAML::Load(r.out)["ray"]["hit"]["name"].as<std::string>(), "Ball");
}

TEST_F(ExplainCli, RenderStats_PrintsTheReport) {
  const CliRun r = run("render " + scene("scenes/demo.yaml") + " -o " + path("s.png") +
                       " --width 32 --height 24 --spp 1 --stats");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* word : {"rays by kind", "shadow", "time by phase", "per pixel"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word << "\n" << r.out;
}

TEST_F(ExplainCli, TermAndCostOutputs_AreWrittenWithHeatmaps) {
  const CliRun r = run("render " + scene("scenes/demo.yaml") + " -o " + path("t.pfm") +
                       " --width 32 --height 24 --spp 1 --heatmap --aov "
                       "ambient,diffuse,specular,reflection,refraction,shadowed,cost.rays,"
                       "cost.depth,cost.time");
  ASSERT_EQ(r.code, 0) << r.out;
  const Image beauty = load_pfm(path("t.pfm"));
  Image sum(32, 24);
  for (const char* term : {"ambient", "diffuse", "specular", "reflection", "refraction"}) {
    const Image t = load_pfm(path(std::string("t.") + term + ".pfm"));
    for (std::size_t i = 0; i < sum.rgb.size(); ++i) sum.rgb[i] += t.rgb[i];
  }
  for (std::size_t i = 0; i < sum.rgb.size(); ++i)
    EXPECT_NEAR(sum.rgb[i], beauty.rgb[i], 1e-6 * (1 + beauty.rgb[i]));
  for (const char* cost : {"shadowed", "cost.rays", "cost.depth", "cost.time"}) {
    EXPECT_TRUE(fs::exists(path(std::string("t.") + cost + ".pfm"))) << cost;
    EXPECT_EQ(load_png(path(std::string("t.") + cost + ".png")).width, 32 + 48) << cost;
  }
  EXPECT_NE(r.out.find("cost.rays heatmap"), std::string::npos) << r.out;
  EXPECT_EQ(run("render -o " + path("u.png") + " --aov cost.nodez").code, 2);
  EXPECT_EQ(run("render -o " + path("u.png") + " --heatmap").code, 2);
}

TEST_F(ExplainCli, MaxDepthSweep_WritesOneContactSheet) {
  const CliRun r = run("render " + scene("scenes/demo.yaml") + " -o " + path("sweep.png") +
                       " --width 40 --height 30 --spp 1 --max-depth 0-3");
  ASSERT_EQ(r.code, 0) << r.out;
  const Image sheet = load_png(path("sweep.png"));
  EXPECT_EQ(sheet.width, 4 * 40 + 5 * 4);
  EXPECT_EQ(run("render -o " + path("x.png") + " --max-depth 3-1").code, 2);
  EXPECT_EQ(run("render -o " + path("x.png") + " --max-depth 2 --width 8 --height 6").code, 0);
}

}  // namespace
}  // namespace raycast

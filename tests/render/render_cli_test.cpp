// `raycast render` end to end: the binary is run as a user would run it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/image.h"

namespace raycast {
namespace {

namespace fs = std::filesystem;

/// Runs the CLI with arguments (shell-quoted by the caller); returns its exit code.
int run(const std::string& args) {
  const std::string command = std::string(RAYCAST_BINARY) + " " + args + " 2>/dev/null";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class RenderCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("raycast_render_cli_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(RenderCli, Demo_WritesAPngOfTheRequestedSize) {
  ASSERT_EQ(run("render -o " + path("demo.png") + " --width 24 --height 10 --spp 1"), 0);
  const Image image = load_png(path("demo.png"));
  EXPECT_EQ(image.width, 24);
  EXPECT_EQ(image.height, 10);
}

TEST_F(RenderCli, SceneFile_IsRendered) {
  const std::string scene = std::string(RAYCAST_SOURCE_DIR) + "/scenes/demo.yaml";
  ASSERT_EQ(
      run("render " + scene + " -o " + path("file.pfm") + " --width 8 --height 6 --threads 1"), 0);
  const Image image = load_pfm(path("file.pfm"));
  EXPECT_EQ(image.width, 8);
  EXPECT_EQ(image.height, 6);
}

TEST_F(RenderCli, Aovs_AreWrittenBesideTheOutput) {
  ASSERT_EQ(run("render -o " + path("a.png") +
                " --width 8 --height 6 --spp 1 --aov depth,normal,id,albedo"),
            0);
  for (const char* aov : {"depth", "normal", "id", "albedo"}) {
    const std::string file = path(std::string("a.") + aov + ".pfm");
    ASSERT_TRUE(fs::exists(file)) << file;
    EXPECT_EQ(load_pfm(file).width, 8);
  }
}

TEST_F(RenderCli, Integrators_AllRun) {
  for (const char* integrator : {"whitted", "raycast", "depth", "normal", "id"})
    EXPECT_EQ(
        run("render -o " + path("i.png") + " --width 6 --height 4 --integrator " + integrator), 0)
        << integrator;
}

TEST_F(RenderCli, DepthPng_IsScaledForViewing) {
  ASSERT_EQ(
      run("render -o " + path("z.png") + " --width 16 --height 12 --spp 1 --integrator depth"), 0);
  const Image z = load_png(path("z.png"));
  EXPECT_EQ(z.at(8, 0), (Vec3f{1, 1, 1}));  // the sky: a miss
  const float floor = z.at(8, 11).x;        // the floor just below the camera
  EXPECT_GT(floor, 0.05f);
  EXPECT_LT(floor, 0.95f);
}

TEST_F(RenderCli, Antialias_EveryMethodRunsAndBadSpecsExitWithTwo) {
  for (const std::string spec : {"1", "2,0.2", "variance,0.1,4", "neighbour,0,2", "none"})
    EXPECT_EQ(run("render -o " + path("aa.png") + " --width 12 --height 9 --antialias " + spec), 0)
        << spec;
  for (const std::string spec :
       {"3", "1,-0.1", "1,0.3,0", "1,0.3,17", "1,x", "1,0.3,3,4", "none,1", "1,nan", "''"})
    EXPECT_EQ(run("render -o " + path("aa.png") + " --width 12 --height 9 --antialias " + spec), 2)
        << spec;
}

TEST_F(RenderCli, BadValues_ExitWithTwo) {
  const std::string out = " -o " + path("bad.png");
  EXPECT_EQ(run("render" + out + " --width 0"), 2);
  EXPECT_EQ(run("render" + out + " --width -5"), 2);
  EXPECT_EQ(run("render" + out + " --width abc"), 2);
  EXPECT_EQ(run("render" + out + " --height 100000"), 2);
  EXPECT_EQ(run("render" + out + " --spp 0"), 2);
  EXPECT_EQ(run("render" + out + " --threads -1"), 2);
  EXPECT_EQ(run("render" + out + " --integrator phong"), 2);
  EXPECT_EQ(run("render" + out + " --aov depth,colour"), 2);
  EXPECT_EQ(run("render -o " + path("bad.bmp")), 2);
  EXPECT_EQ(run("render " + path("no_such_scene.yaml") + out), 2);
  EXPECT_FALSE(fs::exists(path("bad.png")));
}

}  // namespace
}  // namespace raycast

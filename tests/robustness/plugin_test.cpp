// OpenVDB and assimp are read through plugins loaded on first use (io/plugin_library.h): commands
// that read no .vdb grid or glTF mesh never load them, and a missing plugin is a positioned error.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "../support/cli_runner.h"
#include "io/mesh_file.h"
#include "volume/vdb_file.h"

namespace raycast {
namespace {

// Sets an environment variable for the CLI runs of one test.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() { ::unsetenv(name_); }

 private:
  const char* name_;
};

TEST(Plugins, CommandsWithoutAGridOrGltf_LoadNeither) {
  test::Outcome run;
  {
    ScopedEnv debug("LD_DEBUG", "libs");  // glibc's loader lists every library it loads
    run = test::run("--version");
  }
  ASSERT_EQ(run.code, 0) << run.err;
  ASSERT_NE(run.err.find("libstdc++"), std::string::npos) << "no loader trace:\n" << run.err;
  EXPECT_EQ(run.err.find("libopenvdb"), std::string::npos);
  EXPECT_EQ(run.err.find("libraycast_openvdb"), std::string::npos);
  EXPECT_EQ(run.err.find("libassimp"), std::string::npos);
  EXPECT_EQ(run.err.find("libOpenEXR"), std::string::npos);
}

#if RAYCAST_HAVE_OPENVDB

TEST(Plugins, MissingOpenVdbPlugin_IsAnErrorAtTheGridField) {
  const std::string empty_dir = (test::temp_dir() / "no_plugins").string();
  test::fs::create_directories(empty_dir);
  test::write("g.vdb", "not read: the plugin is missing first\n");
  const std::string scene =
      test::write("plugin.yaml", "objects:\n  - isosurface: {grid: g.vdb, iso: 0.5}\n");
  test::Outcome run;
  {
    ScopedEnv dir("RAYCAST_PLUGIN_DIR", empty_dir);
    run = test::run("info '" + scene + "'");
  }
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_NE(run.err.find("plugin.yaml:2:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("libraycast_openvdb.so"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("RAYCAST_PLUGIN_DIR"), std::string::npos) << run.err;
}

TEST(Plugins, ThisBuild_LoadsTheOpenVdbPlugin) {
  EXPECT_TRUE(vdb_supported()) << vdb_unsupported_reason();
}

#endif

#if RAYCAST_HAVE_ASSIMP

TEST(Plugins, MissingAssimpPlugin_IsAnErrorAtTheFileField) {
  const std::string empty_dir = (test::temp_dir() / "no_plugins").string();
  test::fs::create_directories(empty_dir);
  test::write("m.gltf", "{}\n");
  const std::string scene = test::write("gltf.yaml", "objects:\n  - mesh: {file: m.gltf}\n");
  test::Outcome run;
  {
    ScopedEnv dir("RAYCAST_PLUGIN_DIR", empty_dir);
    run = test::run("info '" + scene + "'");
  }
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_NE(run.err.find("gltf.yaml:2:"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("libraycast_assimp.so"), std::string::npos) << run.err;
}

#endif

}  // namespace
}  // namespace raycast

// Every example scene under scenes/ loads (found at run time, so new scenes are covered too).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast {
namespace {

std::vector<std::filesystem::path> example_scenes() {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path dir = std::filesystem::path(RAYCAST_SOURCE_DIR) / "scenes";
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".yaml")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(Scenes, EveryExampleScene_Loads) {
  const auto files = example_scenes();
  EXPECT_GE(files.size(), 6u);
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    try {
      const Scene s = load_scene_file(f.string());
      EXPECT_FALSE(s.objects.empty());
    } catch (const SceneError& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

TEST(Scenes, EachBasicShape_HasItsOwnSceneWithCameraAndLight) {
  for (const char* name : {"sphere", "plane", "box", "triangle", "parallelogram", "disk"}) {
    SCOPED_TRACE(name);
    const auto path =
        std::filesystem::path(RAYCAST_SOURCE_DIR) / "scenes" / (std::string(name) + ".yaml");
    const Scene s = load_scene_file(path.string());
    EXPECT_TRUE(s.camera.has_value());
    EXPECT_FALSE(s.lights.empty());
    const bool has = std::any_of(s.objects.begin(), s.objects.end(), [&](const Object& o) {
      return std::string(shape_name(o)) == name;
    });
    EXPECT_TRUE(has);
  }
}

}  // namespace
}  // namespace raycast

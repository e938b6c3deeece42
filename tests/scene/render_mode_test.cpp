#include "scene/render_mode.h"

#include <gtest/gtest.h>

#include "load/loader.h"

namespace raycast {
namespace {

constexpr RenderMode kAll[] = {RenderMode::kWhitted, RenderMode::kRaycast, RenderMode::kDepth,
                               RenderMode::kNormal,  RenderMode::kId,      RenderMode::kAlbedo};

TEST(RenderMode, EveryName_ReadsBackAsItsMode) {
  for (RenderMode mode : kAll) {
    const std::string name = render_mode_name(mode);
    const bool integrator = mode != RenderMode::kAlbedo;
    const bool aov = mode != RenderMode::kWhitted && mode != RenderMode::kRaycast;
    EXPECT_EQ(integrator_named(name), integrator ? std::optional(mode) : std::nullopt) << name;
    EXPECT_EQ(aov_named(name), aov ? std::optional(mode) : std::nullopt) << name;
    // The messages list exactly the accepted names.
    EXPECT_EQ(std::string(kIntegratorNames).find(name) != std::string::npos, integrator) << name;
    EXPECT_EQ(std::string(kAovNames).find(name) != std::string::npos, aov) << name;
  }
  EXPECT_EQ(integrator_named("Whitted"), std::nullopt);
  EXPECT_EQ(aov_named(""), std::nullopt);
}

TEST(RenderMode, AovList_KeepsOrderAndNamesTheFirstBadEntry) {
  std::vector<std::pair<std::string, RenderMode>> aovs;
  std::string bad;
  ASSERT_TRUE(parse_aov_list("albedo,depth", aovs, bad));
  ASSERT_EQ(aovs.size(), 2u);
  EXPECT_EQ(aovs[0], std::make_pair(std::string("albedo"), RenderMode::kAlbedo));
  EXPECT_EQ(aovs[1], std::make_pair(std::string("depth"), RenderMode::kDepth));
  aovs.clear();
  EXPECT_TRUE(parse_aov_list("", aovs, bad));
  EXPECT_TRUE(aovs.empty());
  EXPECT_FALSE(parse_aov_list("normal,whitted,nope", aovs, bad));
  EXPECT_EQ(bad, "whitted");
}

TEST(RenderMode, SceneIntegrator_UsesTheTable) {
  const Scene scene =
      load_scene_text("render: {integrator: normal}\nobjects: [{sphere: {radius: 1}}]\n", "s.yaml");
  EXPECT_EQ(scene.render.integrator, RenderMode::kNormal);
  EXPECT_THROW(load_scene_text("render: {integrator: albedo}\nobjects: []\n", "s.yaml"),
               std::exception);
}

}  // namespace
}  // namespace raycast

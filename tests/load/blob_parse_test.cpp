#include <gtest/gtest.h>

#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast {
namespace {

void expect_blob_error_at(const std::string& yaml, int line, int column,
                          const std::string& fragment) {
  try {
    load_scene_text(yaml, "s.yaml");
    ADD_FAILURE() << "no error for\n" << yaml;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(BlobParse, SpheresAndCylinders_Load) {
  const Scene s = load_scene_text(
      "objects:\n"
      "  - blob:\n"
      "      threshold: 0.6\n"
      "      components:\n"
      "        - {center: [0, 0, 0], radius: 1}\n"
      "        - {from: [0, 0, 0], to: [1, 0, 0], radius: 0.5, strength: -0.5}\n"
      "        - {center: [1, 1, 0], radius: 1, transform: [{scale: [2, 1, 1]}]}\n");
  ASSERT_EQ(s.objects.size(), 1u);
  // The third component's field reaches 1.45 (in x) from its centre before it drops below 0.6:
  // scaled by 2 along x, 2.9 from the blob's origin; the negative cylinder hollows the origin.
  EXPECT_TRUE(contains(s.objects[0], {2.9, 1, 0}));
  EXPECT_FALSE(contains(s.objects[0], {3.1, 1, 0}));
  EXPECT_FALSE(contains(s.objects[0], {0, 0, 0}));
}

TEST(BlobParse, Errors_Positioned) {
  expect_blob_error_at("objects:\n  - blob: {components: []}\n", 2, 24, "non-empty list");
  expect_blob_error_at("objects:\n  - blob: {threshold: 0, components: [{center: [0, 0, 0]}]}\n", 2,
                       23, "threshold");
  expect_blob_error_at("objects:\n  - blob: {components: [{center: [0, 0, 0], radius: -1}]}\n", 2,
                       53, "radius");
  expect_blob_error_at(
      "objects:\n  - blob: {components: [{center: [0, 0, 0], from: [0, 0, 0], to: [1, 0, 0], "
      "radius: 1}]}\n",
      2, 34, "center and from/to");
  expect_blob_error_at(
      "objects:\n  - blob: {components: [{center: [0, 0, 0], radius: 1, "
      "strength: -1}]}\n",
      2, 24, "positive strength");
  expect_blob_error_at(
      "objects:\n  - blob: {components: [{center: [0, 0, 0], radius: 1, size: 2}]}\n", 2, 56,
      "size");
}

}  // namespace
}  // namespace raycast

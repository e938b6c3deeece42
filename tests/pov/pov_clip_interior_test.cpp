// The reader's description of clipped_by, bounded_by, inverse and interior fade: what it keeps of
// each, as POV-Ray's reference defines them.
#include <gtest/gtest.h>

#include <string>

#include "pov/interpreter.h"

namespace raycast::pov {
namespace {

PovScene read(const std::string& text) {
  Options o;
  o.system_library_path = false;
  return interpret_pov(text, "t.pov", ".", o);
}

TEST(PovClip, ClippedBy_KeepsItsObjectsMovedByLaterTransformations) {
  const PovScene s =
      read("sphere { 0, 1 scale 2 clipped_by { plane { y, 0 } box { -1, 1 } } translate x }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  const Node& n = s.objects[0];
  ASSERT_EQ(n.clipped_by.size(), 2u);
  EXPECT_EQ(n.clipped_by[0].kind, Node::Plane);
  EXPECT_EQ(n.clipped_by[1].kind, Node::Box);
  // The scale came before clipped_by: the clips carry only the translation.
  ASSERT_EQ(n.clipped_by[0].xforms.size(), 1u);
  EXPECT_EQ(n.clipped_by[0].xforms[0].kind, XformOp::Translate);
  EXPECT_EQ(n.xforms.size(), 2u);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("clipped_by"), std::string::npos) << w;
}

TEST(PovClip, ClippedByBoundedBy_TakesTheBounds) {
  const PovScene s = read(
      "sphere { 0, 1 bounded_by { box { -1, 1 } } clipped_by { bounded_by } }\n"
      "sphere { 0, 1 clipped_by { box { -1, 1 } } bounded_by { clipped_by } }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  ASSERT_EQ(s.objects[0].clipped_by.size(), 1u);
  EXPECT_EQ(s.objects[0].clipped_by[0].kind, Node::Box);
  EXPECT_EQ(s.objects[1].clipped_by.size(), 1u);
}

TEST(PovClip, Inverse_TogglesWithoutAWarning) {
  const PovScene s = read("sphere { 0, 1 inverse }\nsphere { 0, 1 inverse inverse }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_TRUE(s.objects[0].inverse);
  EXPECT_FALSE(s.objects[1].inverse);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("inverse"), std::string::npos) << w;
}

TEST(PovInterior, FadeItems_AreKeptAndADeclaredInteriorIsAmended) {
  const PovScene s = read(
      "#declare I = interior { ior 1.33 fade_distance 2 fade_power 1001 }\n"
      "sphere { 0, 1 interior { I fade_colour <0.25, 0.5, 1> } }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_TRUE(s.objects[0].texture && s.objects[0].texture->interior);
  const Interior& in = *s.objects[0].texture->interior;
  EXPECT_EQ(in.ior, 1.33);
  EXPECT_EQ(in.fade_distance, 2);
  EXPECT_EQ(in.fade_power, 1001);
  EXPECT_EQ(in.fade_color.r, 0.25);
  EXPECT_EQ(in.fade_color.g, 0.5);
  EXPECT_EQ(in.fade_color.b, 1);
  for (const std::string& w : s.warnings) EXPECT_EQ(w.find("fade"), std::string::npos) << w;
}

}  // namespace
}  // namespace raycast::pov

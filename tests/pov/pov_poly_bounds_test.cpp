// A poly's bounded_by as the box raycast's algebraic solid needs: a box or a sphere, moved by its
// own transformations; other bounds and bounds after the poly's transformations leave it unbounded.
#include <gtest/gtest.h>

#include <string>

#include "pov/interpreter.h"

namespace raycast::pov {
namespace {

const Node& only_object(const PovScene& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return s.objects.at(0);
}

PovScene read(const std::string& text) {
  Options o;
  o.system_library_path = false;
  return interpret_pov(text, "t.pov", ".", o);
}

constexpr const char* kSphereQuadric = "poly { 2, <1,0,0,0,1,0,0,1,0,-1> ";

void expect_box(const Node& n, const Vec3& lo, const Vec3& hi) {
  ASSERT_TRUE(n.bounds.has_value());
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR((*n.bounds)[0][a], lo[a], 1e-12) << a;
    EXPECT_NEAR((*n.bounds)[1][a], hi[a], 1e-12) << a;
  }
}

TEST(PovPolyBounds, BoundedBySphere_IsTheSpheresBox) {
  const PovScene s =
      read(std::string(kSphereQuadric) + "bounded_by { sphere { <1, 2, 3>, 2 } } }\n");
  expect_box(only_object(s), {-1, 0, 1}, {3, 4, 5});
}

TEST(PovPolyBounds, BoundedByMovedBox_IsTheBoxOfItsMovedCorners) {
  const PovScene s =
      read(std::string(kSphereQuadric) +
           "bounded_by { box { <-1, -2, -3>, <1, 2, 3> rotate 90*z translate x } } }\n");
  // Rotated a quarter turn about z: x spans [-2, 2] and y [-1, 1]; then moved by +x.
  expect_box(only_object(s), {-1, -1, -3}, {3, 1, 3});
}

TEST(PovPolyBounds, BoundsAfterThePolysTransformation_AreNotTaken) {
  const PovScene s =
      read(std::string(kSphereQuadric) + "scale 2 bounded_by { sphere { 0, 2 } } }\n");
  EXPECT_FALSE(only_object(s).bounds.has_value());
}

TEST(PovPolyBounds, OtherBoundingShapes_LeaveThePolyUnbounded) {
  const PovScene s = read(std::string(kSphereQuadric) + "bounded_by { cylinder { 0, y, 1 } } }\n");
  EXPECT_FALSE(only_object(s).bounds.has_value());
}

TEST(PovPolyBounds, IntersectionWithASphere_BoundsThePolyAndKeepsTheSphere) {
  const PovScene s =
      read("intersection { " + std::string(kSphereQuadric) + "} sphere { <0, 1, 0>, 3 } }\n");
  const Node& n = only_object(s);
  ASSERT_EQ(n.children.size(), 2u);
  expect_box(n.children[0], {-3, -2, -3}, {3, 4, 3});
  EXPECT_EQ(n.children[1].kind, Node::Sphere);
}

}  // namespace
}  // namespace raycast::pov

// objects/bounding_ball.h against brute force: every point of an object (its boundary crossings on
// random lines, and random points its contains() accepts) lies in its ball, for every kind of
// shape the ball is built from, rotated, scaled and translated, in CSG trees and instances.
#include "objects/bounding_ball.h"

#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>

#include "load/loader.h"

namespace raycast {
namespace {

std::string vec(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  std::ostringstream s;
  s << "[" << u(rng) << ", " << u(rng) << ", " << u(rng) << "]";
  return s.str();
}

// A random rotation, non-uniform scale and translation.
std::string transform(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> deg(-180, 180);
  std::ostringstream s;
  s << "[{scale: " << vec(rng, 0.4, 2) << "}, {rotate: {axis: " << vec(rng, 0.1, 1)
    << ", degrees: " << deg(rng) << "}}, {translate: " << vec(rng, -3, 3) << "}]";
  return s.str();
}

// One primitive of a random kind, placed by a random transform (or none).
std::string primitive(std::mt19937_64& rng, int kind) {
  std::uniform_real_distribution<double> u(0.3, 1.5);
  std::ostringstream s;
  switch (kind % 7) {
    case 0:
      s << "sphere: {center: " << vec(rng, -1, 1) << ", radius: " << u(rng) << "}";
      break;
    case 1:
      s << "box: {min: " << vec(rng, -1.5, -0.2) << ", max: " << vec(rng, 0.2, 1.5) << "}";
      break;
    case 2:
      s << "cylinder: {from: " << vec(rng, -1, 1) << ", to: " << vec(rng, -1, 1)
        << ", radius: " << u(rng) << "}";
      break;
    case 3:
      s << "cone: {from: " << vec(rng, -1, 1) << ", to: " << vec(rng, -1, 1)
        << ", radius_from: " << u(rng) << ", radius_to: " << (kind % 2 ? 0.0 : u(rng)) << "}";
      break;
    case 4:
      s << "torus: {major_radius: " << u(rng) << ", minor_radius: " << 0.2 * u(rng) << "}";
      break;
    case 5:
      s << "ellipsoid: {center: " << vec(rng, -1, 1) << ", radii: " << vec(rng, 0.2, 1.5) << "}";
      break;
    default:
      s << "cylinder: {radius: " << u(rng) << ", z_min: -1, z_max: " << u(rng) << "}";
      break;
  }
  if (kind % 3 != 0) s << ", transform: " << transform(rng);
  return s.str();
}

// Random top-level objects: primitives, two- and three-operand CSG operations (nested once),
// lenses of two overlapping spheres, unions of two spheres, rotated and scaled spheres, and
// instances of a library entry of two objects.
std::string random_scene(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> pick(0, 1000);
  const char* ops[] = {"union", "intersection", "difference"};
  std::ostringstream s;
  s << "library:\n  pair:\n    group:\n      - {" << primitive(rng, pick(rng)) << "}\n      - {"
    << primitive(rng, pick(rng)) << "}\n";
  s << "objects:\n";
  for (int i = 0; i < 6; ++i) s << "  - {" << primitive(rng, i + pick(rng)) << "}\n";
  for (int i = 0; i < 9; ++i) {
    s << "  - " << ops[i % 3] << ":\n";
    for (int j = 0; j < 2 + i % 2; ++j) s << "      - {" << primitive(rng, pick(rng)) << "}\n";
    if (i % 3 == 1) {  // a nested operation as the last operand
      s << "      - " << ops[pick(rng) % 3] << ":\n";
      for (int j = 0; j < 2; ++j) s << "          - {" << primitive(rng, pick(rng)) << "}\n";
    }
    s << "    transform: " << transform(rng) << "\n";
  }
  for (int i = 0; i < 3; ++i) {  // lenses: two spheres of radius 1.5 at a random distance
    std::uniform_real_distribution<double> d(0, 3.2);
    const double half = 0.5 * d(rng);
    s << "  - intersection:\n      - sphere: {center: [0, 0, " << -half
      << "], radius: 1.5}\n      - sphere: {center: [0, 0, " << half
      << "], radius: 1.5}\n    transform: " << transform(rng) << "\n";
  }
  for (int i = 0; i < 3; ++i) {  // exact balls: unions of two spheres, a sphere rotated and scaled
    std::uniform_real_distribution<double> r(0.2, 1.5), scale(0.3, 3), deg(-180, 180);
    s << "  - union:\n      - sphere: {center: " << vec(rng, -2, 2) << ", radius: " << r(rng)
      << "}\n      - sphere: {center: " << vec(rng, -2, 2) << ", radius: " << r(rng) << "}\n";
    s << "  - sphere: {center: " << vec(rng, -1, 1) << ", radius: " << r(rng)
      << "}\n    transform: [{scale: " << scale(rng) << "}, {rotate: {axis: " << vec(rng, 0.1, 1)
      << ", degrees: " << deg(rng) << "}}, {translate: " << vec(rng, -3, 3) << "}]\n";
  }
  for (int i = 0; i < 3; ++i) s << "  - {use: pair, transform: " << transform(rng) << "}\n";
  return s.str();
}

// |p - centre| <= radius, compared exactly enough: the squared distance in long double.
bool in_ball(const Ball& ball, const Vec3& p) {
  const long double x = (long double)p.x - ball.centre.x, y = (long double)p.y - ball.centre.y,
                    z = (long double)p.z - ball.centre.z;
  return x * x + y * y + z * z <= (long double)ball.radius * ball.radius;
}

TEST(BoundingBall, EveryCrossingAndInsidePointOfRandomObjectsIsInTheBall) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  long points = 0;
  for (int scene_index = 0; scene_index < 24; ++scene_index) {
    const Scene scene = load_scene_text(random_scene(rng));
    for (const Object& object : scene.objects) {
      const Ball ball = bounding_ball(object);
      const Aabb box = bounds(object);
      if (box.is_empty()) continue;
      ASSERT_TRUE(ball.is_bounded());
      // Never larger than the ball around the box, widened.
      EXPECT_LE(ball.radius, 0.5 * length(box.extent()) * (1 + 1e-6) + 1e-6);
      const Vec3 lo = box.lo - Vec3{0.5, 0.5, 0.5}, size = box.extent() + Vec3{1, 1, 1};
      auto random_in_box = [&] {
        return lo + Vec3{u(rng) * size.x, u(rng) * size.y, u(rng) * size.z};
      };
      for (int i = 0; i < 300; ++i) {
        // Lines through two random points around the box: every crossing is on the object.
        const Vec3 a = random_in_box(), b = random_in_box();
        const Ray line{a, b - a, -kInfinity, kInfinity};
        SpanList list;
        spans(object, line, list);
        for (const Span& span : list)
          for (const LocalHit* end : {&span.in, &span.out}) {
            if (!std::isfinite(end->t) || end->part == kNoSurface) continue;
            const Vec3 p = line.o + end->t * line.d;
            ASSERT_TRUE(in_ball(ball, p)) << shape_name(object) << " " << i;
            ++points;
          }
        LocalHit hit;
        if (intersect(object, Ray{a, b - a, 0, kInfinity}, hit)) {
          ASSERT_TRUE(in_ball(ball, a + hit.t * (b - a))) << shape_name(object) << " " << i;
          ++points;
        }
        if (is_closed(object) && contains(object, a)) {
          ASSERT_TRUE(in_ball(ball, a)) << shape_name(object) << " " << i;
          ++points;
        }
      }
    }
  }
  EXPECT_GT(points, 100000);  // the checks ran
}

TEST(BoundingBall, LensOfTwoBallsIsTheBallOnTheirCircle) {
  // Two radius-1.5 balls 2.4 apart meet in a circle of radius 0.9 midway (3-4-5 triangles).
  const Ball lens = overlap_balls({{0, 0, -1.2}, 1.5}, {{0, 0, 1.2}, 1.5});
  EXPECT_NEAR(lens.radius, 0.9, 1e-8);
  EXPECT_NEAR(lens.centre.z, 0, 1e-12);
  // Apart: empty; one inside the other: the inner one; unbounded: the other.
  EXPECT_TRUE(overlap_balls({{0, 0, 0}, 1}, {{3, 0, 0}, 1}).is_empty());
  EXPECT_EQ(overlap_balls({{0, 0, 0}, 3}, {{1, 0, 0}, 1}).radius, 1);
  EXPECT_EQ(overlap_balls({{0, 0, 0}, kInfinity}, {{1, 0, 0}, 2}).radius, 2);
  // Circle plane beyond a centre (a cap more than a hemisphere): the smaller ball.
  EXPECT_EQ(overlap_balls({{0, 0, 0}, 1}, {{0.5, 0, 0}, 1.2}).radius, 1);
  // Merged: around both, touching each from outside.
  const Ball both = merge_balls({{0, 0, 0}, 1}, {{4, 0, 0}, 1});
  EXPECT_DOUBLE_EQ(both.radius, 3);
  EXPECT_DOUBLE_EQ(both.centre.x, 2);
  EXPECT_EQ(merge_balls({{0, 0, 0}, 3}, {{1, 0, 0}, 1}).radius, 3);
  EXPECT_FALSE(merge_balls({{0, 0, 0}, 3}, {{1, 0, 0}, kInfinity}).is_bounded());
}

}  // namespace
}  // namespace raycast

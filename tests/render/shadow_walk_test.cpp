// The shadow rays' walk (ObjectSet::any_along, objects/ball_list.h): its ball culling against
// brute force, and
// the integrator's shadow() against every object asked in turn, with no culling at all.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "load/loader.h"
#include "objects/ball_list.h"
#include "render/integrator.h"

namespace raycast {
namespace {

// Spheres plain, scaled and rotated, a rotated box, a cylinder, a triangle, a disk and a plane,
// some opaque and some transmissive (each filters by transmission * colour); `alt` is the
// material of the plane, the box and the disk.
std::string scene_text(bool transmissive) {
  const char* alt = transmissive ? "a" : "o";
  std::ostringstream text;
  text << "materials:\n  a: {color: [0.8, 0.6, 0.4], transmission: " << (transmissive ? 0.5 : 0)
       << "}\n  b: {color: [1, 0.5, 0.25], transmission: " << (transmissive ? 0.9 : 0)
       << "}\n  o: {color: [1, 1, 1]}\n"
       << "objects:\n"
       << "  - {plane: {normal: [0, 1, 0], point: [0, -2, 0]}, material: " << alt << "}\n"
       << "  - {sphere: {center: [0, 0, 0], radius: 1}, material: a}\n"
       << "  - sphere: {center: [0.5, 0.2, -0.3], radius: 0.7}\n"
       << "    transform: [{scale: [2, 0.5, 1]}, {rotate: {axis: [1, 1, 0], degrees: 40}}, "
          "{translate: [2.5, 0.5, 1]}]\n"
       << "    material: b\n"
       << "  - box: {min: [-0.5, -0.5, -0.5], max: [0.5, 0.8, 0.5]}\n"
       << "    transform: [{rotate: {axis: [0, 1, 0], degrees: 30}}, {translate: [-2.2, 0, 1.5]}]\n"
       << "    material: " << alt << "\n"
       << "  - {cylinder: {from: [-1, 1.5, -2], to: [1, 2.5, -2.5], radius: 0.4}, material: a}\n"
       << "  - {triangle: {vertices: [[-3, -1, -3], [-1, 2, -3], [-2, 0, -1]]}, material: b}\n"
       << "  - {disk: {center: [2, -1, -2], normal: [0.3, 1, 0.2], radius: 0.9}, material: " << alt
       << "}\n"
       << "  - {sphere: {center: [0, 3, 2], radius: 0.05}, material: b}\n";
  return text.str();
}

// Every object asked in ObjectSet's flat order (unbounded ones, then bounded ones by index),
// none culled: an opaque crossing blocks, a transmissive one multiplies by its filter.
Color every_object(const Scene& scene, const Ray& segment) {
  Color through{1, 1, 1};
  if (!is_valid(segment)) return through;
  for (bool unbounded : {true, false}) {
    for (const Object& object : scene.objects) {
      const Aabb box = bounds(object);
      if (box.is_empty() || box.is_bounded() == unbounded) continue;
      if (!occluded(object, segment)) continue;
      const Material& m = scene.materials[std::size_t(object.material)];
      if (!(m.transmission > 0)) return {0, 0, 0};
      through = mul(through, m.transmission * m.color);
      if (!(max_component(through) > 0)) return {0, 0, 0};
    }
  }
  return through;
}

Vec3 random_point(std::mt19937_64& rng, double half) {
  std::uniform_real_distribution<double> u(-half, half);
  return {u(rng), u(rng), u(rng)};
}

// CSG objects and instances whose balls (objects/bounding_ball.h) are much tighter than their
// boxes': a rotated cube minus a sphere, a lens, a rotated notched torus, a union of spheres, a
// Steinmetz solid, and instances of a sphere minus a bar; `alt` as in scene_text.
std::string csg_scene_text(bool transmissive) {
  const char* alt = transmissive ? "a" : "o";
  std::ostringstream text;
  text << "materials:\n  a: {color: [0.8, 0.6, 0.4], transmission: " << (transmissive ? 0.5 : 0)
       << "}\n  o: {color: [1, 1, 1]}\n"
       << "library:\n  nut:\n    difference:\n      - sphere: {radius: 0.45}\n"
       << "      - box: {min: [-0.2, -1, -0.2], max: [0.2, 1, 0.2]}\n"
       << "objects:\n"
       << "  - {plane: {normal: [0, 1, 0], point: [0, -2, 0]}, material: o}\n"
       << "  - difference:\n      - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n"
       << "      - sphere: {radius: 1.3}\n"
       << "    transform: [{rotate: {axis: [1, 2, 0], degrees: 30}}, {translate: [-2, 0, 1]}]\n"
       << "    material: " << alt << "\n"
       << "  - intersection:\n      - sphere: {center: [0, 0, -1.2], radius: 1.5}\n"
       << "      - sphere: {center: [0, 0, 1.2], radius: 1.5}\n"
       << "    transform: [{rotate: {axis: [0, 1, 1], degrees: 50}}, {translate: [1.5, 0.5, 0]}]\n"
       << "    material: a\n"
       << "  - difference:\n      - torus: {major_radius: 0.9, minor_radius: 0.3}\n"
       << "        transform: [{rotate: {axis: [1, 0, 0], degrees: 90}}]\n"
       << "      - box: {min: [-0.5, -0.5, -1.5], max: [0.5, 0.5, -0.5]}\n"
       << "    transform: [{translate: [0, 2, -2]}]\n    material: " << alt << "\n"
       << "  - union:\n      - sphere: {center: [0, 0, 0], radius: 0.5}\n"
       << "      - sphere: {center: [0, 0.6, 0], radius: 0.35}\n"
       << "    transform: [{translate: [2.5, -1, -2]}]\n    material: a\n"
       << "  - intersection:\n      - cylinder: {from: [-1, 0, 0], to: [1, 0, 0], radius: 1}\n"
       << "      - cylinder: {from: [0, -1, 0], to: [0, 1, 0], radius: 1}\n"
       << "      - cylinder: {from: [0, 0, -1], to: [0, 0, 1], radius: 1}\n"
       << "    transform: [{scale: [1, 0.7, 1.2]}, {translate: [-1, 2, 2]}]\n    material: o\n";
  for (int i = 0; i < 4; ++i)
    text << "  - {use: nut, transform: [{scale: " << 1 + 0.3 * i << "}, {translate: ["
         << -3 + 1.5 * i << ", -1, -3]}], material: " << (i % 2 ? alt : "o") << "}\n";
  return text.str();
}

void expect_walk_matches_every_object(bool transmissive, bool csg = false) {
  const Scene scene =
      load_scene_text(csg ? csg_scene_text(transmissive) : scene_text(transmissive));
  ObjectSet set;
  set.build(scene.objects);
  ASSERT_TRUE(set.walks_balls());
  const Integrator integrator(scene, RenderMode::kWhitted);
  SampleState state{Rng(1), 0};
  std::mt19937_64 rng(7);
  int blocked = 0, filtered = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3 from = random_point(rng, 4);
    // Segments to random points and half-lines in random directions, and segments through
    // points of the unit sphere's surface (grazing and crossing it).
    Vec3 to = random_point(rng, 6);
    const bool to_infinity = i % 3 == 1;
    if (i % 3 == 2) to = from + 2.0 * (normalize(random_point(rng, 1)) - from);
    if (csg && i % 2 == 0) {
      // From a point on an object's surface (where shading starts shadow rays), offset along
      // the ray that found it, or a little inside it.
      SceneHit hit;
      const Vec3 eye = random_point(rng, 6), dir = random_point(rng, 3) - eye;
      if (scene.intersect(Ray{eye, dir, 0, kInfinity}, hit))
        from = eye + hit.local.t * (1 + (i % 4 == 0 ? -1e-9 : 1e-9)) * dir;
    }
    const Color got = integrator.shadow(from, to, to_infinity, state);
    const Ray segment{from, to_infinity ? to : to - from, 0, to_infinity ? kInfinity : 1};
    const Color want = every_object(scene, segment);
    ASSERT_EQ(got.x, want.x) << i;
    ASSERT_EQ(got.y, want.y) << i;
    ASSERT_EQ(got.z, want.z) << i;
    if (!transmissive) {
      ASSERT_EQ(got.x == 0, scene.occluded(segment)) << i;
    }
    blocked += got.x == 0;
    filtered += got.x > 0 && got.x < 1;
  }
  // Both answers occur often (the comparison is not trivially met).
  if (!transmissive) {
    EXPECT_GT(blocked, 1000);
  }
  if (transmissive) {
    EXPECT_GT(filtered, 1000);
  }
}

TEST(ShadowWalk, OpaqueScene_SameAnswersAsEveryObjectAskedInTurn) {
  expect_walk_matches_every_object(false);
}

TEST(ShadowWalk, TransmissiveScene_SameProductAsEveryObjectAskedInTurn) {
  expect_walk_matches_every_object(true);
}

TEST(ShadowWalk, CsgOpaqueScene_SameAnswersAsEveryObjectAskedInTurn) {
  expect_walk_matches_every_object(false, true);
}

TEST(ShadowWalk, CsgTransmissiveScene_SameProductAsEveryObjectAskedInTurn) {
  expect_walk_matches_every_object(true, true);
}

TEST(ShadowBalls, EveryBallWithinItsRadiusOfTheHalfLineIsVisited_FartherOnesAreNot) {
  // Balls placed at a chosen distance from random half-lines: at most the radius (down to a
  // grazing 1 - 1e-15 of it) must be visited, beyond 1.01 radii must not unless within the
  // test's widening (kBallSlack |v|^2; the culling culls). The ball sits in lane 0 or 1 of its
  // pair, the other lane empty.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 o = random_point(rng, 100);
    const Vec3 e = normalize(random_point(rng, 1));
    Vec3 s, t;
    make_frame(e, s, t);
    const double radius = std::pow(10.0, 4 * u(rng) - 3);
    const double along = (u(rng) < 0.2 ? -radius : 0) + std::pow(10.0, 4 * u(rng) - 1);
    const double factor = i % 2 == 0 ? 1 - 1e-15 * u(rng) : 1.01 + u(rng);
    // A point at `along` on the line, moved off it perpendicularly; behind the origin the
    // distance is the one from the origin itself.
    const double side = along >= 0 ? radius * factor : radius * factor * 0.6;
    Vec3 c = o + along * e + side * s;
    if (along < 0)
      c = o + (-std::sqrt(radius * factor * radius * factor - side * side)) * e + side * s;
    // The exact distance of the (rounded) centre from the half-line, in long double.
    const long double vx = (long double)c.x - o.x, vy = (long double)c.y - o.y,
                      vz = (long double)c.z - o.z;
    const long double k = vx * e.x + vy * e.y + vz * e.z;
    const long double vv = vx * vx + vy * vy + vz * vz;
    const long double dist2 = k > 0 ? vv - k * k : vv;
    const long double r2 = (long double)radius * radius;
    std::vector<BallPair> balls;
    std::size_t count = 0;
    if (i % 4 >= 2) add_ball(balls, count, 9, {1e3, 1e3, 1e3}, 1);  // far from every half-line
    add_ball(balls, count, 5, c, radius);
    bool visited = false;
    each_ball_near(balls.data(), balls.data() + balls.size(), o, e, [&](std::uint32_t index) {
      EXPECT_EQ(index, 5u);
      visited = true;
      return false;
    });
    if (dist2 <= r2) {
      EXPECT_TRUE(visited) << i;
    } else if (dist2 > 1.0001L * (r2 + kBallSlack * vv)) {  // beyond the test's widening
      EXPECT_FALSE(visited) << i;
    }
  }
}

}  // namespace
}  // namespace raycast

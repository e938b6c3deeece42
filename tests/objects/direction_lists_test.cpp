// The direction lists' walks (objects/direction_lists.h, ObjectSet::set_view) against the walks
// without them: random scenes of spheres, boxes and CSG objects, rays from the apex in random
// directions, along the cells' edges and corners, along the axes and the cube's diagonals, with
// the apex inside an object's ball and on a box face; the nearest hit (same object, same t, bit
// for bit); lists around a light hold every object a shadow segment to it crosses, and
// ObjectSet::any_along_to finds the same crossings as any_along, in its order. Then renders of
// scenes/csg.yaml and bench/scenes/glass.yaml with and without the lists, byte for byte.
#include "objects/direction_lists.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "load/loader.h"
#include "objects/bounding_ball.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "support/random.h"

namespace raycast {
namespace {

std::string text(const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << v.x << " " << v.y << " " << v.z;
  return s.str();
}

// A scene of a plane and `count` objects around the origin: spheres, boxes, transformed CSG
// differences and intersections, and (twice) one sphere written twice, for hits at equal t.
std::string random_scene_text(testing::Rng& rng, int count, const Vec3& box_face_at) {
  std::ostringstream out;
  out.precision(17);
  auto point = [&](const Vec3& p) {
    std::ostringstream s;
    s.precision(17);
    s << "[" << p.x << ", " << p.y << ", " << p.z << "]";
    return s.str();
  };
  out << "objects:\n  - plane: {normal: [0, 1, 0], point: [0, -3, 0]}\n";
  // A box with a face through box_face_at (its min x there).
  out << "  - box: {min: " << point(box_face_at - Vec3{0, 0.5, 0.5})
      << ", max: " << point(box_face_at + Vec3{1, 0.5, 0.5}) << "}\n";
  for (int i = 1; i < count; ++i) {
    const Vec3 c = rng.in_box(3);
    const double r = rng.uniform(0.1, 0.9);
    switch (i % 5) {
      case 0:
        out << "  - sphere: {center: " << point(c) << ", radius: " << r << "}\n";
        break;
      case 1:
        out << "  - box: {min: " << point(c - Vec3{r, 0.5 * r, r})
            << ", max: " << point(c + Vec3{0.7 * r, r, 0.4 * r}) << "}\n";
        break;
      case 2:
        out << "  - difference:\n      - box: {min: [-1, -1, -1], max: [1, 1, 1]}\n"
               "      - sphere: {radius: 1.3}\n"
            << "    transform: [{scale: " << r
            << "}, {rotate: {axis: [0, 1, 0], degrees: " << rng.uniform(0, 90)
            << "}}, {translate: " << point(c) << "}]\n";
        break;
      case 3:
        out << "  - intersection:\n      - sphere: {radius: 1}\n"
               "      - sphere: {center: [0.8, 0, 0], radius: 1}\n"
            << "    transform: [{scale: " << r << "}, {translate: " << point(c) << "}]\n";
        break;
      default:  // the same sphere twice: equal t on every ray that meets it
        out << "  - sphere: {center: " << point(c) << ", radius: " << r << "}\n";
        out << "  - sphere: {center: " << point(c) << ", radius: " << r << "}\n";
        ++i;
        break;
    }
  }
  return out.str();
}

// The direction of face point (u, v) (DirectionLists::cell_of's faces), scaled.
Vec3 face_point(int face, double u, double v, double scale) {
  return DirectionLists::face_direction(std::size_t(face), u, v) * scale;
}

// Directions from an apex: random, on the cells' edges and corners (and one ulp either side),
// along the axes and the diagonals.
std::vector<Vec3> test_directions(testing::Rng& rng, int n) {
  std::vector<Vec3> out;
  const int side = ObjectSet::kListSide;
  for (int k = 0; k < n; ++k) {
    const double scale = rng.uniform(0.1, 10);
    switch (k % 4) {
      case 0:
        out.push_back(rng.direction() * scale);
        break;
      case 1:
      case 2: {  // an edge (k % 4 == 1) or a corner of a cell
        const int face = int(rng.uniform(0, 6));
        double u = -1 + 2.0 * int(rng.uniform(0, side + 1)) / side;
        double v =
            k % 4 == 2 ? -1 + 2.0 * int(rng.uniform(0, side + 1)) / side : rng.uniform(-1, 1);
        const int nudge = int(rng.uniform(0, 3));  // none, an ulp down, an ulp up
        if (nudge == 1) u = std::nextafter(u, -2.0);
        if (nudge == 2) u = std::nextafter(u, 2.0);
        out.push_back(face_point(face, u, v, scale));
        break;
      }
      default: {
        static const Vec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0},
                                    {0, 1, 1}, {1, 0, 1}, {1, 1, 1}, {1, -1, 1}};
        Vec3 d = axes[k / 4 % 8] * scale;
        if (k / 32 % 2) d = -d;
        out.push_back(d);
        break;
      }
    }
  }
  return out;
}

struct Apexes {
  Vec3 view;
  Vec3 light;
};

// Adds to `crossed` the shadow segments that cross a bounded object.
void check_scene(std::uint64_t seed, int count, int apex_kind, int& crossed) {
  testing::Rng rng(seed);
  Vec3 box_face = rng.in_box(2);
  const Scene scene = load_scene_text(random_scene_text(rng, count, box_face));
  const std::vector<Object>& objects = scene.objects;
  // The apexes: random (0), inside the first CSG object's ball (1: the centre of the scene's
  // objects' box is inside some of them), or on the box's face (2).
  Apexes apexes{rng.in_box(5), rng.in_box(6) + Vec3{0, 4, 0}};
  if (apex_kind == 1)
    apexes = {objects[3].xf ? objects[3].xf->point({0, 0, 0}) : Vec3{},
              objects[2].xf ? objects[2].xf->point({0, 0, 0}) : Vec3{}};
  if (apex_kind == 2) apexes = {box_face, box_face + Vec3{0, 0.25, 0}};
  ObjectSet plain, lists;
  plain.build(objects);
  lists.build(objects);
  lists.set_view(objects, apexes.view);
  ASSERT_TRUE(lists.has_view_lists());
  const std::optional<Vec3> light = apexes.light;
  lists.set_lights(objects, std::span<const std::optional<Vec3>>(&light, 1));
  ASSERT_NE(lists.light_lists(0), nullptr);
  ASSERT_TRUE(lists.has_light_lists());
  // Lists around the light, in index order (DirectionLists's guarantee for segments that end at
  // its apex, not used by the renderer).
  std::vector<DirectionLists::Ball> balls;
  for (std::uint32_t i = 0; i < objects.size(); ++i) {
    const Ball ball = bounding_ball(objects[i]);
    if (raycast::bounds(objects[i]).is_bounded() && !ball.is_empty())
      balls.push_back({i, ball.centre, ball.radius});
  }
  DirectionLists light_lists;
  light_lists.build(apexes.light, balls, 100, ObjectSet::kListSide, DirectionLists::Order::kIndex);

  int hits = 0;
  for (const Vec3& d : test_directions(rng, 3000)) {
    // Nearest: the same object and the same t, bit for bit.
    const Ray ray{apexes.view, d, 0, kInfinity};
    LocalHit a, b;
    std::int32_t ia = -1, ib = -1;
    const bool fa = plain.intersect(objects, ray, a, ia);
    const bool fb = lists.intersect(objects, ray, b, ib);
    ASSERT_EQ(fa, fb) << text(d);
    if (fa) {
      ++hits;
      ASSERT_EQ(ia, ib) << text(d);
      ASSERT_EQ(std::memcmp(&a.t, &b.t, sizeof(double)), 0) << text(d);
    }
    // Shadow segments to the light: from the light's side (along d from it) and from the hit
    // points of rays from the view.
    // (Also from far away, as from a plane's far points: up to about 100 times the lists' reach
    // and beyond, where any_along_to takes any_along.)
    std::vector<Vec3> froms{apexes.light + d, apexes.light + d * 300.0};
    if (fa) froms.push_back(ray.o + a.t * ray.d);
    for (const Vec3& from : froms) {
      const Ray segment{from, apexes.light - from, 0, 1};
      if (!is_valid(segment)) continue;
      const Vec3 e = normalize(segment.d);
      // Every bounded object the segment crosses is in its cell, in index order.
      std::vector<std::uint32_t> by_objects, by_lists;
      for (const DirectionLists::Ball& ball : balls)
        if (raycast::occluded(objects[ball.index], segment)) by_objects.push_back(ball.index);
      for (const DirectionLists::Entry& entry : light_lists.cell(-segment.d))
        if (entry.may_meet(segment.o, e, 1.0) && raycast::occluded(objects[entry.index], segment))
          by_lists.push_back(entry.index);
      ASSERT_EQ(by_objects, by_lists) << text(from);
      crossed += !by_objects.empty();
      // ObjectSet's walk of its own light lists (any_along_to) against any_along: the same
      // objects crossed, in the same order, and the same first crossing (the renderer's stop).
      std::vector<std::uint32_t> along, along_to;
      auto collect = [&](std::vector<std::uint32_t>& out) {
        return [&objects, &segment, &out](std::uint32_t index) {
          if (raycast::occluded(objects[index], segment)) out.push_back(index);
          return false;
        };
      };
      plain.any_along(segment, e, collect(along));
      lists.any_along_to(*lists.light_lists(0), segment, collect(along_to));
      ASSERT_EQ(along, along_to) << text(from);
      std::erase_if(along, [&](std::uint32_t i) { return !bounds(objects[i]).is_bounded(); });
      ASSERT_EQ(along, by_objects) << text(from);
    }
  }
  EXPECT_GT(hits, 100);
}

TEST(DirectionLists, RandomScenes_SameAnswersAsTheWalksWithout) {
  int crossed = 0;
  for (int count : {5, 6, 12, 16})
    for (int kind = 0; kind < 3; ++kind) {
      SCOPED_TRACE(::testing::Message() << count << " objects, apex kind " << kind);
      check_scene(100 + std::uint64_t(count) * 3 + std::uint64_t(kind), count, kind, crossed);
    }
  std::printf("segments crossing a bounded object: %d\n", crossed);
  EXPECT_GT(crossed, 500);
}

// cell_of's cell, for a direction on a cell corner and an ulp either side, is one whose entries
// the walks take: every entry of every cell around the corner that the ray's ball test passes
// is in it (the cells are widened).
TEST(DirectionLists, CornerDirections_CellHoldsEveryBallTheRayMeets) {
  testing::Rng rng(7);
  std::vector<DirectionLists::Ball> balls;
  for (std::uint32_t i = 0; i < 200; ++i)
    balls.push_back({i, rng.in_box(10), rng.uniform(0.01, 0.5)});
  DirectionLists lists;
  const Vec3 apex{0.1, -0.2, 0.3};
  const int side = 16;
  lists.build(apex, balls, 40, side, DirectionLists::Order::kIndex);
  int met = 0;
  for (int face = 0; face < 6; ++face)
    for (int j = 0; j <= side; ++j)
      for (int i = 0; i <= side; ++i)
        for (int nudge = 0; nudge < 9; ++nudge) {
          double u = -1 + 2.0 * i / side, v = -1 + 2.0 * j / side;
          if (nudge % 3 == 1) u = std::nextafter(u, -2.0);
          if (nudge % 3 == 2) u = std::nextafter(u, 2.0);
          if (nudge / 3 == 1) v = std::nextafter(v, -2.0);
          if (nudge / 3 == 2) v = std::nextafter(v, 2.0);
          const Vec3 d = face_point(face, u, v, 1);
          const auto cell = lists.cell(d);
          for (const DirectionLists::Ball& b : balls) {
            // The exact ray from the apex meets the ball (by a margin beyond rounding)?
            const Vec3 c = b.centre - apex;
            const double k = dot(c, d) / length_squared(d);
            if (!(k > 0) || length_squared(c - k * d) > b.radius * b.radius * (1 - 1e-9)) continue;
            ++met;
            bool in = false;
            for (const DirectionLists::Entry& e : cell) in |= e.index == b.index;
            ASSERT_TRUE(in) << "ball " << b.index << " direction " << text(d);
          }
        }
  EXPECT_GT(met, 1000);
}

// A scene rendered with the direction lists (around the camera and the lights) and without:
// the same bytes.
void expect_same_render_without_lists(const std::string& path) {
  Scene with = load_scene_file(std::string(RAYCAST_SOURCE_DIR) + "/" + path);
  Scene without = with;
  without.build(false);
  ASSERT_TRUE(with.object_set().has_view_lists());
  ASSERT_TRUE(with.object_set().has_light_lists());
  ASSERT_FALSE(without.object_set().has_view_lists());
  ASSERT_FALSE(without.object_set().has_light_lists());
  RenderOptions options;
  options.width = 160;
  options.height = 120;
  options.spp = 1;
  const Image a = render(with, options);
  const Image b = render(without, options);
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  EXPECT_EQ(std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)), 0);
}

// Opaque shadow rays (Integrator::blocked_to).
TEST(DirectionLists, CsgRender_SameImageAsWithoutLists) {
  expect_same_render_without_lists("scenes/csg.yaml");
}

// Shadow rays through transmissive objects (Integrator::filters_to).
TEST(DirectionLists, GlassRender_SameImageAsWithoutLists) {
  expect_same_render_without_lists("bench/scenes/glass.yaml");
}

}  // namespace
}  // namespace raycast

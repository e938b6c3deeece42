// The public C++ API (include/raycast/raycast.h) seen as a user sees it.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "raycast/raycast.h"

namespace {

raycast::Scene unit_sphere_and_box() {
  raycast::Scene s;
  s.add_sphere({0, 0, 0}, 1);
  s.add_box({2, -1, -1}, {3, 1, 1});
  s.commit();
  return s;
}

TEST(PublicScene, IntersectSphere_GivesExactSurfaceRecord) {
  const raycast::Scene s = unit_sphere_and_box();
  const raycast::SurfaceInfo h = s.intersect(raycast::Ray{{0, 0, -5}, {0, 0, 1}});
  ASSERT_TRUE(h.hit());
  EXPECT_EQ(h.t, 4);
  EXPECT_EQ(h.object, 0);
  EXPECT_EQ(h.primitive, -1);
  EXPECT_EQ(h.point[2], -1);
  EXPECT_EQ(h.normal[2], -1);
}

TEST(PublicScene, Miss_GivesNoObjectAndInfiniteT) {
  const raycast::Scene s = unit_sphere_and_box();
  const raycast::SurfaceInfo h = s.intersect(raycast::Ray{{0, 5, -5}, {0, 0, 1}});
  EXPECT_FALSE(h.hit());
  EXPECT_TRUE(std::isinf(h.t));
  EXPECT_TRUE(std::isnan(h.point[0]));
}

TEST(PublicScene, TMaxEqualToHitDistance_IsOccluded) {
  const raycast::Scene s = unit_sphere_and_box();
  EXPECT_TRUE(s.occluded(raycast::Ray{{0, 0, -5}, {0, 0, 1}, 0, 4}));
  EXPECT_FALSE(s.occluded(raycast::Ray{{0, 0, -5}, {0, 0, 1}, 0, std::nextafter(4.0, 0.0)}));
}

TEST(PublicScene, IntersectAll_GivesEveryCrossingSorted) {
  const raycast::Scene s = unit_sphere_and_box();
  const auto c = s.intersect_all(raycast::Ray{{-5, 0, 0}, {1, 0, 0}});
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c[0].t, 4);
  EXPECT_EQ(c[1].t, 6);
  EXPECT_EQ(c[2].t, 7);
  EXPECT_EQ(c[3].t, 8);
  EXPECT_EQ(c[2].object, 1);
  EXPECT_EQ(c[2].normal[0], -1);
}

TEST(PublicScene, BatchLayouts_AgreeWithSingleRays) {
  const raycast::Scene s = unit_sphere_and_box();
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::size_t n = 1000;
  std::vector<raycast::Ray> rays(n);
  std::vector<double> inter(6 * n), soa(6 * n);
  for (std::size_t i = 0; i < n; ++i) {
    rays[i] = {{u(gen), u(gen), -5}, {u(gen), u(gen), 1}};
    for (int k = 0; k < 3; ++k) {
      inter[6 * i + k] = soa[k * n + i] = rays[i].origin[k];
      inter[6 * i + 3 + k] = soa[(3 + k) * n + i] = rays[i].direction[k];
    }
  }
  std::vector<raycast::SurfaceInfo> aos(n);
  s.intersect(rays, aos);
  std::vector<double> t1(n), t2(n), normals(3 * n);
  std::vector<raycast::ObjectId> ids(n);
  s.intersect(raycast::RayArray::interleaved(inter.data(), n),
              raycast::HitColumns{t1.data(), ids.data(), nullptr, nullptr, normals.data()});
  s.intersect(raycast::RayArray::soa(soa.data(), n), raycast::HitColumns{t2.data()});
  std::vector<std::uint8_t> occ(n);
  s.occluded(raycast::RayArray::interleaved(inter.data(), n), occ);
  for (std::size_t i = 0; i < n; ++i) {
    const raycast::SurfaceInfo one = s.intersect(rays[i]);
    ASSERT_EQ(aos[i].t, one.t) << i;
    ASSERT_EQ(t1[i], one.t) << i;
    ASSERT_EQ(t2[i], one.t) << i;
    ASSERT_EQ(ids[i], one.object) << i;
    ASSERT_EQ(occ[i], one.hit() ? 1 : 0) << i;
    if (one.hit()) {
      ASSERT_EQ(normals[3 * i], one.normal[0]) << i;
    }
  }
}

TEST(PublicScene, LoadErrors_CarryFileLineColumn) {
  try {
    raycast::Scene::from_string("objects:\n  - sphere: {radius: 0}\n", "s.yaml");
    FAIL() << "no error";
  } catch (const raycast::SceneError& e) {
    EXPECT_EQ(e.file(), "s.yaml");
    EXPECT_EQ(e.line(), 2);
    EXPECT_GT(e.column(), 0);
  }
  EXPECT_THROW(raycast::Scene::load("/nonexistent.yaml"), raycast::SceneError);
}

TEST(PublicScene, BadParametersAndMisuse_Throw) {
  raycast::Scene s;
  EXPECT_THROW(s.add_sphere({0, 0, 0}, -1), raycast::SceneError);
  EXPECT_THROW(s.add_box({0, 0, 0}, {0, 1, 1}), raycast::SceneError);
  EXPECT_THROW(s.add_shape("nope", "{}"), raycast::SceneError);
  EXPECT_THROW(s.intersect(raycast::Ray{}), std::logic_error);
  const raycast::ObjectId d = s.add_disk({0, 0, 0}, {0, 0, 1}, 1);
  const raycast::ObjectId b = s.add_box({0, 0, 0}, {1, 1, 1});
  const raycast::ObjectId ops[] = {d, b};
  EXPECT_THROW(s.add_csg(raycast::CsgOp::kUnion, ops), raycast::SceneError);
  raycast::Transform singular;
  singular.m[0] = 0;
  EXPECT_THROW(s.set_transform(b, singular), raycast::SceneError);
  s.commit();
  EXPECT_THROW(s.add_sphere({0, 0, 0}, 1), std::logic_error);
}

TEST(PublicScene, CsgAndInstances_BuiltInCode) {
  raycast::Scene s;
  const raycast::ObjectId box = s.add_box({-1, -1, -1}, {1, 1, 1});
  const raycast::ObjectId ball = s.add_sphere({0, 0, 0}, 1.2);
  const raycast::ObjectId ops[] = {box, ball};
  const raycast::ObjectId csg = s.add_csg(raycast::CsgOp::kDifference, ops);
  const raycast::ObjectId part = s.add_sphere({0, 0, 0}, 0.5);
  const int proto = s.add_prototype(std::span<const raycast::ObjectId>(&part, 1));
  const raycast::ObjectId inst = s.add_instance(proto, raycast::Transform::translate({10, 0, 0}));
  s.commit();
  // Through the box's centre the ball removes everything; near a corner the box remains.
  EXPECT_FALSE(s.intersect(raycast::Ray{{0, 0, -5}, {0, 0, 1}}).hit());
  const raycast::SurfaceInfo corner = s.intersect(raycast::Ray{{0.95, 0.95, -5}, {0, 0, 1}});
  EXPECT_EQ(corner.object, csg);
  EXPECT_EQ(corner.t, 4);
  const raycast::SurfaceInfo i = s.intersect(raycast::Ray{{10, 0, -5}, {0, 0, 1}});
  EXPECT_EQ(i.object, inst);
  EXPECT_EQ(i.t, 4.5);
  EXPECT_EQ(s.shape_name(csg), "csg");
}

TEST(PublicScene, ManyThreads_GiveTheSameAnswers) {
  raycast::Scene s;
  std::vector<double> v;
  std::vector<std::uint32_t> t;
  const int n = 64;  // a height field of 2 n^2 triangles
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x)
      v.insert(v.end(), {double(x) / n, double(y) / n, 0.1 * std::sin(x * 0.3 + y * 0.2)});
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const std::uint32_t a = y * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      t.insert(t.end(), {a, b, d, a, d, c});
    }
  s.add_mesh(v, t);
  s.commit();
  std::vector<raycast::Ray> rays;
  for (int i = 0; i < 4000; ++i)
    rays.push_back({{(i % 97) / 97.0, (i % 89) / 89.0, 5}, {0.01 * (i % 7), 0, -1}});
  std::vector<raycast::SurfaceInfo> expect(rays.size());
  s.intersect(rays, expect);
  std::vector<std::thread> threads;
  std::vector<int> mismatches(6, 0);
  for (int k = 0; k < 6; ++k)
    threads.emplace_back([&, k] {
      for (std::size_t i = 0; i < rays.size(); ++i) {
        const raycast::SurfaceInfo h = s.intersect(rays[i]);
        if (h.t != expect[i].t || h.primitive != expect[i].primitive) ++mismatches[k];
      }
    });
  for (std::thread& th : threads) th.join();
  for (int k = 0; k < 6; ++k) EXPECT_EQ(mismatches[k], 0) << "thread " << k;
}

TEST(PublicScene, Distances_OfSphereAndMesh) {
  raycast::Scene s;
  s.add_sphere({0, 0, 0}, 1);
  const double v[] = {5, 0, 0, 6, 0, 0, 5, 1, 0};
  const std::uint32_t t[] = {0, 1, 2};
  s.add_mesh(std::span<const double>(v), std::span<const std::uint32_t>(t));
  s.commit();
  const double p[] = {0, 0, 3, 5.2, 0.2, 1, 0, 0, 0.5};
  double q[9], d[3];
  raycast::ObjectId obj[3];
  std::int32_t prim[3];
  s.closest_points(p, q, obj, prim, d);
  EXPECT_EQ(d[0], 2);
  EXPECT_EQ(obj[0], 0);
  EXPECT_EQ(d[1], 1);
  EXPECT_EQ(obj[1], 1);
  EXPECT_EQ(prim[1], 0);
  EXPECT_EQ(q[5], 0);
  double sd[3];
  s.signed_distance(p, sd);
  EXPECT_EQ(sd[2], -0.5);
  std::uint8_t occ[3];
  s.occupancy(p, occ);
  EXPECT_EQ(occ[0], 0);
  EXPECT_EQ(occ[2], 1);
}

TEST(PublicScene, Render_FillsTheImage) {
  raycast::Scene s;
  const raycast::ObjectId ball = s.add_sphere({0, 0, 0}, 1);
  raycast::Material red;
  red.color = {1, 0, 0};
  s.set_material(ball, s.add_material(red));
  raycast::Light light;
  light.position = {0, 2, -5};
  s.add_light(light);
  s.commit();
  raycast::Camera cam;
  cam.position = {0, 0, -5};
  raycast::RenderOptions o;
  o.width = 20;
  o.height = 10;
  const raycast::Image img = s.render(&cam, o);
  ASSERT_EQ(img.width, 20);
  ASSERT_EQ(img.rgb.size(), 600u);
  EXPECT_GT(img.rgb[3 * (5 * 20 + 10)], 0.f);
  EXPECT_EQ(img.rgb[3 * (5 * 20 + 10) + 1], 0.f);
}

TEST(PublicScene, RenderRegion_EqualsThatPartOfTheWholeImage) {
  raycast::Scene s;
  s.add_sphere({0, 0, 0}, 1);
  raycast::Light light;
  light.position = {0, 2, -5};
  s.add_light(light);
  s.commit();
  raycast::Camera cam;
  cam.position = {0, 0, -5};
  raycast::RenderOptions o;
  o.width = 20;
  o.height = 10;
  o.samples = 2;
  const raycast::Image whole = s.render(&cam, o);
  o.region = std::array<int, 4>{3, 2, 17, 9};
  const raycast::Image part = s.render(&cam, o);
  ASSERT_EQ(part.width, 14);
  ASSERT_EQ(part.height, 7);
  for (int y = 0; y < 7; ++y)
    for (int x = 0; x < 14; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(part.rgb[3 * (y * 14 + x) + c], whole.rgb[3 * ((y + 2) * 20 + x + 3) + c])
            << x << ", " << y;
  EXPECT_EQ(s.image_size()[0], 640);  // the scene's default, used for width 0
  for (const auto& bad : {std::array<int, 4>{0, 0, 21, 10}, std::array<int, 4>{5, 0, 5, 10},
                          std::array<int, 4>{-1, 0, 4, 4}}) {
    o.region = bad;
    EXPECT_THROW(s.render(&cam, o), std::invalid_argument);
  }
}

}  // namespace

namespace {

// signed_distance reuses a neighbour's sign inside a surface-free ball (api/scene_points.cpp):
// its signs must equal occupancy's point by point, also for dense points straddling surfaces.
TEST(PublicScene, SignedDistanceSigns_EqualOccupancyOnDenseBatches) {
  raycast::Scene s;
  std::vector<double> v;
  std::vector<std::uint32_t> t;
  const int rows = 24, cols = 32;  // a closed UV sphere of radius 1 about the origin
  v.insert(v.end(), {0, 0, 1});
  for (int i = 1; i < rows; ++i)
    for (int j = 0; j < cols; ++j) {
      const double th = M_PI * i / rows, ph = 2 * M_PI * j / cols;
      v.insert(v.end(), {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
    }
  v.insert(v.end(), {0, 0, -1});
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(1 + (i - 1) * cols + j % cols); };
  const auto last = static_cast<std::uint32_t>(v.size() / 3 - 1);
  for (int j = 0; j < cols; ++j) {
    t.insert(t.end(), {0, at(1, j), at(1, j + 1)});
    t.insert(t.end(), {at(rows - 1, j), last, at(rows - 1, j + 1)});
    for (int i = 1; i + 1 < rows; ++i) {
      t.insert(t.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      t.insert(t.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  s.add_mesh(std::span<const double>(v), t);
  s.add_box({1.5, -0.5, -0.5}, {2.5, 0.5, 0.5});
  s.commit();
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-2.6, 2.6), tiny(-1e-3, 1e-3);
  std::vector<double> points;
  for (int i = 0; i < 3000; ++i) points.insert(points.end(), {u(rng), u(rng), u(rng)});
  // Rows of points 1e-4 apart across the sphere's surface and the box's faces.
  for (double x = 0.95; x < 1.05; x += 1e-4) points.insert(points.end(), {x, tiny(rng), 0.01});
  for (double x = 1.45; x < 1.55; x += 1e-4) points.insert(points.end(), {x, tiny(rng), 0.2});
  const std::size_t n = points.size() / 3;
  std::vector<double> sd(n);
  std::vector<std::uint8_t> occ(n);
  s.signed_distance(points, sd);
  s.occupancy(points, occ);
  std::size_t inside = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_EQ(std::signbit(sd[i]), occ[i] == 1)
        << i << ": " << points[3 * i] << " " << points[3 * i + 1] << " " << points[3 * i + 2];
    inside += occ[i];
  }
  EXPECT_GT(inside, 1000u);
  EXPECT_LT(inside, n - 1000);
}

}  // namespace

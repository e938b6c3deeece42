// MeshKernels::occluded_if_valid (a shadow ray's whole query in one call: the validity check,
// the double ray's conversion, the stack and the walk) answers as `any` on to_mesh_ray's ray, on
// every ISA (those the CPU lacks are skipped), as the scalar kernels do: both node formats, the
// heap-stack path, rays whose direction spans every scale the conversion handles, zero direction
// components, tmin 0 and positive, tmax finite and infinite; and occluded_if_valid answers "not
// occluded" for rays that are not is_valid.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "mesh/mesh.h"
#include "mesh/procedural.h"
#include "mesh/wide_kernels.h"

namespace raycast {
namespace {

class OccludedEntry : public testing::TestWithParam<Isa> {
 protected:
  void SetUp() override {
    kernels_ = mesh_kernels(GetParam());
    if (!kernels_) GTEST_SKIP() << "this CPU or build lacks " << isa_name(GetParam());
  }
  const MeshKernels* kernels_ = nullptr;
};

// Shadow-like segments between points around a bumpy sphere (many blocked, many not), at
// direction scales 2^-400 to 2^400, some with zero components, some with an infinite tmax.
std::vector<Ray> segments(std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(-1.3, 1.3), unit(0, 1);
  std::uniform_int_distribution<int> scale_exp(-400, 400), pick(0, 9);
  std::vector<Ray> rays;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 a{pos(rng), pos(rng), pos(rng)}, b{pos(rng), pos(rng), pos(rng)};
    Vec3 d = b - a;
    if (pick(rng) == 0) d.x = 0;  // in a plane of constant x (the kernels clamp 1/d)
    if (pick(rng) == 0) d.y = -0.0;
    const double s = std::ldexp(1.0, scale_exp(rng));
    Ray r{a, d * s, pick(rng) < 3 ? unit(rng) / s : 0.0, 1 / s};
    if (pick(rng) == 0) r.tmax = std::numeric_limits<double>::infinity();
    if (!(r.tmin <= r.tmax) || length_squared(d) == 0) continue;
    rays.push_back(r);
  }
  return rays;
}

TEST_P(OccludedEntry, EqualsAnyOnTheConvertedRay) {
  std::mt19937 rng(7);
  const TriangleSoup sphere = make_octa_sphere(24, 0.2);
  const std::vector<Ray> rays = segments(rng);
  for (const bool quantised : {false, true}) {
    for (const bool heap_stack : {false, true}) {
      SCOPED_TRACE(std::string(quantised ? "quantised" : "float") + " nodes, " +
                   (heap_stack ? "heap" : "local") + " stack");
      MeshBvhConfig config;
      config.quantise_above = quantised ? 0 : std::numeric_limits<std::size_t>::max();
      MeshBvh bvh = build_mesh_bvh(sphere.positions, sphere.triangles, config);
      // A recorded depth beyond the local stack's 128 levels takes the heap stack (the walk
      // needs no more than the real depth).
      if (heap_stack) bvh.depth = 1000;
      std::vector<TraversalEntry> stack(traversal_stack_size(bvh));
      int blocked = 0;
      for (const Ray& ray : rays) {
        double scale;
        const MeshRay r = to_mesh_ray(ray, scale);
        const bool any = kernels_->any(bvh, r, stack.data());
        ASSERT_EQ(kernels_->occluded_if_valid(bvh, ray), any);
        ASSERT_EQ(kMeshKernelsScalar.occluded_if_valid(bvh, ray), any);
        blocked += any;
      }
      EXPECT_GT(blocked, 500);
      EXPECT_LT(blocked, int(rays.size()) - 500);
    }
  }
}

TEST_P(OccludedEntry, RaysNotValid_NeverOccluded) {
  // Rays through the middle of a sphere (any valid one is blocked), each broken in one way.
  const TriangleSoup sphere = make_octa_sphere(8);
  const MeshBvh bvh = build_mesh_bvh(sphere.positions, sphere.triangles, MeshBvhConfig{});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Ray good{{-2, 0.1, 0.2}, {1, 0, 0}, 0, 4};
  ASSERT_TRUE(kernels_->occluded_if_valid(bvh, good));
  std::vector<Ray> bad(9, good);
  bad[0].o.y = nan;
  bad[1].d.z = nan;
  bad[2].tmin = nan;
  bad[3].tmax = nan;
  bad[4].tmin = 5;  // tmin > tmax
  bad[5].d = {1e-160, 0, 0};
  bad[6].d = {1e160, 0, 0};
  bad[7].o.x = -1e160;
  bad[8].d = {inf, 0, 0};
  for (const Ray& r : bad) {
    ASSERT_FALSE(is_valid(r));
    EXPECT_FALSE(kernels_->occluded_if_valid(bvh, r));
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsas, OccludedEntry, testing::ValuesIn(kAllIsas),
                         [](const testing::TestParamInfo<Isa>& info) {
                           return std::string(isa_name(info.param));
                         });

}  // namespace
}  // namespace raycast

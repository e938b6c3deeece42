// MeshKernels::occluded (a shadow ray's whole query in one call: the double ray's conversion, the
// stack and the walk) answers as `any` on to_mesh_ray's ray, on every ISA (those the CPU lacks
// are skipped), bit for bit as the scalar kernels: both node formats, the heap-stack path, rays
// whose direction spans every scale the conversion handles, zero direction components, tmin 0 and
// positive, tmax finite and infinite.
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
        ASSERT_EQ(kernels_->occluded(bvh, ray), any);
        ASSERT_EQ(kMeshKernelsScalar.occluded(bvh, ray), any);
        blocked += any;
      }
      EXPECT_GT(blocked, 500);
      EXPECT_LT(blocked, int(rays.size()) - 500);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllIsas, OccludedEntry, testing::ValuesIn(kAllIsas),
                         [](const testing::TestParamInfo<Isa>& info) {
                           return std::string(isa_name(info.param));
                         });

}  // namespace
}  // namespace raycast

// Differential test against Embree 3 (only when the build has it): the same rays through both.
#include <gtest/gtest.h>

#include "bench/bench.h"
#include "bench/embree_peer.h"
#include "mesh/procedural.h"

namespace raycast {
namespace {

TEST(EmbreeDiff, ForestIncoherentAndPrimaryRays_AgreeWithEmbree) {
  if (!EmbreePeer::available()) GTEST_SKIP() << "built without Embree";
  TriangleSoup soup = make_procedural_mesh("forest", 60000);
  const auto mesh = make_mesh(std::move(soup.positions), std::move(soup.triangles));
  const EmbreePeer peer({{mesh, std::nullopt}}, 0);
  const MeshShape shape{mesh};
  for (const bool primary : {true, false}) {
    SCOPED_TRACE(primary ? "primary" : "incoherent");
    const std::vector<BenchRay> rays =
        primary ? primary_rays(mesh->box, 128, 128) : incoherent_rays(mesh->box, 20000);
    std::vector<PeerHit> theirs(rays.size());
    peer.intersect(rays, theirs);
    std::vector<std::uint8_t> blocked(rays.size());
    peer.occluded(rays, blocked);
    std::size_t hit_miss = 0, t_off = 0, hits = 0, any_off = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Ray ray{rays[i].o, rays[i].d, rays[i].tmin, rays[i].tmax};
      LocalHit h;
      const bool ours = intersect(shape, ray, h);
      hits += ours;
      any_off += occluded(shape, ray) != (blocked[i] != 0);
      if (ours != (theirs[i].geometry >= 0)) {
        ++hit_miss;
        continue;
      }
      if (ours &&
          std::abs(h.t - theirs[i].t) > 1e-4 * std::max(std::abs(h.t), std::abs(theirs[i].t)))
        ++t_off;
    }
    EXPECT_GT(hits, rays.size() / 10);
    // Rays grazing edges can differ between two correct float tests; a few per ten thousand.
    EXPECT_LE(hit_miss, rays.size() / 2000) << "hit/miss disagreements";
    EXPECT_LE(any_off, rays.size() / 2000) << "occlusion disagreements";
    EXPECT_LE(t_off, rays.size() / 500) << "t disagreements";
  }
}

}  // namespace
}  // namespace raycast

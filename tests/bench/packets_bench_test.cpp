// `raycast bench --packets`: the packet path finds the same hits as single rays on the same camera
// (with Embree, when the build has it, its rtcIntersect8 agrees too), and refuses what it cannot
// do.
#include <gtest/gtest.h>

#include "bench/bench.h"
#include "bench/embree_peer.h"
#include "io/scene_error.h"

namespace raycast {
namespace {

BenchOptions small_bench(bool packets) {
  BenchOptions o;
  o.procedural = "forest:20000";
  o.width = 203;  // not a multiple of 8: the last packet of the image is partly masked
  o.height = 64;
  o.repeat = 1;
  o.threads = 2;
  o.packets = packets;
  o.vs_embree = EmbreePeer::available();
  return o;
}

TEST(BenchPackets, PrimaryRays_SameHitsAsSingleRays) {
  const BenchResult single = run_bench(small_bench(false));
  const BenchResult packets = run_bench(small_bench(true));
  EXPECT_TRUE(packets.packets);
  EXPECT_EQ(packets.rays, single.rays);
  EXPECT_GT(single.hits, single.rays / 10);
  EXPECT_EQ(packets.hits, single.hits);
  if (packets.embree) {
    EXPECT_LE(packets.disagree_hit, packets.rays / 2000);
    EXPECT_LE(packets.disagree, packets.rays / 500);
  }
}

TEST(BenchPackets, PacketsOf16_SameHitsAsSingleRays) {
  const BenchResult single = run_bench(small_bench(false));
  BenchOptions o = small_bench(true);
  o.packet_width = 16;  // one 16-lane packet with AVX-512, two of 8 elsewhere; rtcIntersect16
  const BenchResult packets = run_bench(o);
  EXPECT_EQ(packets.packet_width, 16);
  EXPECT_EQ(packets.rays, single.rays);
  EXPECT_EQ(packets.hits, single.hits);
  if (packets.embree) {
    EXPECT_LE(packets.disagree_hit, packets.rays / 2000);
    EXPECT_LE(packets.disagree, packets.rays / 500);
  }
  o.packet_width = 12;
  EXPECT_THROW(run_bench(o), SceneError);
}

TEST(BenchPackets, ShadowRays_Refused) {
  BenchOptions o = small_bench(true);
  o.rays = BenchRays::kShadow;
  EXPECT_THROW(run_bench(o), SceneError);
}

}  // namespace
}  // namespace raycast

#include "mesh/mesh_packet16.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "math/lane_array.h"
#include "mesh/wide_kernels.h"

#if defined(__x86_64__)
namespace raycast::kernels_avx512 {
// mesh/packet_traverse.inl, compiled by mesh/wide_kernels_avx512.cpp.
int closest16_rays(const MeshBvh& bvh, const Ray* rays, int mask, MeshBvhHit* hits, double* scale,
                   PacketEntry* stack, TraversalEntry* single_stack);
}  // namespace raycast::kernels_avx512
#endif

namespace raycast {

namespace {

// The two stacks of a packet traversal: on the C++ stack up to depth 128, else on the heap.
template <class F>
int with_stacks(const MeshBvh& bvh, F&& trace) {
  constexpr std::size_t kLocal = 128 * (kNodeWidth - 1) + 2;
  const std::size_t need = traversal_stack_size(bvh);
  if (need > kLocal) [[unlikely]] {
    std::vector<PacketEntry> packet(need);
    std::vector<TraversalEntry> single(need);
    return trace(packet.data(), single.data());
  }
  PacketEntry packet[kLocal];
  TraversalEntry single[kLocal];
  return trace(packet, single);
}

}  // namespace

int packet_width(Isa isa) {
#if defined(__x86_64__)
  if (isa == Isa::kAvx512) return 16;
#endif
  (void)isa;
  return 8;
}

int intersect_closest16(const MeshBvh& bvh, Isa isa, const Ray* rays, int mask, MeshBvhHit* hits,
                        double* scale) {
  mask &= 0xFFFF;
  const MeshKernels* k = mesh_kernels(isa);
  if (!k) k = &active_mesh_kernels();
  return with_stacks(bvh, [&](PacketEntry* stack, TraversalEntry* single) {
#if defined(__x86_64__)
    if (k->isa == Isa::kAvx512)
      return kernels_avx512::closest16_rays(bvh, rays, mask, hits, scale, stack, single);
#endif
    const int lo =
        mask & 0xFF ? k->closest8_rays(bvh, rays, mask & 0xFF, hits, scale, stack, single) : 0;
    if (lo < 0) return -1;
    const int hi =
        mask >> 8 ? k->closest8_rays(bvh, rays + 8, mask >> 8, hits + 8, scale + 8, stack, single)
                  : 0;
    return hi < 0 ? -1 : lo | hi << 8;
  });
}

int intersect16(const MeshShape& s, const Ray* rays, int mask, LocalHit* hits) {
  const Mesh& m = *s.mesh;
  double scale[16];
  LaneArray<MeshBvhHit, 16> h;  // no zero-fill: the kernel writes the lanes that hit
  const int found = intersect_closest16(m.bvh, active_isa(), rays, mask, h.data(), scale);
  // A direction that needs to_mesh_ray's slow path: each half as intersect8 does it.
  if (found < 0)
    return intersect8(s, rays, mask & 0xFF, hits) |
           intersect8(s, rays + 8, mask >> 8 & 0xFF, hits + 8) << 8;
  write_packet_hits(m, rays, found, h.data(), scale, hits);
  return found;
}

}  // namespace raycast

#pragma once
// The mesh traversal kernels of each instruction set, as a table of function pointers: one
// traversal template (mesh/wide_traverse.inl) compiled once per ISA (mesh/wide_kernels_*.cpp)
// and picked at run time (math/isa.h; docs/architecture.md "ISA dispatch").
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "geometry/ray.h"
#include "math/isa.h"
#include "mesh/mesh_bvh.h"

namespace raycast {

/// One traversal stack entry: a child reference and the distance at which the ray enters it.
struct TraversalEntry {
  std::uint32_t ref;
  float tnear;
};

/// One packet traversal stack entry: a child reference, a lower bound of the entry distances of
/// its rays, and the lanes (rays) that enter it.
struct PacketEntry {
  std::uint32_t ref;
  float tnear;
  std::uint32_t lanes;
};

/// The three queries of one ISA. `stack` has room for traversal_stack_size(bvh) entries. The
/// results are bit for bit the same on every ISA (same float operations in the same order, no
/// fused multiply-add): only the order of `every`'s hits may differ.
struct MeshKernels {
  Isa isa;
  bool (*closest)(const MeshBvh& bvh, const MeshRay& ray, MeshBvhHit& hit, TraversalEntry* stack);
  bool (*any)(const MeshBvh& bvh, const MeshRay& ray, TraversalEntry* stack);
  void (*every)(const MeshBvh& bvh, const MeshRay& ray, std::vector<MeshBvhHit>& out,
                TraversalEntry* stack);
  /// The nearest hits of up to eight rays as one packet (rays[l] for each bit l of mask), the
  /// same bit for bit as `closest` on each; returns the mask of the rays that hit. Rays that
  /// cannot go as one packet (mesh/packet_traverse.inl) are traced one by one. `stack` and
  /// `single_stack` each have room for traversal_stack_size(bvh) entries.
  int (*closest8)(const MeshBvh& bvh, const MeshRay* rays, int mask, MeshBvhHit* hits,
                  PacketEntry* stack, TraversalEntry* single_stack);
  /// closest8 on the rays of `mask` converted as mesh.cpp's to_mesh_ray does (the same bits; its
  /// power-of-two scale of each converted lane in scale[l]), the conversion done on the lanes at
  /// once. Returns -1, with nothing traced, when a ray's direction is outside the conversion's
  /// fast range (convert those one by one).
  int (*closest8_rays)(const MeshBvh& bvh, const Ray* rays, int mask, MeshBvhHit* hits,
                       double* scale, PacketEntry* stack, TraversalEntry* single_stack);
  /// false for a ray that is not is_valid (the scene's rule), else `any` on the ray converted as
  /// to_mesh_ray does (mesh/mesh_ray.h), with a stack of its own: a shadow ray's whole query in
  /// one call (Scene's one-mesh path calls it straight).
  bool (*occluded_if_valid)(const MeshBvh& bvh, const Ray& ray);
};

/// The kernels of `isa`, or nullptr when this build or this CPU lacks it (isa_supported).
const MeshKernels* mesh_kernels(Isa isa);

/// The kernels of active_isa().
const MeshKernels& active_mesh_kernels();

/// The kernels of active_isa(), looked up once (the single-ray entries call it per query).
inline const MeshKernels& kernels_in_use() {
  static const MeshKernels& k = active_mesh_kernels();
  return k;
}

/// Traversal stack entries a single-ray query keeps on the C stack: every tree up to 128 levels
/// deep (deeper ones, which the SAH build makes only for pathological inputs, get a heap stack).
inline constexpr std::size_t kLocalTraversalStack = 128 * (kNodeWidth - 1) + 2;

/// A heap stack of traversal_stack_size(bvh) entries (out of line: only for pathological trees).
std::unique_ptr<TraversalEntry[]> deep_traversal_stack(const MeshBvh& bvh);

/// Returns f(stack) with a traversal stack big enough for `bvh`: a plain array on the C stack for
/// every tree up to 128 levels deep, the heap only beyond (the one choice of every single-ray
/// query; inlined, so the common path costs one compare).
template <class F>
[[gnu::noinline, gnu::cold]] decltype(auto) with_deep_traversal_stack(const MeshBvh& bvh, F& f) {
  const std::unique_ptr<TraversalEntry[]> stack = deep_traversal_stack(bvh);
  return f(stack.get());
}

template <class F>
[[gnu::always_inline]] inline decltype(auto) with_traversal_stack(const MeshBvh& bvh, F&& f) {
  // The heap stack out of line: its unique_ptr inlined here cost ~3 instructions per query.
  if (traversal_stack_size(bvh) > kLocalTraversalStack) [[unlikely]]
    return with_deep_traversal_stack(bvh, f);
  TraversalEntry stack[kLocalTraversalStack];
  return f(static_cast<TraversalEntry*>(stack));
}

/// Appends to a hit list (out of line, so that ISA-specific code never instantiates vector code).
void append_mesh_hit(std::vector<MeshBvhHit>& out, const MeshBvhHit& hit);

/// A group of four triangles that no ray hits (NaN vertices): the partner of a leaf's odd last
/// group when kernels test two groups per pass.
extern const TriangleGroup kEmptyTriangleGroup;

// The tables, defined by mesh/wide_kernels_<isa>.cpp (the SIMD ones on x86-64 only). Use
// mesh_kernels(isa), which also checks that the CPU can run them.
extern const MeshKernels kMeshKernelsScalar;
#if defined(__x86_64__)
extern const MeshKernels kMeshKernelsSse4;
extern const MeshKernels kMeshKernelsAvx2;
extern const MeshKernels kMeshKernelsAvx512;
#endif

}  // namespace raycast

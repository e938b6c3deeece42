#pragma once
// The per-mesh acceleration structure: an 8-wide BVH in float, built by collapsing the generic
// binary SAH tree of accel/bvh.h, with leaves of precomputed triangle groups (4 triangles in SoA
// form; the AVX2 and AVX-512 kernels test two groups per pass). Traversal is ordered, nearest child
// first, by kernels compiled per instruction set and picked at run time (mesh/wide_kernels.h).
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "accel/bvh.h"
#include "geometry/ray.h"
#include "math/vec3.h"

namespace raycast {

inline constexpr int kNodeWidth = 8;

// Two node formats with the same child references, chosen per mesh by its size
// (MeshBvhConfig::quantise_above: by default float nodes at every size, which trace faster than
// quantised ones on the 1M and 10M spheres of bench/embree_table.sh). A child reference is an inner
// node's index, or (bit 31 set) a leaf: bits 0-28 the first triangle group, bits 29-30 the group
// count minus 1. An unused slot has its bit clear in `used` and reference 0.

/// A node with up to 8 children, 256 bytes (four cache lines): the child boxes in float, one
/// 64-byte line per axis holding [lo of the eight children | hi of the eight children] (the
/// AVX-512 node test reads an axis in one load; the 8-lane tests read the near and the far half),
/// then the eight child references and the mask of the used children (unused planes are 0).
struct alignas(64) WideNode {
  float box[3][2 * kNodeWidth];
  std::uint32_t child[kNodeWidth];
  std::uint8_t used;
  std::uint8_t pad[31];
};
static_assert(sizeof(WideNode) == 256);

/// A node with up to 8 children, 128 bytes (two cache lines), its child boxes quantised to 8 bits
/// relative to the node (Ylitie, Karras and Laine 2017). The first line holds all the box test
/// reads: q[plane][child] for the planes lo_x, hi_x, lo_y, hi_y, lo_z, hi_z (48 bytes), the
/// node's origin, one power-of-two scale exponent per axis, and the mask of the used children. A
/// child's plane on axis a is dequantise(origin[a], node_scale(exponent[a]), q) in float, the same
/// on every ISA; the build picks each q so that this box holds the child's float box. The second
/// line: the eight child references, then padding.
struct alignas(64) QuantisedNode {
  std::uint8_t q[6][kNodeWidth];
  float origin[3];
  std::int8_t exponent[3];
  std::uint8_t used;
  std::uint32_t child[kNodeWidth];
  std::uint32_t pad[kNodeWidth];
};
static_assert(sizeof(QuantisedNode) == 128);

/// 2^e for e in [-126, 127] (a normal float), from its bits.
inline float node_scale(int e) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(e + 127) << 23);
}

/// A quantised plane: origin + q * scale, the product exact (q < 2^8, scale a power of two), the
/// sum rounded once (or overflowing to infinity). Never fused (the build is ISO C++).
inline float dequantise(float origin, float scale, std::uint8_t q) {
  return origin + static_cast<float>(q) * scale;
}

inline constexpr std::uint32_t kLeafBit = 0x80000000u;
inline constexpr int kMaxGroupsPerLeaf = 4;

/// Four triangles in SoA form (176 bytes): v[vertex][axis][lane], then the triangle index of each
/// lane and its caller-given source index (the mesh's input index: carried here so that a hit
/// needs no second, cache-missing lookup). A lane past the end of a leaf's triangles has NaN
/// vertices (never hit) and id and source kNoTriangle.
/// The vertices (not edges) are stored so that the watertight test sees shared vertices bit for
/// bit.
struct alignas(16) TriangleGroup {
  float v[3][3][4];
  std::uint32_t id[4];
  std::uint32_t source[4];
};
static_assert(sizeof(TriangleGroup) == 176);

inline constexpr std::uint32_t kNoTriangle = 0xFFFFFFFFu;

struct MeshBvhConfig {
  int bins = 16;          // SAH bins per axis
  int max_leaf_size = 8;  // triangles per leaf (at most 4 groups of 4)
  // The SAH counts leaf cost per block of this many triangles: 8, one pass of the AVX2 and
  // AVX-512 leaf test (two groups). With 4 the tree had 21 % more nodes and smaller leaves for the
  // same node visits per ray (bench/embree_table.sh).
  int leaf_block = 8;
  double traversal_cost = 1.0;
  // Meshes of more triangles than this get quantised nodes (half the node bytes: ~51 against
  // ~56 bytes per triangle), smaller ones float nodes. By default none: float nodes trace faster
  // at 1M and at 10M (bench/embree_table.sh: the 10M sphere's primary rays about 20 % faster,
  // incoherent ones level); the quantised format stays for callers short of memory.
  std::size_t quantise_above = std::numeric_limits<std::size_t>::max();
  // Early split clipping (Ernst and Greiner 2007; mesh/split_refs.h): at most this many extra
  // references per triangle (0.3: +30 %), given to the pieces of most wasted box area first.
  // Off by default: it wins only on meshes of long thin triangles (bench/embree_table.sh).
  double split_budget = 0;
  // Only pieces whose box's half area exceeds this many times the area of the triangle inside
  // are split (long thin or diagonal ones; an axis-aligned right triangle has 2; at 4 the
  // forest's ordinary triangles took the whole budget and lost, at 8 none is split).
  double split_min_ratio = 8;
};

struct MeshBvh {
  BuildVector<WideNode> nodes;        // float nodes, or none when quantised: nodes[0] is the
                                      // root when the root is not a leaf
  BuildVector<QuantisedNode> qnodes;  // quantised nodes (the mesh's other format), the same way
  BuildVector<TriangleGroup> groups;  // leaf data, permuted to leaf order (resize leaves them
                                      // uninitialised: the build's parallel pass writes them)
  std::uint32_t root = 0;             // a child reference: node 0, or a single leaf
  int depth = 0;                      // deepest node level (the root is level 1)
  bool quantised = false;             // which of nodes / qnodes the tree uses
  bool split = false;                 // split references: a triangle may sit in several leaves
  bool empty() const { return groups.empty(); }
  std::size_t memory_bytes() const {
    return nodes.size() * sizeof(WideNode) + qnodes.size() * sizeof(QuantisedNode) +
           groups.size() * sizeof(TriangleGroup);
  }
};

/// Builds the BVH over triangles (vertex index triples into positions; all finite). Triangle ids
/// in the leaves are indices into `triangles`; hits also report source[id] (the id itself when
/// `source` is empty). Parallel (oneTBB); the result does not depend on the thread count.
MeshBvh build_mesh_bvh(std::span<const Vec3f> positions,
                       std::span<const std::array<std::uint32_t, 3>> triangles,
                       const MeshBvhConfig& config = {},
                       std::span<const std::uint32_t> source = {});

/// A ray prepared for float traversal: origin and direction in float (the caller scales d by a
/// power of two so that it is representable), [tmin, tmax] in units of that d.
struct MeshRay {
  Vec3f o;
  Vec3f d;
  float tmin = 0;
  float tmax = 0;
};

/// The nearest triangle hit: its float t in units of MeshRay::d, barycentrics b1 and b2 (of the
/// second and third vertex) and the triangle index (into the build's `triangles`).
struct MeshBvhHit {
  float t = 0;
  float b1 = 0;
  float b2 = 0;
  std::uint32_t triangle = kNoTriangle;
  std::uint32_t source = kNoTriangle;  // source[triangle] of the build
  std::uint32_t group = 0;  // where the triangle's vertices sit in MeshBvh::groups (cache-warm)
  std::uint32_t lane = 0;
};

/// Vertex k (0, 1, 2) of a hit triangle, read from the leaf data the test just used.
inline Vec3f hit_vertex(const MeshBvh& bvh, const MeshBvhHit& h, int k) {
  const TriangleGroup& g = bvh.groups[h.group];
  return {g.v[k][0][h.lane], g.v[k][1][h.lane], g.v[k][2][h.lane]};
}

/// Entries a traversal stack needs for `bvh`: each level below the root pushes at most
/// kNodeWidth - 1 entries.
inline std::size_t traversal_stack_size(const MeshBvh& bvh) {
  return static_cast<std::size_t>(bvh.depth) * (kNodeWidth - 1) + 2;
}

/// The queries below run the kernels of active_isa() (math/isa.h); mesh/wide_kernels.h gives
/// those of any ISA.
/// Nearest hit with tmin <= t <= tmax (watertight test, float); false on a miss.
bool intersect_closest(const MeshBvh& bvh, const MeshRay& ray, MeshBvhHit& hit);
/// Whether any triangle is hit with tmin <= t <= tmax; stops at the first found.
bool intersect_any(const MeshBvh& bvh, const MeshRay& ray);
/// The nearest hits of up to eight rays traced as one packet (rays[l] for each bit l of mask):
/// the same hits as intersect_closest on each, bit for bit; returns the mask of those that hit.
int intersect_closest8(const MeshBvh& bvh, const MeshRay* rays, int mask, MeshBvhHit* hits);
/// intersect_closest8 on the double rays of `mask` converted as to_mesh_ray (mesh/mesh.h) does,
/// the conversion done on the lanes at once (scale[l]: to_mesh_ray's scale). -1, with nothing
/// traced, when a ray needs to_mesh_ray's slow path (MeshKernels::closest8_rays).
int intersect_closest8(const MeshBvh& bvh, const Ray* rays, int mask, MeshBvhHit* hits,
                       double* scale);
/// Every triangle hit with tmin <= t <= tmax, in no particular order, appended to out.
void intersect_every(const MeshBvh& bvh, const MeshRay& ray, std::vector<MeshBvhHit>& out);

}  // namespace raycast

// Diagnostic (not part of the library, not a test): why Embree traces the bench's shadow rays
// faster than raycast, where it does. It separates the tree from
// the kernel:
//   - counts, per shadow ray, what a scalar copy of the any-hit walk visits in a mesh BVH (nodes,
//     leaves, groups of 4 triangles, triangles, bytes of nodes and leaves), and the tree's SAH
//     figures (expected node visits and group tests of a random ray);
//   - builds the same 8-wide layout (WideNode + TriangleGroup) with Embree's own builder
//     (rtcBuildBVH, binned SAH, the settings of Embree's BVH8<Triangle4> scene builder) and counts
//     and times raycast's kernel on it;
//   - times raycast's kernel (kernels_in_use().any, the release path) on both trees against
//     Embree's rtcOccluded1 on the same float rays, one thread, CPU seconds, rounds alternated.
// Usage: shadow_tree_diag sphere|forest TRIANGLES [rounds] [our leaf size] [our bins]
//        [embree max leaf] [embree min leaf] [our SAH leaf block] [our SAH traversal cost]
#include <time.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/bench.h"
#include "mesh/mesh_bvh.h"
#include "mesh/procedural.h"
#include "mesh/wide_kernels.h"

#ifdef RAYCAST_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

using namespace raycast;

namespace {

double thread_cpu_s() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// A float ray as the kernels take it (d scaled by a power of two into [1, 2) on its largest
// axis, tmax scaled to match), and the unscaled one Embree takes.
struct DiagRay {
  MeshRay scaled;
  Vec3f o, d;
  float tmin, tmax;
};

DiagRay make_ray(const Vec3& o, const Vec3& d, double tmin, double tmax) {
  DiagRay r;
  r.o = Vec3f(float(o.x), float(o.y), float(o.z));
  r.d = Vec3f(float(d.x), float(d.y), float(d.z));
  r.tmin = float(tmin);
  r.tmax = float(tmax);
  const double m =
      std::max({std::abs(double(r.d.x)), std::abs(double(r.d.y)), std::abs(double(r.d.z))});
  int e = 0;
  std::frexp(m, &e);  // m in [2^(e-1), 2^e)
  const float s = std::ldexp(1.0f, 1 - e);
  r.scaled.o = r.o;
  r.scaled.d = Vec3f(r.d.x * s, r.d.y * s, r.d.z * s);
  r.scaled.tmin = r.tmin / s;
  r.scaled.tmax = r.tmax / s;
  return r;
}

// ---- Counting walk (scalar; the any-hit walk's order: first hit child taken, others pushed) --

struct Counts {
  double rays = 0, blocked = 0, nodes = 0, child_hits = 0, leaves = 0, groups = 0, pairs = 0,
         tris = 0, node_bytes = 0, leaf_bytes = 0;
  void add(const Counts& c) {
    rays += c.rays, blocked += c.blocked, nodes += c.nodes, child_hits += c.child_hits;
    leaves += c.leaves, groups += c.groups, pairs += c.pairs, tris += c.tris;
    node_bytes += c.node_bytes, leaf_bytes += c.leaf_bytes;
  }
};

bool hit_triangle(const TriangleGroup& g, int l, const MeshRay& r) {
  // Moeller-Trumbore in double (counting only: the kernels' watertight test decides real hits).
  const Vec3 a(g.v[0][0][l], g.v[0][1][l], g.v[0][2][l]);
  const Vec3 b(g.v[1][0][l], g.v[1][1][l], g.v[1][2][l]);
  const Vec3 c(g.v[2][0][l], g.v[2][1][l], g.v[2][2][l]);
  const Vec3 o(r.o.x, r.o.y, r.o.z), d(r.d.x, r.d.y, r.d.z);
  const Vec3 e1 = b - a, e2 = c - a, p = cross(d, e2);
  const double det = dot(e1, p);
  if (det == 0) return false;
  const Vec3 s = o - a;
  const double u = dot(s, p) / det;
  if (u < 0 || u > 1) return false;
  const Vec3 q = cross(s, e1);
  const double v = dot(d, q) / det;
  if (v < 0 || u + v > 1) return false;
  const double t = dot(e2, q) / det;
  return t >= r.tmin && t <= r.tmax;
}

Counts count_walk(const MeshBvh& bvh, const MeshRay& r) {
  Counts c;
  c.rays = 1;
  const double inv[3] = {1.0 / r.d.x, 1.0 / r.d.y, 1.0 / r.d.z};
  const double o[3] = {r.o.x, r.o.y, r.o.z};
  std::vector<std::uint32_t> stack;
  std::uint32_t ref = bvh.root;
  for (;;) {
    if (!(ref & kLeafBit)) {
      const WideNode& n = bvh.nodes[ref];
      c.nodes += 1;
      c.node_bytes += sizeof(WideNode);
      int mask = 0;
      for (int i = 0; i < kNodeWidth; ++i) {
        if (!(n.used >> i & 1)) continue;
        double t0 = r.tmin, t1 = r.tmax;
        for (int a = 0; a < 3; ++a) {
          double lo = (n.box[a][i] - o[a]) * inv[a],
                 hi = (n.box[a][kNodeWidth + i] - o[a]) * inv[a];
          if (lo > hi) std::swap(lo, hi);
          t0 = std::max(t0, lo);
          t1 = std::min(t1, hi * (1 + 1e-6));
        }
        if (t0 <= t1) mask |= 1 << i;
      }
      c.child_hits += std::popcount(unsigned(mask));
      if (mask) {
        // DIAG_ENTER_LAST: enter the last hit child (Embree's any-hit step), push the others.
        static const bool enter_last = std::getenv("DIAG_ENTER_LAST") != nullptr;
        const int first =
            enter_last ? 31 - std::countl_zero(unsigned(mask)) : std::countr_zero(unsigned(mask));
        if (enter_last) {
          for (int m = mask & ~(1 << first); m; m &= m - 1)
            stack.push_back(n.child[std::countr_zero(unsigned(m))]);
          ref = n.child[first];
          continue;
        }
        for (int m = mask & (mask - 1); m; m &= m - 1)
          stack.push_back(n.child[std::countr_zero(unsigned(m))]);
        ref = n.child[first];
        continue;
      }
    } else {
      const std::uint32_t first = ref & 0x1FFFFFFFu, count = ((ref >> 29) & 3u) + 1;
      c.leaves += 1;
      c.pairs += (count + 1) / 2;
      for (std::uint32_t gi = first; gi < first + count; ++gi) {
        c.groups += 1;
        c.leaf_bytes += sizeof(TriangleGroup);
        const TriangleGroup& g = bvh.groups[gi];
        bool hit = false;
        for (int l = 0; l < 4; ++l) {
          if (g.id[l] == kNoTriangle) continue;
          c.tris += 1;
          hit |= hit_triangle(g, l, r);
        }
        if (hit) {
          c.blocked = 1;
          return c;
        }
      }
    }
    if (stack.empty()) return c;
    ref = stack.back();
    stack.pop_back();
  }
}

// ---- Tree figures ---------------------------------------------------------------------------

struct TreeStats {
  double nodes = 0, leaves = 0, groups = 0, tris = 0, children = 0;
  double sah_nodes = 0, sah_groups = 0;  // expected node visits / group tests of a random ray
  int leaf_hist[17] = {};
};

double half_area(const float lo[3], const float hi[3]) {
  const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
  return x * y + y * z + z * x;
}

void tree_stats(const MeshBvh& bvh, std::uint32_t ref, double area, double root_area,
                TreeStats& s) {
  if (ref & kLeafBit) {
    const std::uint32_t first = ref & 0x1FFFFFFFu, count = ((ref >> 29) & 3u) + 1;
    int tris = 0;
    for (std::uint32_t gi = first; gi < first + count; ++gi)
      for (int l = 0; l < 4; ++l) tris += bvh.groups[gi].id[l] != kNoTriangle;
    s.leaves += 1;
    s.groups += count;
    s.tris += tris;
    s.leaf_hist[std::min(tris, 16)] += 1;
    s.sah_groups += count * area / root_area;
    return;
  }
  const WideNode& n = bvh.nodes[ref];
  s.nodes += 1;
  s.sah_nodes += area / root_area;
  for (int i = 0; i < kNodeWidth; ++i) {
    if (!(n.used >> i & 1)) continue;
    s.children += 1;
    const float lo[3] = {n.box[0][i], n.box[1][i], n.box[2][i]};
    const float hi[3] = {n.box[0][kNodeWidth + i], n.box[1][kNodeWidth + i],
                         n.box[2][kNodeWidth + i]};
    tree_stats(bvh, n.child[i], half_area(lo, hi), root_area, s);
  }
}

void print_tree(const char* name, const MeshBvh& bvh) {
  TreeStats s;
  const WideNode& root = bvh.nodes[0];
  float lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = *std::min_element(root.box[a], root.box[a] + kNodeWidth);
    hi[a] = *std::max_element(root.box[a] + kNodeWidth, root.box[a] + 2 * kNodeWidth);
  }
  const double ra = half_area(lo, hi);
  tree_stats(bvh, bvh.root, ra, ra, s);
  std::printf(
      "%s: nodes %.0f (children/node %.2f), leaves %.0f, tris/leaf %.2f, groups/leaf %.2f, "
      "fill %.2f, depth %d, B/tri %.1f; SAH: node visits %.2f + group tests %.2f = %.2f\n",
      name, s.nodes, s.children / s.nodes, s.leaves, s.tris / s.leaves, s.groups / s.leaves,
      s.tris / (4 * s.groups), bvh.depth, double(bvh.memory_bytes()) / s.tris, s.sah_nodes,
      s.sah_groups, s.sah_nodes + s.sah_groups);
  std::printf("  leaf sizes:");
  for (int i = 1; i <= 16; ++i)
    if (s.leaf_hist[i]) std::printf(" %d:%.1f%%", i, 100.0 * s.leaf_hist[i] / s.leaves);
  std::printf("\n");
}

void print_counts(const char* name, const MeshBvh& bvh, const std::vector<DiagRay>& rays) {
  Counts all, unblocked;
  for (const DiagRay& r : rays) {
    const Counts c = count_walk(bvh, r.scaled);
    all.add(c);
    if (!c.blocked) unblocked.add(c);
  }
  const auto line = [](const char* what, const Counts& c) {
    std::printf(
        "  %-9s rays %.0f: nodes %.2f (child hits %.2f), leaves %.2f, pairs %.2f, groups %.2f, "
        "tris %.2f, bytes %.0f (nodes %.0f + leaves %.0f)\n",
        what, c.rays, c.nodes / c.rays, c.child_hits / c.rays, c.leaves / c.rays, c.pairs / c.rays,
        c.groups / c.rays, c.tris / c.rays, (c.node_bytes + c.leaf_bytes) / c.rays,
        c.node_bytes / c.rays, c.leaf_bytes / c.rays);
  };
  std::printf("%s walk: blocked %.1f%%\n", name, 100.0 * all.blocked / all.rays);
  line("all", all);
  line("unblocked", unblocked);
}

// Triangles under a child reference.
double subtree_tris(const MeshBvh& bvh, std::uint32_t ref) {
  if (ref & kLeafBit) {
    const std::uint32_t first = ref & 0x1FFFFFFFu, count = ((ref >> 29) & 3u) + 1;
    double n = 0;
    for (std::uint32_t gi = first; gi < first + count; ++gi)
      for (int l = 0; l < 4; ++l) n += bvh.groups[gi].id[l] != kNoTriangle;
    return n;
  }
  const WideNode& w = bvh.nodes[ref];
  double n = 0;
  for (int i = 0; i < kNodeWidth; ++i)
    if (w.used >> i & 1) n += subtree_tris(bvh, w.child[i]);
  return n;
}

// The same tree with each node's children ordered by key (largest first): "tris" (Embree's
// order: subtree size), or "area" (surface area).
MeshBvh sorted_children(const MeshBvh& in, bool by_area) {
  MeshBvh out = in;
  for (WideNode& w : out.nodes) {
    const int n = std::popcount(unsigned(w.used));
    int order[kNodeWidth];
    double key[kNodeWidth];
    for (int i = 0; i < n; ++i) {
      order[i] = i;
      const float lo[3] = {w.box[0][i], w.box[1][i], w.box[2][i]};
      const float hi[3] = {w.box[0][kNodeWidth + i], w.box[1][kNodeWidth + i],
                           w.box[2][kNodeWidth + i]};
      key[i] = by_area ? half_area(lo, hi) : subtree_tris(in, w.child[i]);
    }
    std::stable_sort(order, order + n, [&](int a, int b) { return key[a] > key[b]; });
    const WideNode old = w;
    for (int i = 0; i < n; ++i) {
      w.child[i] = old.child[order[i]];
      for (int a = 0; a < 3; ++a) {
        w.box[a][i] = old.box[a][order[i]];
        w.box[a][kNodeWidth + i] = old.box[a][kNodeWidth + order[i]];
      }
    }
  }
  return out;
}

// The same tree with its leaf groups re-laid in the wide tree's depth-first order, a node's leaf
// children next to each other (the builder numbers groups in the binary tree's node order, which
// depends on the order its tasks finish).
void relay_groups(const MeshBvh& in, std::uint32_t ref, MeshBvh& out) {
  WideNode& w = out.nodes[ref];
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < kNodeWidth; ++i) {
      if (!(w.used >> i & 1)) continue;
      const std::uint32_t c = w.child[i];
      if (pass == 0 && (c & kLeafBit)) {
        const std::uint32_t first = c & 0x1FFFFFFFu, count = ((c >> 29) & 3u) + 1;
        const std::uint32_t at = std::uint32_t(out.groups.size());
        for (std::uint32_t g = first; g < first + count; ++g) out.groups.push_back(in.groups[g]);
        w.child[i] = (c & ~0x1FFFFFFFu) | at;
      } else if (pass == 1 && !(c & kLeafBit)) {
        relay_groups(in, c, out);
      }
    }
}

MeshBvh relaid_groups(const MeshBvh& in) {
  MeshBvh out = in;
  out.groups.clear();
  relay_groups(in, in.root, out);
  return out;
}

// ---- Embree's builder into raycast's layout ---------------------------------------------------

#ifdef RAYCAST_HAVE_EMBREE
struct BuildNode {
  bool leaf = false;
  unsigned count = 0;
  BuildNode* child[kNodeWidth] = {};
  RTCBounds box[kNodeWidth] = {};
  unsigned prim[32] = {};
};

void* create_node(RTCThreadLocalAllocator a, unsigned count, void*) {
  auto* n = new (rtcThreadLocalAlloc(a, sizeof(BuildNode), 16)) BuildNode;
  n->count = count;
  return n;
}
void set_children(void* p, void** c, unsigned count, void*) {
  for (unsigned i = 0; i < count; ++i)
    static_cast<BuildNode*>(p)->child[i] = static_cast<BuildNode*>(c[i]);
}
void set_bounds(void* p, const RTCBounds** b, unsigned count, void*) {
  for (unsigned i = 0; i < count; ++i) static_cast<BuildNode*>(p)->box[i] = *b[i];
}
void* create_leaf(RTCThreadLocalAllocator a, const RTCBuildPrimitive* prims, size_t count, void*) {
  auto* n = new (rtcThreadLocalAlloc(a, sizeof(BuildNode), 16)) BuildNode;
  n->leaf = true;
  n->count = unsigned(count);
  for (size_t i = 0; i < count; ++i) n->prim[i] = prims[i].primID;
  return n;
}

struct Converter {
  const TriangleSoup& mesh;
  MeshBvh& out;

  std::uint32_t leaf(const BuildNode& n) {
    const std::uint32_t first = std::uint32_t(out.groups.size());
    const unsigned groups = (n.count + 3) / 4;
    for (unsigned k = 0; k < groups; ++k) {
      TriangleGroup g;
      for (int l = 0; l < 4; ++l) {
        const unsigned i = k * 4 + unsigned(l);
        if (i >= n.count) {
          for (auto& vertex : g.v)
            for (auto& axis : vertex) axis[l] = std::nanf("");
          g.id[l] = g.source[l] = kNoTriangle;
          continue;
        }
        const std::uint32_t tri = n.prim[i];
        for (int v = 0; v < 3; ++v) {
          const Vec3f& p = mesh.positions[mesh.triangles[tri][v]];
          g.v[v][0][l] = p.x, g.v[v][1][l] = p.y, g.v[v][2][l] = p.z;
        }
        g.id[l] = g.source[l] = tri;
      }
      out.groups.push_back(g);
    }
    return kLeafBit | ((groups - 1) << 29) | first;
  }

  // Depth first, children in Embree's order (largest subtree first).
  std::uint32_t node(const BuildNode& n, int depth) {
    if (n.leaf) return leaf(n);
    out.depth = std::max(out.depth, depth);
    const std::uint32_t index = std::uint32_t(out.nodes.size());
    out.nodes.emplace_back();
    std::uint32_t refs[kNodeWidth] = {};
    for (unsigned i = 0; i < n.count; ++i) refs[i] = node(*n.child[i], depth + 1);
    WideNode& w = out.nodes[index];
    for (int i = 0; i < kNodeWidth; ++i) {
      const bool u = unsigned(i) < n.count;
      const RTCBounds& b = n.box[u ? i : 0];
      w.box[0][i] = u ? b.lower_x : 0, w.box[1][i] = u ? b.lower_y : 0,
      w.box[2][i] = u ? b.lower_z : 0;
      w.box[0][kNodeWidth + i] = u ? b.upper_x : 0;
      w.box[1][kNodeWidth + i] = u ? b.upper_y : 0;
      w.box[2][kNodeWidth + i] = u ? b.upper_z : 0;
      w.child[i] = u ? refs[i] : 0;
    }
    w.used = static_cast<std::uint8_t>((1u << n.count) - 1);
    std::fill(std::begin(w.pad), std::end(w.pad), 0);
    return index;
  }
};

MeshBvh embree_tree(RTCDevice device, const TriangleSoup& mesh, unsigned max_leaf,
                    unsigned min_leaf) {
  std::vector<RTCBuildPrimitive> prims(mesh.triangles.size());
  for (std::size_t i = 0; i < prims.size(); ++i) {
    const Vec3f& a = mesh.positions[mesh.triangles[i][0]];
    const Vec3f& b = mesh.positions[mesh.triangles[i][1]];
    const Vec3f& c = mesh.positions[mesh.triangles[i][2]];
    prims[i] = {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}),
                std::min({a.z, b.z, c.z}), 0,
                std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}),
                std::max({a.z, b.z, c.z}), unsigned(i)};
  }
  RTCBVH handle = rtcNewBVH(device);
  RTCBuildArguments args = rtcDefaultBuildArguments();
  args.byteSize = sizeof(args);
  args.buildQuality = RTC_BUILD_QUALITY_MEDIUM;
  args.maxBranchingFactor = kNodeWidth;
  args.maxDepth = 1024;
  // Embree's BVH8<Triangle4> scene builder: BVHNBuilderSAH<8,Triangle4>(bvh, scene, 4, 1.0f, 4,
  // inf) -> sahBlockSize 4, intCost 1, minLeafSize 4, maxLeafSize 4 * 7 blocks, travCost 1.
  args.sahBlockSize = 4;
  args.minLeafSize = min_leaf;
  args.maxLeafSize = max_leaf;
  args.traversalCost = 1.0f;
  args.intersectionCost = 1.0f;
  args.bvh = handle;
  args.primitives = prims.data();
  args.primitiveCount = prims.size();
  args.primitiveArrayCapacity = prims.size();
  args.createNode = create_node;
  args.setNodeChildren = set_children;
  args.setNodeBounds = set_bounds;
  args.createLeaf = create_leaf;
  auto* root = static_cast<BuildNode*>(rtcBuildBVH(&args));
  MeshBvh out;
  Converter conv{mesh, out};
  out.depth = 1;
  out.root = conv.node(*root, 1);
  rtcReleaseBVH(handle);
  return out;
}
#endif

// One thread, CPU seconds: raycast's release any-hit kernel over the rays.
double time_ours(const MeshBvh& bvh, const std::vector<DiagRay>& rays, std::size_t& blocked) {
  blocked = 0;
  const double t0 = thread_cpu_s();
  for (const DiagRay& r : rays) blocked += intersect_any(bvh, r.scaled);
  return thread_cpu_s() - t0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: %s sphere|forest TRIANGLES [rounds] [leaf] [bins] [embree max leaf] "
                 "[embree min leaf] [leaf block] [traversal cost]\n",
                 argv[0]);
    return 2;
  }
  const TriangleSoup mesh = make_procedural_mesh(argv[1], std::strtoull(argv[2], nullptr, 10));
  const int rounds = argc > 3 ? std::atoi(argv[3]) : 3;
  MeshBvhConfig config;
  if (argc > 4) config.max_leaf_size = std::atoi(argv[4]);
  if (argc > 5) config.bins = std::atoi(argv[5]);
  const unsigned emax = argc > 6 ? unsigned(std::atoi(argv[6])) : 16;
  const unsigned emin = argc > 7 ? unsigned(std::atoi(argv[7])) : 4;
  if (argc > 8) config.leaf_block = std::atoi(argv[8]);
  if (argc > 9) config.traversal_cost = std::atof(argv[9]);
  const MeshBvh ours = build_mesh_bvh(mesh.positions, mesh.triangles, config);

  // The bench's shadow rays, as near as a diagnostic needs: primary hits offset along the normal
  // towards the light.
  Aabb box;
  for (const Vec3f& p : mesh.positions) box.grow(Vec3(p.x, p.y, p.z));
  const Vec3 light = bench_light(box);
  const double eps = 1e-6 * length(box.extent());
  std::vector<DiagRay> rays;
  for (const BenchRay& b : primary_rays(box, 1024, 1024)) {
    const DiagRay pr = make_ray(b.o, b.d, b.tmin, std::min(b.tmax, 1e30));
    MeshBvhHit h;
    if (!intersect_closest(ours, pr.scaled, h)) continue;
    const Vec3 o(pr.scaled.o.x, pr.scaled.o.y, pr.scaled.o.z),
        d(pr.scaled.d.x, pr.scaled.d.y, pr.scaled.d.z);
    const Vec3 a(hit_vertex(ours, h, 0)), bb(hit_vertex(ours, h, 1)), c(hit_vertex(ours, h, 2));
    Vec3 n = normalize(cross(bb - a, c - a));
    Vec3 p = o + d * double(h.t);
    if (dot(n, light - p) < 0) n = -n;
    p = p + n * eps;
    rays.push_back(make_ray(p, light - p, 0, 1));
  }
  std::printf("%s %s: %zu triangles, %zu shadow rays\n", argv[1], argv[2], mesh.triangles.size(),
              rays.size());
  if (const char* ab = std::getenv("DIAG_AB_BLOCKS")) {
    // Two trees of this build, SAH leaf blocks A and B (e.g. "4,8"), timed alternately in this
    // process on the shadow (any hit), primary and incoherent (nearest hit) rays.
    MeshBvhConfig ca = config, cb = config;
    std::sscanf(ab, "%d,%d", &ca.leaf_block, &cb.leaf_block);
    const MeshBvh ta = build_mesh_bvh(mesh.positions, mesh.triangles, ca);
    const MeshBvh tb = std::getenv("DIAG_RELAY")
                           ? relaid_groups(ta)
                           : build_mesh_bvh(mesh.positions, mesh.triangles, cb);
    if (!ours.quantised) {
      print_tree("A", ta);
      print_tree("B", tb);
    }
    std::vector<DiagRay> primary, incoherent;
    for (const BenchRay& b : primary_rays(box, 1024, 1024))
      primary.push_back(make_ray(b.o, b.d, b.tmin, std::min(b.tmax, 1e30)));
    for (const BenchRay& b : incoherent_rays(box, 1 << 20))
      incoherent.push_back(make_ray(b.o, b.d, b.tmin, std::min(b.tmax, 1e30)));
    const auto closest = [](const MeshBvh& t, const std::vector<DiagRay>& rs) {
      std::size_t hits = 0;
      MeshBvhHit h;
      const double t0 = thread_cpu_s();
      for (const DiagRay& r : rs) hits += intersect_closest(t, r.scaled, h);
      return thread_cpu_s() - t0;
    };
    for (int round = 0; round < rounds; ++round) {
      std::size_t b = 0;
      double s[2], p[2], q[2];
      for (int k = 0; k < 2; ++k) {
        const MeshBvh& t = (k ^ (round & 1)) ? tb : ta;
        const int slot = (k ^ (round & 1));
        s[slot] = p[slot] = q[slot] = 1e30;
        for (int pass = 0; pass < 3; ++pass) {  // the fastest of three passes
          s[slot] = std::min(s[slot], time_ours(t, rays, b));
          p[slot] = std::min(p[slot], closest(t, primary));
          q[slot] = std::min(q[slot], closest(t, incoherent));
        }
      }
      std::printf("  round %d, B/A speed: shadow %.3f, primary %.3f, incoherent %.3f\n", round,
                  s[0] / s[1], p[0] / p[1], q[0] / q[1]);
    }
    return 0;
  }
  print_tree("ours", ours);
  print_counts("ours", ours, rays);
  const MeshBvh sorted = sorted_children(ours, std::getenv("DIAG_SORT_AREA") != nullptr);
  print_counts("ours, children largest first", sorted, rays);

#ifdef RAYCAST_HAVE_EMBREE
  RTCDevice device = rtcNewDevice("threads=1");
  const MeshBvh theirs = embree_tree(device, mesh, emax, emin);
  print_tree("embree-built", theirs);
  print_counts("embree-built", theirs, rays);

  RTCScene scene = rtcNewScene(device);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  std::vector<float> v(mesh.positions.size() * 3 + 1);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    v[3 * i] = mesh.positions[i].x, v[3 * i + 1] = mesh.positions[i].y,
          v[3 * i + 2] = mesh.positions[i].z;
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, v.data(), 0,
                             3 * sizeof(float), mesh.positions.size());
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                             mesh.triangles.data(), 0, 3 * sizeof(std::uint32_t),
                             mesh.triangles.size());
  rtcCommitGeometry(geom);
  rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(scene);
  const auto time_embree = [&](std::size_t& blocked) {
    blocked = 0;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    const double t0 = thread_cpu_s();
    for (const DiagRay& r : rays) {
      RTCRay q;
      q.org_x = r.o.x, q.org_y = r.o.y, q.org_z = r.o.z;
      q.dir_x = r.d.x, q.dir_y = r.d.y, q.dir_z = r.d.z;
      q.tnear = r.tmin, q.tfar = r.tmax, q.time = 0, q.mask = 0xFFFFFFFFu, q.id = 0, q.flags = 0;
      rtcOccluded1(scene, &ctx, &q);
      blocked += q.tfar < 0;
    }
    return thread_cpu_s() - t0;
  };
  std::printf("Mrays per CPU s (1 thread): ours-on-ours | ours-on-embree-tree | embree; ratios\n");
  for (int round = 0; round < rounds; ++round) {
    std::size_t b0 = 0, b1 = 0, b2 = 0;
    const double t0 = time_ours(ours, rays, b0);
    const double t1 = time_ours(theirs, rays, b1);
    const double t2 = time_embree(b2);
    std::size_t b3 = 0;
    const double t3 = time_ours(sorted, rays, b3);
    const double n = double(rays.size()) * 1e-6;
    std::printf("  round %d: ours with children largest first %.2f, /embree %.3f\n", round, n / t3,
                t2 / t3);
    std::printf(
        "  round %d: %.2f | %.2f | %.2f; ours/embree %.3f, ours-on-embree-tree/embree %.3f "
        "(blocked %zu %zu %zu)\n",
        round, n / t0, n / t1, n / t2, t2 / t0, t2 / t1, b0, b1, b2);
  }
  rtcReleaseScene(scene);
  rtcReleaseDevice(device);
#endif
  return 0;
}

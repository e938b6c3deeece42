#include "mesh/closest_point.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/distance.h"

namespace raycast {

namespace {

// Rounding of the stored boxes. The axes are unit vectors rounded to float, so their Gram matrix
// differs from the identity by a few 2^-24 per entry: coordinates along them and projections
// onto them differ by at most that times the sum of the half-extents, which the half-extents
// are widened by (kAxisSlack), and squared lengths measured along them shrink by at most
// 1 + 3 * 3 * 2^-24, which pruning allows for (kPruneSlack). Double rounding of the
// projections is covered by kRoundSlack times the box's magnitude.
constexpr double kAxisSlack = 4e-6;
constexpr double kRoundSlack = 1e-12;
constexpr double kPruneSlack = 4e-6;

// The second axis of a box from its first and third (float): n x u, computed in double and
// rounded to float like the others, so the axes stay unit and orthogonal to float rounding.
inline Vec3 third_axis(const Vec3& u, const Vec3& n) {
  const Vec3 v = cross(n, u);
  return Vec3(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

struct Obb {
  float c[3] = {0, 0, 0};
  float a[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // u, v, n
  float h[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                std::numeric_limits<float>::infinity()};
  double volume = kInfinity;
};

float round_up_to_float(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) >= x ? f
                                     : std::nextafter(f, std::numeric_limits<float>::infinity());
}

// The box along `axes` (u and n rounded to float, v = n x u from those) holding every point
// `each(f)` passes to f. An infinite box (bound 0 everywhere) when the values do not fit in
// float.
template <class Each>
Obb fit(const Vec3 (&axes)[3], Each&& each) {
  Obb out;
  Vec3 ad[3];
  for (int k : {0, 2})
    for (int j = 0; j < 3; ++j) {
      out.a[k][j] = static_cast<float>(axes[k][j]);
      ad[k][j] = out.a[k][j];
    }
  ad[1] = third_axis(ad[0], ad[2]);
  for (int j = 0; j < 3; ++j) out.a[1][j] = static_cast<float>(ad[1][j]);
  double lo[3] = {kInfinity, kInfinity, kInfinity}, hi[3] = {-kInfinity, -kInfinity, -kInfinity};
  each([&](const Vec3& v) {
    for (int k = 0; k < 3; ++k) {
      const double s = dot(v, ad[k]);
      lo[k] = std::min(lo[k], s);
      hi[k] = std::max(hi[k], s);
    }
  });
  Vec3 c;
  for (int k = 0; k < 3; ++k) c += (0.5 * (lo[k] + hi[k])) * ad[k];
  Vec3 cd;
  for (int j = 0; j < 3; ++j) {
    out.c[j] = static_cast<float>(c[j]);
    cd[j] = out.c[j];
  }
  double h[3] = {0, 0, 0};
  each([&](const Vec3& v) {
    const Vec3 d = v - cd;
    for (int k = 0; k < 3; ++k) h[k] = std::max(h[k], std::abs(dot(d, ad[k])));
  });
  const double sum = h[0] + h[1] + h[2];
  const double scale = std::max({std::abs(cd.x), std::abs(cd.y), std::abs(cd.z)}) + sum;
  const double widest = std::max({h[0], h[1], h[2]});
  out.volume = 1;
  for (int k = 0; k < 3; ++k) {
    out.h[k] = round_up_to_float(h[k] + kAxisSlack * sum + kRoundSlack * scale);
    out.volume *= h[k] + 1e-3 * widest;
  }
  bool finite = std::isfinite(scale) && std::isfinite(out.volume);
  for (int k = 0; k < 3; ++k) finite = finite && std::isfinite(out.h[k]) && std::isfinite(out.c[k]);
  return finite ? out : Obb{};
}

// Lower bounds of the squared distance from p to a node's four boxes.
void box_bounds(const MeshDistance::Node& node, const Vec3& p, double d2[4]) {
  for (int l = 0; l < 4; ++l) {
    const double d[3] = {p.x - node.c[0][l], p.y - node.c[1][l], p.z - node.c[2][l]};
    const float(*axes[3])[4] = {node.u, node.v, node.n};
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      const double q = d[0] * axes[k][0][l] + d[1] * axes[k][1][l] + d[2] * axes[k][2][l];
      const double out = std::max(std::abs(q) - static_cast<double>(node.h[k][l]), 0.0);
      s += out * out;
    }
    d2[l] = s;
  }
}

}  // namespace

double distance2(const Aabb& box, const Vec3& p) {
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max({box.lo[a] - p[a], 0.0, p[a] - box.hi[a]});
    d2 += d * d;
  }
  return d2;
}

namespace {

// The triangle range under each node of a binary BVH (leaves are contiguous in leaf order when
// the builder partitions in place; a subtree whose range has gaps keeps its axis-aligned box).
struct SubtreeRanges {
  std::vector<std::uint32_t> lo, hi, count;

  explicit SubtreeRanges(const Bvh& bvh)
      : lo(bvh.nodes.size()), hi(bvh.nodes.size()), count(bvh.nodes.size()) {
    visit(bvh, 0);
  }
  bool contiguous(std::uint32_t i) const { return count[i] == hi[i] - lo[i]; }

 private:
  void visit(const Bvh& bvh, std::uint32_t i) {
    const BvhNode& node = bvh.nodes[i];
    if (node.is_leaf()) {
      lo[i] = node.first, hi[i] = node.first + node.count, count[i] = node.count;
      return;
    }
    visit(bvh, node.first);
    visit(bvh, node.first + 1);
    lo[i] = std::min(lo[node.first], lo[node.first + 1]);
    hi[i] = std::max(hi[node.first], hi[node.first + 1]);
    count[i] = count[node.first] + count[node.first + 1];
  }
};

// The children of binary node i that a 4-wide node takes: open the child of largest area until
// there are 4 (or only leaves). Returns how many of `lanes` are used.
int wide_children(const Bvh& bvh, std::uint32_t i, std::uint32_t (&lanes)[4]) {
  lanes[0] = bvh.nodes[i].first, lanes[1] = bvh.nodes[i].first + 1;
  int used = 2;
  while (used < 4) {
    int pick = -1;
    double area = -1;
    for (int l = 0; l < used; ++l) {
      const BvhNode& c = bvh.nodes[lanes[l]];
      if (!c.is_leaf() && c.box.half_area() > area) pick = l, area = c.box.half_area();
    }
    if (pick < 0) break;
    const std::uint32_t opened = lanes[pick];
    lanes[pick] = bvh.nodes[opened].first;
    lanes[used++] = bvh.nodes[opened].first + 1;
  }
  return used;
}

constexpr Vec3 kWorldAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

// The oriented box of a patch of triangles (each(f) passes f their corners): the world-aligned
// box, or one in the patch's frame when that is smaller: its area-weighted mean normal, and in
// the plane the world axis along which the box `box` is widest. The frame is tried only for
// patches whose normals mostly agree (|mean| > 0.3 of the summed areas).
template <class Each>
Obb patch_box(const Aabb& box, const Vec3& normal_sum, double area, Each&& each) {
  Obb best = fit(kWorldAxes, each);
  if (!(length(normal_sum) > 0.3 * area && area > 0)) return best;
  const Vec3 nz = normalize(normal_sum);
  const Vec3 e = box.extent();
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int x, int y) { return e[x] > e[y]; });
  for (int o : order) {
    const Vec3 u = kWorldAxes[o] - dot(kWorldAxes[o], nz) * nz;
    if (length(u) < 0.3) continue;
    const Vec3 nx = normalize(u);
    const Vec3 axes[3] = {nx, cross(nz, nx), nz};
    const Obb oriented = fit(axes, each);
    if (oriented.volume < best.volume) best = oriented;
    break;
  }
  return best;
}

}  // namespace

MeshDistance::MeshDistance(const Mesh& mesh, const std::optional<Transform>& xf) {
  const std::size_t n = mesh.triangles.size();
  std::vector<Tri> tris(n);
  std::vector<Aabb> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& t = mesh.triangles[i];
    Vec3 v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = Vec3(mesh.positions[t[k]]);
      if (xf) v[k] = xf->point(v[k]);
      boxes[i].grow(v[k]);
    }
    tris[i] = {v[0], v[1], v[2], static_cast<std::int32_t>(mesh.source[i])};
    box_.grow(boxes[i]);
  }
  if (n == 0) return;
  BvhBuildConfig config;
  config.max_leaf_size = 4;
  const Bvh bvh = build_bvh(boxes, config);
  tris_.resize(n);
  for (std::size_t i = 0; i < bvh.prims.size(); ++i) tris_[i] = tris[bvh.prims[i]];
  if (bvh.nodes[0].is_leaf()) {
    root_ref_ = bvh.nodes[0].first, root_count_ = bvh.nodes[0].count;
    return;
  }
  std::vector<LaneSource> sources;
  collapse(bvh, 0, sources);
  root_ref_ = 0, root_count_ = 0;
  fit_lane_boxes(bvh, sources);
}

std::uint32_t MeshDistance::collapse(const Bvh& bvh, std::uint32_t i,
                                     std::vector<LaneSource>& sources) {
  std::uint32_t lanes[4] = {0, 0, 0, 0};
  const int used = wide_children(bvh, i, lanes);
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  for (int l = 0; l < 4; ++l) {
    std::uint32_t ref = 0, cnt = kNone;
    if (l < used) {
      const BvhNode& c = bvh.nodes[lanes[l]];
      if (c.is_leaf())
        ref = c.first, cnt = c.count;
      else
        ref = collapse(bvh, lanes[l], sources), cnt = 0;
      sources.push_back({index, static_cast<std::uint32_t>(l), lanes[l]});
    }
    nodes_[index].ref[l] = ref;
    nodes_[index].count[l] = cnt;
  }
  return index;
}

void MeshDistance::fit_lane_boxes(const Bvh& bvh, const std::vector<LaneSource>& sources) {
  const SubtreeRanges ranges(bvh);
  tbb::parallel_for(std::size_t(0), sources.size(), [&](std::size_t j) {
    const LaneSource& job = sources[j];
    const std::uint32_t s = job.binary_node;
    const Aabb& box = bvh.nodes[s].box;
    Obb best;
    if (ranges.contiguous(s)) {
      const std::uint32_t lo = ranges.lo[s], hi = ranges.hi[s];
      Vec3 normal_sum;
      double area = 0;
      for (std::uint32_t t = lo; t < hi; ++t) {
        const Vec3 nt = cross(tris_[t].b - tris_[t].a, tris_[t].c - tris_[t].a);
        normal_sum += nt, area += length(nt);
      }
      best = patch_box(box, normal_sum, area, [&](auto&& f) {
        for (std::uint32_t t = lo; t < hi; ++t) f(tris_[t].a), f(tris_[t].b), f(tris_[t].c);
      });
    } else if (box.is_bounded()) {
      best = fit(kWorldAxes, [&](auto&& f) {
        for (int k = 0; k < 8; ++k)
          f(Vec3(k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y,
                 k & 4 ? box.hi.z : box.lo.z));
      });
    }
    Node& node = nodes_[job.node];
    for (int k = 0; k < 3; ++k) {
      node.c[k][job.lane] = best.c[k];
      node.h[k][job.lane] = best.h[k];
      node.u[k][job.lane] = best.a[0][k];
      node.v[k][job.lane] = best.a[1][k];
      node.n[k][job.lane] = best.a[2][k];
    }
  });
  // Lanes without a child: a finite box that is never looked at (count kNone).
  for (Node& node : nodes_)
    for (int l = 0; l < 4; ++l)
      if (node.count[l] == kNone)
        for (int k = 0; k < 3; ++k) {
          node.c[k][l] = node.h[k][l] = 0;
          node.u[k][l] = k == 0 ? 1.f : 0.f;
          node.v[k][l] = k == 1 ? 1.f : 0.f;
          node.n[k][l] = k == 2 ? 1.f : 0.f;
        }
}

bool MeshDistance::closest(const Vec3& p, Result& best) const {
  if (tris_.empty()) return false;
  bool improved = false;
  auto test_leaf = [&](std::uint32_t first, std::uint32_t count) {
    for (std::uint32_t i = first; i < first + count; ++i) {
      const Tri& t = tris_[i];
      const Vec3 q = closest_point_on_triangle(p, t.a, t.b, t.c);
      const double d2 = length_squared(q - p);
      if (d2 < best.distance2 || (d2 == best.distance2 && t.prim < best.prim)) {
        best = {q, d2, t.prim};
        improved = true;
      }
    }
  };
  if (root_count_ != 0) {
    test_leaf(root_ref_, root_count_);
    return improved;
  }
  // Best-first: the entry of least bound next (a binary heap), until the least bound exceeds
  // the best so far (allowing for the boxes' rounding). This opens only about the nodes whose
  // bound is below the final distance; a depth-first walk opens about 1.6x as many on the
  // curved meshes of python/bench_python.py. Ties are never pruned, so the least prim wins whatever
  // the order.
  struct Entry {
    double d2;
    std::uint32_t ref, count;
  };
  auto farther = [](const Entry& a, const Entry& b) { return a.d2 > b.d2; };
  std::vector<Entry> heap;  // about three entries per node opened
  heap.reserve(128);
  heap.push_back({0, 0, 0});
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), farther);
    const Entry e = heap.back();
    heap.pop_back();
    const double bound = best.distance2 * (1 + kPruneSlack);
    if (e.d2 > bound) break;  // every entry left is at least as far
    if (e.count != 0) {
      test_leaf(e.ref, e.count);
      continue;
    }
    const Node& node = nodes_[e.ref];
    double d2[4];
    box_bounds(node, p, d2);
    for (int l = 0; l < 4; ++l) {
      if (node.count[l] == kNone || d2[l] > bound) continue;
      // Start every kept child's fetch now, so that their cache misses overlap.
      const char* child = node.count[l] == 0 ? reinterpret_cast<const char*>(&nodes_[node.ref[l]])
                                             : reinterpret_cast<const char*>(&tris_[node.ref[l]]);
      const std::size_t bytes = node.count[l] == 0 ? sizeof(Node) : node.count[l] * sizeof(Tri);
      for (std::size_t b = 0; b < bytes; b += 64) __builtin_prefetch(child + b);
      heap.push_back({d2[l], node.ref[l], node.count[l]});
      std::push_heap(heap.begin(), heap.end(), farther);
    }
  }
  return improved;
}

}  // namespace raycast

#include "mesh/mesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#if defined(__unix__)
#include <sys/resource.h>
#endif

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include "accel/build_memory.h"
#include "io/progress.h"
#include "math/lane_array.h"
#include "mesh/mesh_ray.h"
#include "mesh/wide_kernels.h"

namespace raycast {

namespace {

// CPU milliseconds (user + system, all threads) of the process so far; 0 where unknown.
double process_cpu_ms() {
#if defined(__unix__)
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return 1e3 * (u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-3 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
#else
  return 0;
#endif
}

// A fixed direction for the inside test of closed meshes: irrational-looking so that it is
// unlikely to run exactly along an edge of a modelled mesh.
const Vec3 kContainsDirection = normalize(Vec3{0.5377, 0.6337, 0.5561});

Vec3 vertex(const Mesh& m, std::uint32_t tri, int k) {
  return Vec3(m.positions[m.triangles[tri][k]]);
}

Vec3 face_normal_unnormalised(const Mesh& m, std::uint32_t tri) {
  const Vec3 v0 = vertex(m, tri, 0);
  return cross(vertex(m, tri, 1) - v0, vertex(m, tri, 2) - v0);
}

// Signed volume of a closed mesh (positive when its normals point out).
double signed_volume(const Mesh& m) {
  double v = 0;
  for (std::uint32_t i = 0; i < m.triangles.size(); ++i)
    v += dot(vertex(m, i, 0), cross(vertex(m, i, 1), vertex(m, i, 2)));
  return v / 6;
}

}  // namespace

void Mesh::find_closed() const {
  std::call_once(closed_once_, [this] {
    closed_ = is_closed_mesh(positions, triangles);
    if (closed_ && signed_volume(*this) < 0) orientation_ = -1;
  });
}

bool Mesh::closed() const {
  find_closed();
  return closed_;
}

double Mesh::orientation() const {
  find_closed();
  return orientation_;
}

std::size_t Mesh::memory_bytes() const {
  return positions.capacity() * sizeof(Vec3f) + triangles.capacity() * sizeof(triangles[0]) +
         source.capacity() * sizeof(std::uint32_t) + normals.capacity() * sizeof(Vec3f) +
         bvh.memory_bytes();
}

std::vector<Vec3f> angle_weighted_normals(
    const std::vector<Vec3f>& positions,
    const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  std::vector<Vec3> acc(positions.size());
  for (const auto& t : triangles) {
    const Vec3 p[3] = {Vec3(positions[t[0]]), Vec3(positions[t[1]]), Vec3(positions[t[2]])};
    const Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
    const double len = length(n);
    if (!(len > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
      const double la = length(a), lb = length(b);
      if (!(la > 0 && lb > 0)) continue;
      const double angle = std::acos(std::clamp(dot(a, b) / (la * lb), -1.0, 1.0));
      acc[t[k]] += (angle / len) * n;
    }
  }
  std::vector<Vec3f> out(positions.size());
  for (std::size_t i = 0; i < acc.size(); ++i) {
    const double len = length(acc[i]);
    out[i] = len > 0 ? Vec3f(acc[i] / len) : Vec3f{0, 0, 1};
  }
  return out;
}

bool is_closed_mesh(const std::vector<Vec3f>& positions,
                    const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  if (triangles.empty()) return false;
  // Weld vertices by exact position, so that files which split vertices (STL, per-face normals)
  // are judged by their geometry.
  std::vector<std::uint32_t> order(positions.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  auto key = [&](std::uint32_t i) {
    const Vec3f& p = positions[i];
    return std::array<float, 3>{p.x, p.y, p.z};
  };
  tbb::parallel_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
  std::vector<std::uint32_t> weld(positions.size());
  std::uint32_t id = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i > 0 && key(order[i]) != key(order[i - 1])) ++id;
    weld[order[i]] = id;
  }
  std::vector<std::uint64_t> edges;
  edges.reserve(triangles.size() * 3);
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      std::uint64_t a = weld[t[k]], b = weld[t[(k + 1) % 3]];
      if (a > b) std::swap(a, b);
      edges.push_back(a << 32 | b);
    }
  tbb::parallel_sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i != 2) return false;
    i = j;
  }
  return true;
}

namespace {

// Rows per block of the parallel passes of make_mesh (fixed, so results never depend on threads).
constexpr std::size_t kBlock = 65536;

// The smallest i in [0, n) with bad(i), or n: in parallel, the same answer as a serial scan.
template <class Bad>
std::size_t first_bad(std::size_t n, Bad bad) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, kBlock), n,
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t found) {
        for (std::size_t i = r.begin(); i < r.end() && i < found; ++i)
          if (bad(i)) return i;
        return found;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
}

}  // namespace

std::shared_ptr<const Mesh> make_mesh(std::vector<Vec3f> positions,
                                      std::vector<std::array<std::uint32_t, 3>> triangles,
                                      std::vector<Vec3f> normals, const MeshOptions& options) {
  const std::size_t nv = positions.size(), nt = triangles.size();
  StageProgress stage("checking triangles", nt);
  {
    if (const std::size_t i =
            first_bad(nv, [&](std::size_t k) { return !is_finite(positions[k]); });
        i < nv)
      throw std::invalid_argument("vertex " + std::to_string(i) + " is not finite");
    if (const std::size_t i = first_bad(nt,
                                        [&](std::size_t k) {
                                          const auto& t = triangles[k];
                                          return t[0] >= nv || t[1] >= nv || t[2] >= nv;
                                        });
        i < nt) {
      std::uint32_t bad = 0;
      for (std::uint32_t k : triangles[i])
        if (k >= nv) {
          bad = k;
          break;
        }
      throw std::invalid_argument("triangle " + std::to_string(i) + " has vertex index " +
                                  std::to_string(bad) + " out of range (" + std::to_string(nv) +
                                  " vertices)");
    }
    if (!normals.empty()) {
      if (normals.size() != nv)
        throw std::invalid_argument("normals must be one per vertex (" +
                                    std::to_string(normals.size()) + " for " + std::to_string(nv) +
                                    " vertices)");
      if (const std::size_t i = first_bad(normals.size(),
                                          [&](std::size_t k) {
                                            const Vec3 n(normals[k]);
                                            return !is_finite(n) || !(length_squared(n) > 0);
                                          });
          i < normals.size())
        throw std::invalid_argument("normal " + std::to_string(i) + " is zero or not finite");
      tbb::parallel_for(std::size_t(0), normals.size(),
                        [&](std::size_t k) { normals[k] = Vec3f(normalize(Vec3(normals[k]))); });
    }
  }
  auto mesh = std::make_shared<Mesh>();
  Mesh& m = *mesh;
  m.positions = std::move(positions);
  {
    // Drop degenerate triangles: repeated indices or zero area (exactly, from the float
    // vertices). One parallel pass flags them, counts the kept ones per block and bounds them;
    // a second scatters the kept ones when any was dropped.
    const std::size_t blocks = (nt + kBlock - 1) / kBlock;
    std::vector<std::uint8_t> keep(nt);
    std::vector<std::size_t> kept(blocks + 1, 0);
    std::vector<Aabb> box(blocks);
    tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
      const std::size_t e = std::min(nt, (b + 1) * kBlock);
      std::size_t count = 0;
      Aabb bb;
      for (std::size_t i = b * kBlock; i < e; ++i) {
        const auto& t = triangles[i];
        const Vec3 v0(m.positions[t[0]]), v1(m.positions[t[1]]), v2(m.positions[t[2]]);
        const bool degenerate = t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
                                length_squared(cross(v1 - v0, v2 - v0)) == 0;
        keep[i] = !degenerate;
        if (degenerate) continue;
        ++count;
        bb.grow(v0);
        bb.grow(v1);
        bb.grow(v2);
      }
      kept[b + 1] = count;
      box[b] = bb;
      stage.advance(e - b * kBlock);
    });
    for (std::size_t b = 0; b < blocks; ++b) {
      kept[b + 1] += kept[b];
      m.box.grow(box[b]);
    }
    const std::size_t total = kept[blocks];
    m.dropped = nt - total;
    m.source.resize(total);  // uninitialised: written in parallel below
    if (m.dropped == 0) {
      m.triangles = std::move(triangles);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, total, kBlock),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i)
                            m.source[i] = static_cast<std::uint32_t>(i);
                        });
    } else {
      resize_huge(m.triangles, total);
      tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
        const std::size_t e = std::min(nt, (b + 1) * kBlock);
        std::size_t out = kept[b];
        for (std::size_t i = b * kBlock; i < e; ++i) {
          if (!keep[i]) continue;
          m.triangles[out] = triangles[i];
          m.source[out++] = static_cast<std::uint32_t>(i);
        }
      });
      triangles = {};
    }
  }
  stage.finish();
  if (options.smooth)
    m.normals =
        normals.empty() ? angle_weighted_normals(m.positions, m.triangles) : std::move(normals);
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_ms();
  m.bvh = build_mesh_bvh(m.positions, m.triangles, options.bvh, m.source);
  m.build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  m.build_cpu_ms = process_cpu_ms() - cpu_start;
  return mesh;
}

MeshRay to_mesh_ray(const Ray& ray, double& scale) { return convert_ray(ray, scale); }

namespace {

// refine_t's body, inlined into refine_hit (the call passed five vectors through memory).
[[gnu::always_inline]] inline double plane_t(const Vec3& v0, const Vec3& v1, const Vec3& v2,
                                             const Vec3& o, const Vec3& d, double t_float) {
  const Vec3 n = cross(v1 - v0, v2 - v0);
  const double dn = dot(d, n);
  if (dn == 0) return t_float;  // the ray runs in the plane: keep the float test's answer
  const double t = dot(v0 - o, n) / dn;
  return std::isfinite(t) ? t : t_float;
}

}  // namespace

double refine_t(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& o, const Vec3& d,
                double t_float) {
  return plane_t(v0, v1, v2, o, d, t_float);
}

namespace {

[[gnu::always_inline]] inline double refine_hit(const Mesh& m, const MeshBvhHit& h, const Ray& ray,
                                                double scale) {
  return plane_t(Vec3(hit_vertex(m.bvh, h, 0)), Vec3(hit_vertex(m.bvh, h, 1)),
                 Vec3(hit_vertex(m.bvh, h, 2)), ray.o, ray.d, h.t * scale);
}

}  // namespace

Aabb bounds(const MeshShape& s) { return s.mesh->box; }

bool intersect(const Mesh& m, const Ray& ray, LocalHit& hit) {
  double scale;
  const MeshRay r = convert_ray(ray, scale);
  LaneArray<MeshBvhHit, 1> hl;  // no zero-fill: the kernel writes it when it returns true
  MeshBvhHit& h = hl[0];
  // The kernel called from here (intersect_closest, which also handles trees too deep for the
  // local stack, without its call level and without a lambda whose captures went through memory).
  bool found;
  if (traversal_stack_size(m.bvh) <= kLocalTraversalStack) [[likely]] {
    TraversalEntry stack[kLocalTraversalStack];  // uninitialised: the kernel writes before it reads
    found = kernels_in_use().closest(m.bvh, r, h, stack);
  } else {
    found = intersect_closest(m.bvh, r, h);
  }
  if (!found) return false;
  // The double refinement and the record for the winning hit only.
  const double t = std::clamp(refine_hit(m, h, ray, scale), ray.tmin, ray.tmax);
  hit = LocalHit{t, static_cast<std::int32_t>(h.source), static_cast<std::int32_t>(h.triangle),
                 h.b1, h.b2};
  return true;
}

bool intersect(const MeshShape& s, const Ray& ray, LocalHit& hit) {
  return intersect(*s.mesh, ray, hit);
}

int intersect8(const MeshShape& s, const Ray* rays, int mask, LocalHit* hits) {
  const Mesh& m = *s.mesh;
  double scale[8];
  LaneArray<MeshBvhHit, 8> h;  // no zero-fill: the kernel writes the lanes that hit
  // The lanes converted at once (same bits as convert_ray); one by one when a direction needs
  // convert_ray's slow path.
  int found = intersect_closest8(m.bvh, rays, mask, h.data(), scale);
  if (found < 0) {
    MeshRay r[8];
    for (int l = 0; l < 8; ++l)
      if (mask >> l & 1) r[l] = convert_ray(rays[l], scale[l]);
    found = intersect_closest8(m.bvh, r, mask, h.data());
  }
  write_packet_hits(m, rays, found, h.data(), scale, hits);
  return found;
}

void write_packet_hits(const Mesh& m, const Ray* rays, int found, const MeshBvhHit* h,
                       const double* scale, LocalHit* hits) {
  for (; found; found &= found - 1) {
    const int l = __builtin_ctz(found);
    const double t = std::clamp(refine_hit(m, h[l], rays[l], scale[l]), rays[l].tmin, rays[l].tmax);
    hits[l] = LocalHit{t, static_cast<std::int32_t>(h[l].source),
                       static_cast<std::int32_t>(h[l].triangle), h[l].b1, h[l].b2};
  }
}

bool occluded(const Mesh& m, const Ray& ray) {
  double scale;
  const MeshRay r = convert_ray(ray, scale);
  // The kernel called from here (intersect_any without its call level). Scene's one-mesh path
  // calls MeshKernels::occluded_if_valid instead, the conversion inside the kernel.
  return with_traversal_stack(
      m.bvh, [&](TraversalEntry* stack) { return kernels_in_use().any(m.bvh, r, stack); });
}

bool occluded(const MeshShape& s, const Ray& ray) { return occluded(*s.mesh, ray); }

void spans(const MeshShape& s, const Ray& ray, SpanList& out) {
  const Mesh& m = *s.mesh;
  Ray line = ray;
  line.tmin = -kInfinity;
  line.tmax = kInfinity;
  double scale;
  const MeshRay r = to_mesh_ray(line, scale);
  std::vector<MeshBvhHit> hits;
  intersect_every(m.bvh, r, hits);
  if (hits.empty()) return;
  struct Crossing {
    LocalHit hit;
    bool entering;
  };
  std::vector<Crossing> xs;
  xs.reserve(hits.size());
  const double orientation = m.orientation();
  for (const MeshBvhHit& h : hits) {
    const double t = refine_hit(m, h, ray, scale);
    const double facing = dot(ray.d, face_normal_unnormalised(m, h.triangle)) * orientation;
    xs.push_back({LocalHit{t, static_cast<std::int32_t>(h.source),
                           static_cast<std::int32_t>(h.triangle), h.b1, h.b2},
                  facing < 0});
  }
  std::sort(xs.begin(), xs.end(),
            [](const Crossing& a, const Crossing& b) { return a.hit.t < b.hit.t; });
  // Two triangles sharing the edge or vertex a ray passes through both report the crossing:
  // crossings closer than the float resolution of the mesh's coordinates are one event.
  const double coord = std::max(max_component(abs(m.box.lo)), max_component(abs(m.box.hi)));
  const double tol = 8 * std::numeric_limits<float>::epsilon() * coord / length(ray.d);
  if (!m.closed()) {
    // An open mesh: each event is a zero-length span (same-direction duplicates merged).
    std::vector<Crossing> merged;
    for (const Crossing& c : xs) {
      if (!merged.empty() && merged.back().entering == c.entering &&
          c.hit.t - merged.back().hit.t <= tol)
        continue;
      merged.push_back(c);
    }
    for (const Crossing& c : merged) out.add(c.hit, c.hit);
    return;
  }
  // A closed mesh: the nonzero winding rule over events. An event's direction is the sign of its
  // entries minus its exits, so duplicates of one crossing count once and a ray that only touches
  // an edge or vertex (leaving through one face's plane, entering through the other's at the same
  // t, in either sorted order) changes nothing. Overlapping closed components give their union.
  int winding = 0;
  LocalHit in;
  for (std::size_t i = 0; i < xs.size();) {
    std::size_t j = i + 1;
    while (j < xs.size() && xs[j].hit.t - xs[j - 1].hit.t <= tol) ++j;
    int entries = 0, exits = 0;
    const LocalHit* first_entry = nullptr;
    const LocalHit* last_exit = nullptr;
    for (std::size_t k = i; k < j; ++k) {
      if (xs[k].entering) {
        if (entries++ == 0) first_entry = &xs[k].hit;
      } else {
        ++exits;
        last_exit = &xs[k].hit;
      }
    }
    i = j;
    if (entries > exits) {
      if (winding++ == 0) in = *first_entry;
    } else if (exits > entries && winding > 0) {
      if (--winding == 0) out.add(in, *last_exit);
    }
  }
}

SurfaceInfo surface(const MeshShape& s, const Ray& ray, const LocalHit& hit) {
  const Mesh& m = *s.mesh;
  const auto tri = static_cast<std::uint32_t>(hit.part);
  const Vec3 v0 = vertex(m, tri, 0), v1 = vertex(m, tri, 1), v2 = vertex(m, tri, 2);
  const double b1 = hit.a, b2 = hit.b, b0 = 1 - b1 - b2;
  SurfaceInfo si;
  // The point on the ray at the refined t, so that p = o + t d as users expect. Its distance to
  // the plane comes from solving for t: the numerator dot(v0 - o, n) carries at most
  // gamma(5) dot(|v0 - o|, |n|) (plus the error of n from exact float vertices), divided by |d.n|.
  const Vec3 n = cross(v1 - v0, v2 - v0);
  si.p = ray.at(hit.t);
  const double dn = std::abs(dot(ray.d, n));
  const double t_error = dn > 0 ? gamma(7) * dot(abs(v0 - ray.o), abs(n)) / dn : 0;
  si.p_error = gamma(3) * (abs(ray.o) + abs(hit.t * ray.d)) + t_error * abs(ray.d);
  // The BVH and triangle test run in float on a float copy of the ray: a secondary ray leaving
  // p is rounded to float too, so the bound must cover float rounding of p and of the
  // barycentric interpolation (pbrt-v4's gamma(7) in float, plus one rounding of p).
  constexpr double kFloatGamma9 = 9 * 0x1p-24 / (1 - 9 * 0x1p-24);
  const Vec3 float_bound = kFloatGamma9 * (abs(b0 * v0) + abs(b1 * v1) + abs(b2 * v2) + abs(si.p));
  si.p_error += float_bound;
  if (!(dn > 0) || !is_finite(si.p_error)) {
    // The ray runs in the plane (or the bound overflowed): take the point from the barycentrics.
    si.p = b0 * v0 + b1 * v1 + b2 * v2;
    si.p_error = gamma(7) * (abs(b0 * v0) + abs(b1 * v1) + abs(b2 * v2)) + float_bound;
  }
  si.n = normalize(cross(v1 - v0, v2 - v0));
  si.shading_n = si.n;
  if (!m.normals.empty()) {
    const auto& t = m.triangles[tri];
    const Vec3 ns =
        b0 * Vec3(m.normals[t[0]]) + b1 * Vec3(m.normals[t[1]]) + b2 * Vec3(m.normals[t[2]]);
    const double len = length(ns);
    if (len > 0 && std::isfinite(len)) si.shading_n = dot(ns, si.n) < 0 ? -ns / len : ns / len;
  }
  si.u = b1;
  si.v = b2;
  return si;
}

bool contains(const MeshShape& s, const Vec3& p) {
  if (!s.mesh->closed()) return false;
  SpanList out;
  spans(s, Ray{p, kContainsDirection}, out);
  for (const Span& sp : out)
    if (sp.in.t <= 0 && 0 <= sp.out.t) return true;
  return false;
}

bool is_closed(const MeshShape& s) { return s.mesh->closed(); }

}  // namespace raycast

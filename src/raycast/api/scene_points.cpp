// Point queries of raycast::api::Scene: occupancy, closest points, signed distance.
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "api/distance_index.h"
#include "api/impl.h"

namespace raycast::api {

namespace {

constexpr std::size_t kPointGrain = 64;
// Points nearer to a surface than this times the scene's magnitude never share a sign: it is far
// above every on-surface tolerance of api/distance_index.cpp (16 float ulps for meshes).
constexpr double kSignReuseFloor = 1e-4;

void check_points(std::span<const double> points, std::size_t out_size, std::size_t per_point,
                  const char* call) {
  if (points.size() % 3 != 0)
    throw std::invalid_argument(std::string(call) + ": points must hold x, y, z per point");
  if (out_size != points.size() / 3 * per_point)
    throw std::invalid_argument(std::string(call) + ": the output has the wrong size");
}

raycast::Vec3 point_at(std::span<const double> points, std::size_t i) {
  return {points[3 * i], points[3 * i + 1], points[3 * i + 2]};
}

// Spreads the low 21 bits of x to every third bit (a 63-bit Morton code from three of them).
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffff;
  x = (x | x << 16) & 0x1f0000ff0000ff;
  x = (x | x << 8) & 0x100f00f00f00f00f;
  x = (x | x << 4) & 0x10c30c30c30c30c3;
  x = (x | x << 2) & 0x1249249249249249;
  return x;
}

// The points' indices in Morton order of their position in the points' box (non-finite points
// last). Queries of neighbouring points walk the same tree nodes: taking them in this order
// keeps those nodes in cache, which on large meshes is most of a query's time
// (python/bench_python.py). Answers do not depend on the order.
std::vector<std::uint32_t> spatial_order(std::span<const double> points) {
  const std::size_t n = points.size() / 3;
  raycast::Aabb box;
  for (std::size_t i = 0; i < n; ++i)
    if (const raycast::Vec3 p = point_at(points, i); raycast::is_finite(p)) box.grow(p);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keys(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) {
                        const raycast::Vec3 p = point_at(points, i);
                        std::uint64_t code = ~std::uint64_t(0);
                        if (raycast::is_finite(p)) {
                          code = 0;
                          for (int a = 0; a < 3; ++a) {
                            const double w = box.hi[a] - box.lo[a];
                            const double u = w > 0 ? (p[a] - box.lo[a]) / w : 0;
                            const double cell = std::clamp(u * 2097151.0, 0.0, 2097151.0);
                            code |= spread_bits(static_cast<std::uint64_t>(cell)) << a;
                          }
                        }
                        keys[i] = {code, static_cast<std::uint32_t>(i)};
                      }
                    });
  tbb::parallel_sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = keys[i].second;
  return order;
}

// f(i, state) for every point, in parallel, with one State per block of consecutive points; in
// spatial order when the batch is large enough for it to pay (and the indices fit the order's 32
// bits), so that consecutive points of a block are neighbours.
template <class State, class F>
void for_each_point_with(std::span<const double> points, F&& f) {
  const std::size_t n = points.size() / 3;
  if (n < 256 || n > 0xffffffffu) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kPointGrain),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        State state;
                        for (std::size_t i = r.begin(); i != r.end(); ++i) f(i, state);
                      });
    return;
  }
  const std::vector<std::uint32_t> order = spatial_order(points);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kPointGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      State state;
                      for (std::size_t i = r.begin(); i != r.end(); ++i) f(order[i], state);
                    });
}

template <class F>
void for_each_point(std::span<const double> points, F&& f) {
  struct None {};
  for_each_point_with<None>(points, [&](std::size_t i, None&) { f(i); });
}

}  // namespace

void Scene::occupancy(std::span<const double> points, std::span<std::uint8_t> out) const {
  const DistanceIndex& index = ready().distance_index();
  check_points(points, out.size(), 1, "occupancy");
  for_each_point(points, [&](std::size_t i) {
    const raycast::Vec3 p = point_at(points, i);
    out[i] = raycast::is_finite(p) && index.inside(p) ? 1 : 0;
  });
}

void Scene::closest_points(std::span<const double> points, double* closest, ObjectId* object,
                           std::int32_t* primitive, double* distance) const {
  const Impl& impl = ready();
  const DistanceIndex& index = impl.distance_index();
  if (!index.unsupported().empty()) throw NotImplementedError(index.unsupported());
  check_points(points, points.size() / 3, 1, "closest_points");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for_each_point(points, [&](std::size_t i) {
    const raycast::Vec3 p = point_at(points, i);
    DistanceIndex::Nearest n;
    if (raycast::is_finite(p)) n = index.nearest(p);
    const bool found = n.object >= 0;
    if (closest)
      for (int k = 0; k < 3; ++k) closest[3 * i + k] = found ? n.point[k] : nan;
    if (object) object[i] = found ? impl.scene.objects[n.object].entry : kNoObject;
    if (primitive) primitive[i] = found ? n.prim : -1;
    if (distance) distance[i] = found ? std::sqrt(n.distance2) : nan;
  });
}

void Scene::signed_distance(std::span<const double> points, std::span<double> out) const {
  const DistanceIndex& index = ready().distance_index();
  if (!index.unsupported().empty()) throw NotImplementedError(index.unsupported());
  check_points(points, out.size(), 1, "signed_distance");
  // The sign of the previous point of the block is reused when this point lies well inside the
  // ball around it that no surface meets (radius: its distance), both points being far beyond
  // every on-surface tolerance: inside-ness of a closed solid is constant in such a ball. Exact,
  // and with the points in spatial order it saves most parity queries.
  struct Previous {
    raycast::Vec3 p;
    double d = 0;  // 0: no usable previous point
    bool inside = false;
  };
  const double magnitude = index.magnitude();
  for_each_point_with<Previous>(points, [&](std::size_t i, Previous& prev) {
    const raycast::Vec3 p = point_at(points, i);
    if (!raycast::is_finite(p)) {
      out[i] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    const DistanceIndex::Nearest n = index.nearest(p);
    const double d = n.object >= 0 ? std::sqrt(n.distance2) : raycast::kInfinity;
    const double scale =
        std::max({magnitude, std::abs(p.x), std::abs(p.y), std::abs(p.z)}) * kSignReuseFloor;
    const bool far = d > scale && std::isfinite(d);
    bool inside;
    if (far && prev.d > 0 && raycast::length(p - prev.p) < 0.5 * prev.d) {
      inside = prev.inside;
    } else {
      inside = index.inside(p, n.distance2);
    }
    prev = far && std::isfinite(scale) ? Previous{p, d, inside} : Previous{};
    out[i] = inside ? -d : d;
  });
}

}  // namespace raycast::api

// Point queries of raycast::api::Scene: occupancy, closest points, signed distance.
#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

#include "public/distance_index.h"
#include "public/impl.h"

namespace raycast::api {

namespace {

constexpr std::size_t kGrain = 64;

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

template <class F>
void for_each_point(std::size_t n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
                    });
}

}  // namespace

void Scene::occupancy(std::span<const double> points, std::span<std::uint8_t> out) const {
  const DistanceIndex& index = ready().distance_index();
  check_points(points, out.size(), 1, "occupancy");
  for_each_point(out.size(), [&](std::size_t i) {
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
  for_each_point(points.size() / 3, [&](std::size_t i) {
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
  for_each_point(out.size(), [&](std::size_t i) {
    const raycast::Vec3 p = point_at(points, i);
    if (!raycast::is_finite(p)) {
      out[i] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    const DistanceIndex::Nearest n = index.nearest(p);
    const double d = n.object >= 0 ? std::sqrt(n.distance2) : raycast::kInfinity;
    out[i] = index.inside(p) ? -d : d;
  });
}

}  // namespace raycast::api

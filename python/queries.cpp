// The batch queries of raycast.Scene (docs/python.md "Queries"): Open3D's names, numpy in and
// out, the GIL released while the engine runs. A query on an uncommitted scene commits it.
#include <limits>

#include "bindings.h"

namespace raycast::python {

namespace {

// Signed ids (-1: none) as Open3D's uint32 with INVALID_ID.
py::array_t<std::uint32_t> as_ids(const py::array_t<std::int32_t>& a) {
  py::array_t<std::uint32_t> out(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()));
  const std::int32_t* in = a.data();
  std::uint32_t* o = out.mutable_data();
  for (py::ssize_t i = 0; i < a.size(); ++i)
    o[i] = in[i] < 0 ? kInvalidId : static_cast<std::uint32_t>(in[i]);
  return out;
}

std::int32_t* as_signed(py::array_t<std::uint32_t>& a) {
  static_assert(sizeof(std::int32_t) == sizeof(std::uint32_t));
  return reinterpret_cast<std::int32_t*>(a.mutable_data());
}

py::dict cast_rays(Scene& scene, const py::handle& rays) {
  ensure_committed(scene);
  RayView v = ray_view(rays);
  auto t = make_array<double>(v.shape, {});
  // Ids go straight into Open3D's uint32 arrays: -1 (none) is INVALID_ID bit for bit.
  auto object = make_array<std::uint32_t>(v.shape, {});
  auto prim = make_array<std::uint32_t>(v.shape, {});
  auto uv = make_array<double>(v.shape, {2});
  auto normal = make_array<double>(v.shape, {3});
  auto point = make_array<double>(v.shape, {3});
  HitColumns out{t.mutable_data(),     as_signed(object),     as_signed(prim),
                 point.mutable_data(), normal.mutable_data(), uv.mutable_data()};
  {
    py::gil_scoped_release release;
    scene.intersect(v.rays, out);
  }
  py::dict d;
  d["t_hit"] = t;
  d["geometry_ids"] = object;
  d["primitive_ids"] = prim;
  d["primitive_uvs"] = uv;
  d["primitive_normals"] = normal;
  d["points"] = point;
  return d;
}

py::array_t<bool> test_occlusions(Scene& scene, const py::handle& rays, double tnear, double tfar) {
  ensure_committed(scene);
  RayView v = ray_view(rays);
  v.rays.tmin = tnear;
  v.rays.tmax = tfar;
  auto out = make_array<bool>(v.shape, {});
  static_assert(sizeof(bool) == 1);
  std::span<std::uint8_t> o(reinterpret_cast<std::uint8_t*>(out.mutable_data()), v.rays.count);
  {
    py::gil_scoped_release release;
    scene.occluded(v.rays, o);
  }
  return out;
}

py::array_t<std::int32_t> count_intersections(Scene& scene, const py::handle& rays) {
  ensure_committed(scene);
  RayView v = ray_view(rays);
  auto out = make_array<std::int32_t>(v.shape, {});
  {
    py::gil_scoped_release release;
    scene.count_intersections(v.rays, {out.mutable_data(), v.rays.count});
  }
  return out;
}

py::dict list_intersections(Scene& scene, const py::handle& rays) {
  ensure_committed(scene);
  RayView v = ray_view(rays);
  std::vector<std::int64_t> offsets;
  std::vector<Crossing> crossings;
  {
    py::gil_scoped_release release;
    scene.intersect_all(v.rays, offsets, crossings);
  }
  const auto n = static_cast<py::ssize_t>(crossings.size());
  py::array_t<std::int64_t> splits(static_cast<py::ssize_t>(offsets.size()));
  std::copy(offsets.begin(), offsets.end(), splits.mutable_data());
  py::array_t<std::int64_t> ray_ids(n);
  py::array_t<double> t(n);
  py::array_t<std::uint32_t> geometry(n);
  py::array_t<double> normals({n, py::ssize_t{3}});
  {
    py::gil_scoped_release release;
    for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
      for (std::int64_t k = offsets[r]; k < offsets[r + 1]; ++k) ray_ids.mutable_data()[k] = r;
    for (py::ssize_t k = 0; k < n; ++k) {
      const Crossing& c = crossings[k];
      t.mutable_data()[k] = c.t;
      geometry.mutable_data()[k] = static_cast<std::uint32_t>(c.object);
      for (int j = 0; j < 3; ++j) normals.mutable_data()[3 * k + j] = c.normal[j];
    }
  }
  py::dict d;
  d["ray_splits"] = splits;
  d["ray_ids"] = ray_ids;
  d["t_hit"] = t;
  d["geometry_ids"] = geometry;
  d["primitive_normals"] = normals;
  return d;
}

py::array_t<float> compute_occupancy(Scene& scene, const py::handle& points) {
  ensure_committed(scene);
  PointView v = point_view(points);
  std::vector<std::uint8_t> inside(v.count);
  {
    py::gil_scoped_release release;
    scene.occupancy({v.points.data(), 3 * v.count}, inside);
  }
  auto out = make_array<float>(v.shape, {});
  for (std::size_t i = 0; i < v.count; ++i) out.mutable_data()[i] = inside[i];
  return out;
}

py::dict compute_closest_points(Scene& scene, const py::handle& points) {
  ensure_committed(scene);
  PointView v = point_view(points);
  auto q = make_array<double>(v.shape, {3});
  auto object = make_array<std::int32_t>(v.shape, {});
  auto prim = make_array<std::int32_t>(v.shape, {});
  auto dist = make_array<double>(v.shape, {});
  {
    py::gil_scoped_release release;
    scene.closest_points({v.points.data(), 3 * v.count}, q.mutable_data(), object.mutable_data(),
                         prim.mutable_data(), dist.mutable_data());
  }
  py::dict d;
  d["points"] = q;
  d["geometry_ids"] = as_ids(object);
  d["primitive_ids"] = as_ids(prim);
  d["distances"] = dist;
  return d;
}

py::array_t<double> compute_distance(Scene& scene, const py::handle& points) {
  ensure_committed(scene);
  PointView v = point_view(points);
  auto dist = make_array<double>(v.shape, {});
  {
    py::gil_scoped_release release;
    scene.closest_points({v.points.data(), 3 * v.count}, nullptr, nullptr, nullptr,
                         dist.mutable_data());
  }
  return dist;
}

py::array_t<double> compute_signed_distance(Scene& scene, const py::handle& points) {
  ensure_committed(scene);
  PointView v = point_view(points);
  auto dist = make_array<double>(v.shape, {});
  {
    py::gil_scoped_release release;
    scene.signed_distance({v.points.data(), 3 * v.count}, {dist.mutable_data(), v.count});
  }
  return dist;
}

}  // namespace

void bind_queries(py::class_<Scene>& scene) {
  scene
      .def("commit", &ensure_committed,
           "Builds the acceleration structures unless already built (the first query does it "
           "too); afterwards the scene is immutable and thread-safe.")
      .def_property_readonly("committed", &Scene::committed)
      .def_property_readonly("object_count", &Scene::object_count)
      .def("shape_name", &Scene::shape_name, py::arg("object"))
      .def("cast_rays", &cast_rays, py::arg("rays"),
           "Nearest hits: dict of t_hit, geometry_ids, primitive_ids, primitive_uvs, "
           "primitive_normals, points.")
      .def("test_occlusions", &test_occlusions, py::arg("rays"), py::arg("tnear") = 0.0,
           py::arg("tfar") = std::numeric_limits<double>::infinity())
      .def("count_intersections", &count_intersections, py::arg("rays"))
      .def("list_intersections", &list_intersections, py::arg("rays"))
      .def("compute_occupancy", &compute_occupancy, py::arg("query_points"))
      .def("compute_closest_points", &compute_closest_points, py::arg("query_points"))
      .def("compute_distance", &compute_distance, py::arg("query_points"))
      .def("compute_signed_distance", &compute_signed_distance, py::arg("query_points"));
}

}  // namespace raycast::python

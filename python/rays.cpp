#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>

#include "bindings.h"

namespace raycast::python {

namespace {

std::string describe(const py::array& a) {
  std::ostringstream s;
  s << py::str(a.dtype()).cast<std::string>() << " array shaped (";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s << (i ? ", " : "") << a.shape(i);
  s << (a.ndim() == 1 ? ",)" : ")");
  return s.str();
}

py::array as_array(const py::handle& h, const char* what, const char* expected) {
  if (!py::isinstance<py::array>(h))
    throw py::value_error(std::string(what) + " must be a numpy array " + expected + ", got " +
                          py::str(py::type::of(h)).cast<std::string>());
  return py::reinterpret_borrow<py::array>(h);
}

}  // namespace

RayView ray_view(const py::handle& h, const char* what) {
  const char* expected = "shaped (..., 6) of float32 or float64 ([ox, oy, oz, dx, dy, dz] per ray)";
  py::array a = as_array(h, what, expected);
  const bool f32 = py::isinstance<py::array_t<float>>(a);
  const bool f64 = py::isinstance<py::array_t<double>>(a);
  if ((!f32 && !f64) || a.ndim() < 1 || a.shape(a.ndim() - 1) != 6)
    throw py::value_error(std::string(what) + " must be a numpy array " + expected + ", got " +
                          describe(a));
  RayView v;
  for (py::ssize_t i = 0; i + 1 < a.ndim(); ++i) v.shape.push_back(a.shape(i));
  // The leading axes collapse to one stride when each one's stride is the next one's times the
  // next one's size (axes of size 1 excepted); otherwise the rays are copied into C order.
  std::size_t count = 1;
  for (const py::ssize_t s : v.shape) count *= static_cast<std::size_t>(s);
  bool collapses = true;
  if (a.ndim() >= 3) {
    py::ssize_t expect = a.strides(a.ndim() - 2);
    for (py::ssize_t j = a.ndim() - 3; j >= 0; --j) {
      expect *= a.shape(j + 1);
      if (a.shape(j) > 1 && a.strides(j) != expect) collapses = false;
    }
  }
  if (!collapses) a = py::module_::import("numpy").attr("ascontiguousarray")(a);
  v.keep = a;
  v.rays.data = a.data();
  v.rays.type = f32 ? RayArray::Type::kFloat32 : RayArray::Type::kFloat64;
  v.rays.count = count;
  v.rays.ray_stride = a.ndim() >= 2 ? a.strides(a.ndim() - 2) : 0;
  v.rays.component_stride = a.strides(a.ndim() - 1);
  return v;
}

}  // namespace raycast::python

namespace raycast::python {

PointView point_view(const py::handle& h, const char* what) {
  const char* expected = "shaped (..., 3) of float32 or float64 ([x, y, z] per point)";
  py::array a = as_array(h, what, expected);
  const bool real = py::isinstance<py::array_t<float>>(a) || py::isinstance<py::array_t<double>>(a);
  if (!real || a.ndim() < 1 || a.shape(a.ndim() - 1) != 3)
    throw py::value_error(std::string(what) + " must be a numpy array " + expected + ", got " +
                          describe(a));
  PointView v;
  for (py::ssize_t i = 0; i + 1 < a.ndim(); ++i) v.shape.push_back(a.shape(i));
  v.points = py::array_t<double, py::array::c_style>::ensure(a);  // a view when already so
  v.count = static_cast<std::size_t>(v.points.size() / 3);
  return v;
}

py::array_t<float> create_rays_pinhole(double fov_deg, const Vec3d& center, const Vec3d& eye,
                                       const Vec3d& up, int width, int height) {
  if (width <= 0 || height <= 0) throw py::value_error("width_px and height_px must be > 0");
  if (!(fov_deg > 0 && fov_deg < 180)) throw py::value_error("fov_deg must be in (0, 180)");
  auto sub = [](const Vec3d& a, const Vec3d& b) {
    return Vec3d{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  auto cross = [](const Vec3d& a, const Vec3d& b) {
    return Vec3d{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto unit = [](const Vec3d& a) {
    const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (!(l > 0) || !std::isfinite(l))
      throw py::value_error("create_rays_pinhole: eye, center and up must span a camera frame");
    return Vec3d{a[0] / l, a[1] / l, a[2] / l};
  };
  const Vec3d f = unit(sub(center, eye));
  const Vec3d r = unit(cross(f, up));
  const Vec3d u = cross(r, f);
  // As Open3D: fov_deg is the horizontal field of view, the principal point the image centre.
  const double focal = 0.5 * width / std::tan(0.5 * fov_deg * std::numbers::pi / 180);
  py::array_t<float> out(
      {static_cast<py::ssize_t>(height), static_cast<py::ssize_t>(width), py::ssize_t{6}});
  auto m = out.mutable_unchecked<3>();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double cx = (x + 0.5 - 0.5 * width) / focal, cy = (y + 0.5 - 0.5 * height) / focal;
      for (int k = 0; k < 3; ++k) {
        m(y, x, k) = static_cast<float>(eye[k]);
        m(y, x, 3 + k) = static_cast<float>(f[k] + cx * r[k] - cy * u[k]);
      }
    }
  return out;
}

}  // namespace raycast::python

namespace raycast::python {

void bind_rays(py::module_& m) {
  m.def(
      "_time_intersect",
      [](Scene& scene, const py::handle& rays) {
        // The C++ batch path alone, on the caller's rays and preallocated outputs, for
        // python/bench_python.py's overhead figure.
        ensure_committed(scene);
        RayView v = ray_view(rays);
        std::vector<double> t(v.rays.count), uv(2 * v.rays.count), n(3 * v.rays.count),
            p(3 * v.rays.count);
        std::vector<ObjectId> o(v.rays.count);
        std::vector<std::int32_t> prim(v.rays.count);
        py::gil_scoped_release release;
        const auto start = std::chrono::steady_clock::now();
        scene.intersect(v.rays,
                        HitColumns{t.data(), o.data(), prim.data(), p.data(), n.data(), uv.data()});
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      },
      py::arg("scene"), py::arg("rays"));
  m.def(
      "create_rays_pinhole",
      [](double fov_deg, const py::handle& center, const py::handle& eye, const py::handle& up,
         int width_px, int height_px) {
        return create_rays_pinhole(fov_deg, vec3(center, "center"), vec3(eye, "eye"),
                                   vec3(up, "up"), width_px, height_px);
      },
      py::arg("fov_deg"), py::arg("center"), py::arg("eye"), py::arg("up"), py::arg("width_px"),
      py::arg("height_px"),
      "Rays (height, width, 6) float32 of a pinhole camera at eye looking at center, the image "
      "upright (row 0 at the top, up pointing up); fov_deg is horizontal; directions have unit "
      "depth so t_hit is depth.");
}

}  // namespace raycast::python

#pragma once
// numpy arrays in and out of the public API (docs/python.md): checks with errors that name the
// expected shape and dtype, and zero-copy views where the layout allows.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "raycast/raycast.h"

namespace raycast::python {

namespace py = pybind11;

/// A (..., 6) float32/float64 array of rays viewed without copying when its leading axes
/// collapse to one stride; `keep` holds whatever array the view points into.
struct RayView {
  RayArray rays;
  std::vector<py::ssize_t> shape;  // the leading axes (the answers' shape)
  py::object keep;
};
/// Throws ValueError naming the expected shape and dtype.
RayView ray_view(const py::handle& rays, const char* what = "rays");

/// A (..., 3) array of points as contiguous float64 (a view when it already is one).
struct PointView {
  py::array_t<double, py::array::c_style> points;
  std::vector<py::ssize_t> shape;  // the leading axes
  std::size_t count = 0;
};
PointView point_view(const py::handle& points, const char* what = "points");

/// A new array shaped `lead` + `tail`.
template <class T>
py::array_t<T> make_array(const std::vector<py::ssize_t>& lead, std::vector<py::ssize_t> tail) {
  std::vector<py::ssize_t> shape = lead;
  shape.insert(shape.end(), tail.begin(), tail.end());
  return py::array_t<T>(shape);
}

/// Open3D's pinhole rays: (height, width, 6) float32, origin at eye, directions through pixel
/// centres scaled so that their component along the viewing axis is 1 (t_hit is then depth).
py::array_t<float> create_rays_pinhole(double fov_deg, const Vec3d& center, const Vec3d& eye,
                                       const Vec3d& up, int width, int height);

}  // namespace raycast::python

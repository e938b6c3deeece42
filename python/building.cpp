// Scene.load, Scene.from_yaml and the add_* calls of raycast.Scene for meshes, files, shapes
// and their combinations (docs/python.md "Building").
#include "bindings.h"

namespace raycast::python {

namespace {

template <class T>
ObjectId add_triangles(Scene& scene, const py::array& vertices, const py::array& triangles) {
  const auto v = py::array_t<T, py::array::c_style>::ensure(vertices);
  if (v.ndim() != 2 || v.shape(1) != 3)
    throw py::value_error("vertices must be a numpy array shaped (n, 3) of float32 or float64");
  const auto t =
      py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>::ensure(triangles);
  if (!t || t.ndim() != 2 || t.shape(1) != 3)
    throw py::value_error("triangles must be a numpy array shaped (m, 3) of integer indices");
  py::gil_scoped_release release;
  return scene.add_mesh(
      std::span<const T>(v.data(), static_cast<std::size_t>(v.size())),
      std::span<const std::uint32_t>(t.data(), static_cast<std::size_t>(t.size())));
}

ObjectId add_triangles_any(Scene& scene, const py::handle& vertices, const py::handle& triangles) {
  if (!py::isinstance<py::array>(vertices) || !py::isinstance<py::array>(triangles))
    throw py::value_error("vertices (n, 3) and triangles (m, 3) must be numpy arrays");
  const auto tri = py::reinterpret_borrow<py::array>(triangles);
  if (tri.dtype().kind() != 'i' && tri.dtype().kind() != 'u')
    throw py::value_error("triangles must be a numpy array shaped (m, 3) of integer indices, got " +
                          py::str(tri.dtype()).cast<std::string>());
  if (tri.size() > 0) {
    const auto wide = py::array_t<std::int64_t, py::array::forcecast>::ensure(tri);
    for (py::ssize_t i = 0; i < wide.size(); ++i)
      if (wide.data()[i] < 0 || wide.data()[i] > 0xFFFFFFFELL)
        throw py::value_error("triangles: index " + std::to_string(wide.data()[i]) +
                              " is out of range");
  }
  const auto v = py::reinterpret_borrow<py::array>(vertices);
  if (py::isinstance<py::array_t<float>>(v)) return add_triangles<float>(scene, v, tri);
  if (py::isinstance<py::array_t<double>>(v)) return add_triangles<double>(scene, v, tri);
  throw py::value_error("vertices must be a numpy array shaped (n, 3) of float32 or float64, got " +
                        py::str(v.dtype()).cast<std::string>());
}

std::vector<ObjectId> ids(const py::handle& h) { return h.cast<std::vector<ObjectId>>(); }

void bind_loading(py::class_<Scene>& scene) {
  scene
      .def_static(
          "load",
          [](const std::string& path) {
            require_file(path);
            return Scene::load(path);
          },
          py::arg("path"), "Loads and commits a scene file (YAML or JSON).")
      .def_static(
          "from_yaml",
          [](const std::string& text, const std::string& name) {
            return Scene::from_string(text, name);
          },
          py::arg("text"), py::arg("name") = "<string>",
          "Loads and commits a scene from YAML or JSON text.")
      .def("add_triangles", &add_triangles_any, py::arg("vertices"), py::arg("triangles"),
           "A triangle mesh from vertices (n, 3) and triangles (m, 3); returns its id.");
}

void bind_shapes(py::class_<Scene>& scene) {
  scene
      .def(
          "add_mesh_file",
          [](Scene& s, const std::string& path) {
            require_file(path);
            return s.add_mesh_file(path);
          },
          py::arg("path"))
      .def(
          "add_shape",
          [](Scene& s, const std::string& key, const py::object& fields) {
            const std::string text =
                py::isinstance<py::str>(fields)
                    ? fields.cast<std::string>()
                    : py::module_::import("json").attr("dumps")(fields).cast<std::string>();
            return s.add_shape(key, text);
          },
          py::arg("key"), py::arg("fields"),
          "Any shape of the scene format by key, with its fields as a dict or YAML text.")
      .def(
          "add_plane",
          [](Scene& s, const py::object& normal, const py::object& point) {
            return s.add_plane(vec3(normal, "normal"), vec3(point, "point"));
          },
          py::arg("normal"), py::arg("point") = py::make_tuple(0, 0, 0))
      .def(
          "add_sphere",
          [](Scene& s, const py::object& c, double r) {
            return s.add_sphere(vec3(c, "center"), r);
          },
          py::arg("center") = py::make_tuple(0, 0, 0), py::arg("radius") = 1.0)
      .def(
          "add_box",
          [](Scene& s, const py::object& lo, const py::object& hi) {
            return s.add_box(vec3(lo, "min"), vec3(hi, "max"));
          },
          py::arg("min"), py::arg("max"))
      .def(
          "add_triangle",
          [](Scene& s, const py::object& a, const py::object& b, const py::object& c) {
            return s.add_triangle(vec3(a, "a"), vec3(b, "b"), vec3(c, "c"));
          },
          py::arg("a"), py::arg("b"), py::arg("c"))
      .def(
          "add_disk",
          [](Scene& s, const py::object& c, const py::object& n, double r, double inner) {
            return s.add_disk(vec3(c, "center"), vec3(n, "normal"), r, inner);
          },
          py::arg("center"), py::arg("normal"), py::arg("radius"), py::arg("inner_radius") = 0.0)
      .def(
          "add_cylinder",
          [](Scene& s, const py::object& a, const py::object& b, double r, bool capped) {
            return s.add_cylinder(vec3(a, "from"), vec3(b, "to"), r, capped);
          },
          py::arg("start"), py::arg("end"), py::arg("radius"), py::arg("capped") = true)
      .def(
          "add_cone",
          [](Scene& s, const py::object& a, const py::object& b, double r0, double r1,
             bool capped) { return s.add_cone(vec3(a, "from"), vec3(b, "to"), r0, r1, capped); },
          py::arg("start"), py::arg("end"), py::arg("radius_start"), py::arg("radius_end") = 0.0,
          py::arg("capped") = true)
      .def(
          "add_ellipsoid",
          [](Scene& s, const py::object& c, const py::object& r) {
            return s.add_ellipsoid(vec3(c, "center"), vec3(r, "radii"));
          },
          py::arg("center"), py::arg("radii"))
      .def("add_torus", &Scene::add_torus, py::arg("major_radius"), py::arg("minor_radius"))
      .def(
          "add_quadric",
          [](Scene& s, const std::array<double, 10>& c, const py::object& lo,
             const py::object& hi) {
            return s.add_quadric(c, vec3(lo, "bounds_min"), vec3(hi, "bounds_max"));
          },
          py::arg("coefficients"), py::arg("bounds_min"), py::arg("bounds_max"))
      .def(
          "add_algebraic",
          [](Scene& s, const std::string& eq, const py::object& lo, const py::object& hi) {
            return s.add_algebraic(eq, vec3(lo, "bounds_min"), vec3(hi, "bounds_max"));
          },
          py::arg("equation"), py::arg("bounds_min"), py::arg("bounds_max"))
      .def(
          "add_implicit",
          [](Scene& s, const std::string& f, const py::object& lo, const py::object& hi) {
            return s.add_implicit(f, vec3(lo, "bounds_min"), vec3(hi, "bounds_max"));
          },
          py::arg("function"), py::arg("bounds_min"), py::arg("bounds_max"));
}

void bind_combinations(py::class_<Scene>& scene) {
  scene
      .def(
          "add_csg",
          [](Scene& s, const std::string& op, const py::object& operands) {
            CsgOp o = CsgOp::kUnion;
            if (op == "intersection")
              o = CsgOp::kIntersection;
            else if (op == "difference")
              o = CsgOp::kDifference;
            else if (op != "union")
              throw py::value_error("op must be union, intersection or difference, got " + op);
            const auto v = ids(operands);
            return s.add_csg(o, v);
          },
          py::arg("op"), py::arg("operands"))
      .def(
          "add_prototype",
          [](Scene& s, const py::object& objects) { return s.add_prototype(ids(objects)); },
          py::arg("objects"))
      .def(
          "add_instance",
          [](Scene& s, int proto, const py::object& xf) {
            return s.add_instance(proto, matrix4(xf, "transform"));
          },
          py::arg("prototype"), py::arg("transform"))
      .def(
          "set_transform",
          [](Scene& s, ObjectId id, const py::object& xf) {
            s.set_transform(id, matrix4(xf, "transform"));
          },
          py::arg("object"), py::arg("transform"));
}

}  // namespace

void bind_building(py::class_<Scene>& scene) {
  bind_loading(scene);
  bind_shapes(scene);
  bind_combinations(scene);
}

}  // namespace raycast::python

// The Python module `raycast` (docs/python.md): raycast::Scene for numpy, with Open3D's names
// for the batch queries. Every batch releases the GIL and runs on all cores.
#include <pybind11/stl.h>

#include <chrono>
#include <filesystem>
#include <limits>

#include "arrays.h"

namespace raycast::python {

void bind_explain(py::module_& m);  // explain_binding.cpp

namespace {

constexpr std::uint32_t kInvalidId = std::numeric_limits<std::uint32_t>::max();  // Open3D's

Vec3d vec3(const py::handle& h, const char* what) {
  try {
    const auto v = h.cast<std::vector<double>>();
    if (v.size() == 3) return {v[0], v[1], v[2]};
  } catch (const py::cast_error&) {
  }
  throw py::value_error(std::string(what) + " must be 3 numbers");
}

Transform matrix4(const py::handle& h, const char* what) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(h);
  if (!a || a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
    throw py::value_error(std::string(what) + " must be a 4x4 matrix (object to world)");
  Transform t;
  for (int i = 0; i < 16; ++i) t.m[i] = a.data()[i];
  return t;
}

std::vector<ObjectId> ids(const py::handle& h) { return h.cast<std::vector<ObjectId>>(); }

void require_file(const std::string& path) {
  if (!std::filesystem::exists(path)) {
    PyErr_SetString(PyExc_FileNotFoundError, ("no such file: '" + path + "'").c_str());
    throw py::error_already_set();
  }
}

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

py::dict cast_rays(const Scene& scene, const py::handle& rays) {
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

py::array_t<bool> test_occlusions(const Scene& scene, const py::handle& rays, double tnear,
                                  double tfar) {
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

py::array_t<std::int32_t> count_intersections(const Scene& scene, const py::handle& rays) {
  RayView v = ray_view(rays);
  auto out = make_array<std::int32_t>(v.shape, {});
  {
    py::gil_scoped_release release;
    scene.count_intersections(v.rays, {out.mutable_data(), v.rays.count});
  }
  return out;
}

py::dict list_intersections(const Scene& scene, const py::handle& rays) {
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

py::array_t<float> compute_occupancy(const Scene& scene, const py::handle& points) {
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

py::dict compute_closest_points(const Scene& scene, const py::handle& points) {
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

py::array_t<double> compute_distance(const Scene& scene, const py::handle& points) {
  PointView v = point_view(points);
  auto dist = make_array<double>(v.shape, {});
  {
    py::gil_scoped_release release;
    scene.closest_points({v.points.data(), 3 * v.count}, nullptr, nullptr, nullptr,
                         dist.mutable_data());
  }
  return dist;
}

py::array_t<double> compute_signed_distance(const Scene& scene, const py::handle& points) {
  PointView v = point_view(points);
  auto dist = make_array<double>(v.shape, {});
  {
    py::gil_scoped_release release;
    scene.signed_distance({v.points.data(), 3 * v.count}, {dist.mutable_data(), v.count});
  }
  return dist;
}

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
  if (v.dtype().is(py::dtype::of<float>())) return add_triangles<float>(scene, v, tri);
  if (v.dtype().is(py::dtype::of<double>())) return add_triangles<double>(scene, v, tri);
  throw py::value_error("vertices must be a numpy array shaped (n, 3) of float32 or float64, got " +
                        py::str(v.dtype()).cast<std::string>());
}

// add_isosurface: exactly one of `particles` ((n, 3) positions) or `grid` (a 3D array of node
// values indexed [i, j, k]), with the scene key's parameters (docs/python.md).
ObjectId add_isosurface(Scene& scene, const py::object& particles, const py::object& grid,
                        const py::object& iso, const py::object& smoothing_length,
                        double rest_density, const py::object& particle_volume,
                        const py::object& domain, const py::object& resolution,
                        const py::object& cell_size, const py::object& origin,
                        const py::object& spacing) {
  if (particles.is_none() == grid.is_none())
    throw py::value_error(
        "add_isosurface needs exactly one of particles= (n, 3) or grid= (a 3D "
        "array)");
  if (!grid.is_none()) {
    for (const auto& [name, value] : {std::pair{"smoothing_length", &smoothing_length},
                                      {"particle_volume", &particle_volume},
                                      {"domain", &domain},
                                      {"resolution", &resolution},
                                      {"cell_size", &cell_size}})
      if (!value->is_none())
        throw py::value_error(std::string("add_isosurface: ") + name +
                              " applies to particles only");
    if (iso.is_none()) throw py::value_error("add_isosurface: a grid needs iso=");
    if (!py::isinstance<py::array>(grid))
      throw py::value_error("grid must be a 3D numpy array of node values indexed [i, j, k]");
    // Fortran order puts i fastest, the engine's layout: no copy for float32 Fortran arrays.
    const auto g = py::array_t<float, py::array::f_style | py::array::forcecast>::ensure(grid);
    if (!g || g.ndim() != 3)
      throw py::value_error("grid must be a 3D numpy array of node values indexed [i, j, k]");
    GridSurface gs;
    for (int a = 0; a < 3; ++a) {
      if (g.shape(a) > 2000000000) throw py::value_error("grid: too many nodes on one axis");
      gs.counts[a] = static_cast<int>(g.shape(a));
    }
    if (!origin.is_none()) gs.origin = vec3(origin, "origin");
    if (!spacing.is_none()) gs.spacing = vec3(spacing, "spacing");
    gs.iso = iso.cast<double>();
    py::gil_scoped_release release;
    return scene.add_isosurface(
        std::span<const float>(g.data(), static_cast<std::size_t>(g.size())), gs);
  }
  if (!origin.is_none() || !spacing.is_none())
    throw py::value_error("add_isosurface: origin and spacing apply to grid only");
  const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(particles);
  if (!p || p.ndim() != 2 || p.shape(1) != 3)
    throw py::value_error("particles must be a numpy array shaped (n, 3) of positions");
  if (smoothing_length.is_none())
    throw py::value_error(
        "add_isosurface: particles need "
        "smoothing_length=");
  ParticleSurface ps;
  ps.smoothing_length = smoothing_length.cast<double>();
  ps.rest_density = rest_density;
  if (!particle_volume.is_none()) ps.particle_volume = particle_volume.cast<double>();
  if (!iso.is_none()) ps.iso = iso.cast<double>();
  if (!domain.is_none()) {
    const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(domain);
    if (!d || d.ndim() != 2 || d.shape(0) != 2 || d.shape(1) != 3)
      throw py::value_error("domain must be [[xmin, ymin, zmin], [xmax, ymax, zmax]]");
    ps.domain = std::array<Vec3d, 2>{Vec3d{d.at(0, 0), d.at(0, 1), d.at(0, 2)},
                                     Vec3d{d.at(1, 0), d.at(1, 1), d.at(1, 2)}};
  }
  if (!resolution.is_none()) {
    const auto r = resolution.cast<std::vector<long long>>();
    if (r.size() != 3) throw py::value_error("resolution must be [nx, ny, nz]");
    std::array<int, 3> n{};
    for (int a = 0; a < 3; ++a) {
      if (r[a] < 2 || r[a] > 2000000000)
        throw py::value_error("resolution must hold whole numbers >= 2");
      n[a] = static_cast<int>(r[a]);
    }
    ps.resolution = n;
  }
  if (!cell_size.is_none()) ps.cell_size = cell_size.cast<double>();
  py::gil_scoped_release release;
  return scene.add_isosurface(std::span<const double>(p.data(), static_cast<std::size_t>(p.size())),
                              ps);
}

Camera camera_from(const py::dict& d) {
  Camera c;
  for (const auto& [k, val] : d) {
    const std::string key = py::str(k);
    if (key == "position")
      c.position = vec3(val, "camera position");
    else if (key == "look_at")
      c.look_at = vec3(val, "camera look_at");
    else if (key == "up")
      c.up = vec3(val, "camera up");
    else if (key == "fov")
      c.fov = val.cast<double>();
    else if (key == "height")
      c.height = val.cast<double>();
    else if (key == "type")
      c.orthographic = val.cast<std::string>() == "orthographic";
    else
      throw py::value_error("unknown camera key '" + key +
                            "' (position, look_at, up, fov, height, type)");
  }
  return c;
}

}  // namespace

PYBIND11_MODULE(raycast, m) {
  m.doc() =
      "raycast: exact ray casting, distances and rendering over meshes, analytic shapes "
      "and CSG (docs/python.md)";
  m.attr("__version__") = RAYCAST_VERSION_STRING;
  m.attr("INVALID_ID") = kInvalidId;

  static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SceneError& e) {
      py::object err = py::reinterpret_borrow<py::object>(scene_error.ptr())(e.what());
      err.attr("file") = e.file();
      err.attr("line") = e.line();
      err.attr("column") = e.column();
      err.attr("message") = e.message();
      PyErr_SetObject(scene_error.ptr(), err.ptr());
    } catch (const NotImplementedError& e) {
      PyErr_SetString(PyExc_NotImplementedError, e.what());
    } catch (const std::logic_error& e) {
      if (dynamic_cast<const std::invalid_argument*>(&e) ||
          dynamic_cast<const std::out_of_range*>(&e))
        throw;
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });

  m.def(
      "_time_intersect",
      [](const Scene& scene, const py::handle& rays) {
        // The C++ batch path alone, on the caller's rays and preallocated outputs, for
        // python/bench_python.py's overhead figure.
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
  m.def("create_rays_pinhole", &create_rays_pinhole, py::arg("fov_deg"), py::arg("center"),
        py::arg("eye"), py::arg("up"), py::arg("width_px"), py::arg("height_px"),
        "Rays (height, width, 6) float32 of a pinhole camera at eye looking at center; "
        "fov_deg is horizontal.");

  py::class_<Scene>(m, "Scene", "A scene: build (add_*, commit) or load, then query.")
      .def(py::init<>())
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
           "A triangle mesh from vertices (n, 3) and triangles (m, 3); returns its id.")
      .def("add_isosurface", &add_isosurface, py::arg("particles") = py::none(), py::kw_only(),
           py::arg("grid") = py::none(), py::arg("iso") = py::none(),
           py::arg("smoothing_length") = py::none(), py::arg("rest_density") = 1000.0,
           py::arg("particle_volume") = py::none(), py::arg("domain") = py::none(),
           py::arg("resolution") = py::none(), py::arg("cell_size") = py::none(),
           py::arg("origin") = py::none(), py::arg("spacing") = py::none(),
           "An iso-surface (docs/iso-surfaces.md) of SPH particles (n, 3) splatted with the cubic "
           "spline kernel, or of a grid of node values indexed [i, j, k] at origin + (i, j, k) * "
           "spacing; the solid is where the field exceeds iso. Returns its id.")
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
          py::arg("function"), py::arg("bounds_min"), py::arg("bounds_max"))
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
          py::arg("object"), py::arg("transform"))
      .def(
          "add_material",
          [](Scene& s, const py::object& color, double ambient, double diffuse, double specular,
             double shininess, double reflection, double transmission, double ior) {
            Material mat;
            mat.color = vec3(color, "color");
            mat.ambient = ambient;
            mat.diffuse = diffuse;
            mat.specular = specular;
            mat.shininess = shininess;
            mat.reflection = reflection;
            mat.transmission = transmission;
            mat.ior = ior;
            return s.add_material(mat);
          },
          py::arg("color") = py::make_tuple(0.8, 0.8, 0.8), py::arg("ambient") = 1.0,
          py::arg("diffuse") = 0.8, py::arg("specular") = 0.0, py::arg("shininess") = 32.0,
          py::arg("reflection") = 0.0, py::arg("transmission") = 0.0, py::arg("ior") = 1.0)
      .def("set_material", &Scene::set_material, py::arg("object"), py::arg("material"))
      .def(
          "add_point_light",
          [](Scene& s, const py::object& position, const py::object& color, double intensity) {
            Light l;
            l.position = vec3(position, "position");
            l.color = vec3(color, "color");
            l.intensity = intensity;
            s.add_light(l);
          },
          py::arg("position"), py::arg("color") = py::make_tuple(1, 1, 1),
          py::arg("intensity") = 1.0)
      .def(
          "add_directional_light",
          [](Scene& s, const py::object& direction, const py::object& color, double intensity) {
            Light l;
            l.type = Light::Type::kDirectional;
            l.direction = vec3(direction, "direction");
            l.color = vec3(color, "color");
            l.intensity = intensity;
            s.add_light(l);
          },
          py::arg("direction"), py::arg("color") = py::make_tuple(1, 1, 1),
          py::arg("intensity") = 1.0)
      .def("set_camera", [](Scene& s, const py::kwargs& kw) { s.set_camera(camera_from(kw)); })
      .def("commit", &Scene::commit, py::call_guard<py::gil_scoped_release>(),
           "Builds the scene; afterwards it is immutable and thread-safe.")
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
      .def("compute_signed_distance", &compute_signed_distance, py::arg("query_points"))
      .def(
          "render",
          [](const Scene& s, int width, int height, int samples, const std::string& integrator,
             const py::object& camera) {
            RenderOptions o;
            o.width = width;
            o.height = height;
            o.samples = samples;
            o.integrator = integrator;
            Camera c;
            const bool has_camera = !camera.is_none();
            if (has_camera) c = camera_from(camera.cast<py::dict>());
            Image img;
            {
              py::gil_scoped_release release;
              img = s.render(has_camera ? &c : nullptr, o);
            }
            py::array_t<float> out({static_cast<py::ssize_t>(img.height),
                                    static_cast<py::ssize_t>(img.width), py::ssize_t{3}});
            std::copy(img.rgb.begin(), img.rgb.end(), out.mutable_data());
            return out;
          },
          py::arg("width") = 0, py::arg("height") = 0, py::arg("samples") = 0,
          py::arg("integrator") = "", py::arg("camera") = py::none(),
          "Renders into a (height, width, 3) float32 array of linear RGB.");
  bind_explain(m);
}

}  // namespace raycast::python

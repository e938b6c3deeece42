// Scene.add_isosurface: SPH particles or a grid of node values (docs/iso-surfaces.md).
#include "bindings.h"

namespace raycast::python {

namespace {

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

}  // namespace

void bind_isosurface(py::class_<Scene>& scene) {
  scene.def("add_isosurface", &add_isosurface, py::arg("particles") = py::none(), py::kw_only(),
            py::arg("grid") = py::none(), py::arg("iso") = py::none(),
            py::arg("smoothing_length") = py::none(), py::arg("rest_density") = 1000.0,
            py::arg("particle_volume") = py::none(), py::arg("domain") = py::none(),
            py::arg("resolution") = py::none(), py::arg("cell_size") = py::none(),
            py::arg("origin") = py::none(), py::arg("spacing") = py::none(),
            "An iso-surface (docs/iso-surfaces.md) of SPH particles (n, 3) splatted with the cubic "
            "spline kernel, or of a grid of node values indexed [i, j, k] at origin + (i, j, k) * "
            "spacing; the solid is where the field exceeds iso. Returns its id.");
}

}  // namespace raycast::python

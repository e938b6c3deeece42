// The `isosurface` shape: SPH particles splatted to a density grid, or a grid read from a file
// (docs/iso-surfaces.md).
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "load/frame_pattern.h"
#include "load/shape_parsers.h"
#include "volume/grid_file.h"
#include "volume/isosurface.h"
#include "volume/particle_file.h"
#include "volume/splat.h"
#include "volume/vdb_file.h"

namespace raycast {

namespace {

// The data file's path: the frame substituted, relative paths against the scene's folder.
std::string data_path(Fields& f, const std::string& key) {
  std::string name = f.string(key);
  try {
    name = expand_frame_pattern(name, f.ctx().frame < 0 ? 0 : f.ctx().frame);
  } catch (const std::invalid_argument& e) {
    f.fail(key, f.name(key) + ": " + e.what());
  }
  const std::filesystem::path p(name);
  const std::string path =
      p.is_absolute() ? name : (std::filesystem::path(f.ctx().dir) / p).string();
  if (f.ctx().files) f.ctx().files->push_back(path);
  return path;
}

SceneError as_scene_error(const VolumeFileError& e) {
  return SceneError(e.file(), e.line(), e.column(), e.message());
}

std::array<int, 3> read_resolution(Fields& f) {
  const YamlNode node = f.required("resolution");
  const std::vector<double> v = read_numbers(f.ctx(), node, f.name("resolution"));
  if (v.size() != 3) f.fail("resolution", f.name("resolution") + " must be [nx, ny, nz]");
  std::array<int, 3> r{};
  for (int a = 0; a < 3; ++a) {
    if (!(v[a] >= 2 && v[a] <= 2e9 && v[a] == std::floor(v[a])))
      fail_at(f.ctx(), node[a], f.name("resolution") + " must hold whole numbers >= 2");
    r[a] = int(v[a]);
  }
  return r;
}

ShapeVariant from_particles(Fields& f) {
  SplatParams p;
  p.h = f.positive("smoothing_length");
  p.rest_density = f.positive("rest_density", 1000);
  if (f.has("particle_volume")) p.particle_volume = f.positive("particle_volume");
  const double iso = f.non_negative("iso", p.rest_density / 2);
  if (f.has("domain")) {
    Fields d(f.ctx(), f.required("domain"), f.name("domain"));
    p.domain = Aabb{d.vec3("min"), d.vec3("max")};
    d.finish();
    if (!(p.domain->lo.x < p.domain->hi.x && p.domain->lo.y < p.domain->hi.y &&
          p.domain->lo.z < p.domain->hi.z))
      f.fail("domain", f.name("domain") + ".min must be < max on every axis");
  }
  if (f.has("resolution") && f.has("cell_size"))
    f.fail("cell_size", f.name("cell_size") + ": give either resolution or cell_size, not both");
  if (f.has("resolution")) p.resolution = read_resolution(f);
  if (f.has("cell_size")) p.cell_size = f.positive("cell_size");
  const std::string path = data_path(f, "particles");
  std::vector<Vec3> particles;
  try {
    particles = read_particles(path);
  } catch (const VolumeFileError& e) {
    throw as_scene_error(e);
  }
  ScalarGrid grid;
  try {
    grid = splat_particles(particles, p);
  } catch (const std::length_error& e) {
    f.fail(f.has("resolution") ? "resolution"
                               : (f.has("cell_size") ? "cell_size" : "smoothing_length"),
           f.name("particles") + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    f.fail("smoothing_length", f.name("particles") + ": " + e.what());
  }
  try {
    return make_isosurface(std::move(grid), iso);
  } catch (const std::invalid_argument& e) {
    f.fail("iso", f.name("iso") + ": " + e.what());
  }
}

ShapeVariant from_grid(Fields& f) {
  const double iso = f.number("iso");
  if (!(iso >= 0)) f.fail("iso", f.name("iso") + " must be >= 0, got " + std::to_string(iso));
  const std::string path = data_path(f, "grid");
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  ScalarGrid grid;
  if (ext == ".raw") {
    if (f.ctx().files) f.ctx().files->push_back(grid_sidecar_path(path));
    try {
      grid = read_raw_grid(path);
    } catch (const VolumeFileError& e) {
      throw as_scene_error(e);
    }
  } else if (ext == ".vdb") {
    const std::string name = f.has("name") ? f.string("name") : std::string();
    try {
      grid = read_vdb_grid(path, name);
    } catch (const VdbUnsupportedError& e) {
      f.fail("grid", f.name("grid") + ": " + e.what());
    } catch (const VolumeFileError& e) {
      throw as_scene_error(e);
    } catch (const VdbGridError& e) {
      f.fail(f.has("name") ? "name" : "grid",
             f.name(f.has("name") ? "name" : "grid") + ": " + e.what());
    } catch (const std::length_error& e) {
      f.fail("grid", f.name("grid") + ": " + e.what());
    }
  } else {
    f.fail("grid", f.name("grid") +
                       " must be a .raw file (with a .json sidecar) or a .vdb file, got '" + ext +
                       "'");
  }
  try {
    return make_isosurface(std::move(grid), iso);
  } catch (const std::invalid_argument& e) {
    f.fail("grid", f.name("grid") + ": " + e.what());
  }
}

}  // namespace

ShapeVariant parse_shape(std::type_identity<Isosurface>, Fields& f) {
  const bool particles = f.has("particles"), grid = f.has("grid");
  if (particles == grid)
    f.fail(particles ? "grid" : "iso",
           "isosurface needs exactly one of particles (a .ply/.csv/.xyz file) or grid (.raw/.vdb)");
  return particles ? from_particles(f) : from_grid(f);
}

}  // namespace raycast

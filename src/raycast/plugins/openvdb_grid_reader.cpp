// The OpenVDB plugin (volume/vdb_plugin_abi.h): the only code that links OpenVDB, loaded by
// volume/vdb_file.cpp the first time a scene reads a .vdb grid. It throws the core's own error
// types (header-only classes), which the core catches by name across the module boundary.
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>

#include <mutex>

#include "volume/vdb_file.h"
#include "volume/vdb_plugin_abi.h"
#include "volume/volume_error.h"

namespace raycast {
namespace {

ScalarGrid read_grid(const std::string& path, const std::string& name,
                     void (*check_fits)(const std::array<std::uint64_t, 3>&)) {
  static std::once_flag initialised;
  std::call_once(initialised, [] { openvdb::initialize(); });
  openvdb::GridBase::Ptr base;
  std::string names;
  try {
    openvdb::io::File file(path);
    file.open(false);  // no delayed loading: the file is read now, errors surface here
    std::string only;
    int floats = 0;
    for (auto it = file.beginName(); it != file.endName(); ++it) {
      names += (names.empty() ? "'" : ", '") + it.gridName() + "'";
      if (name.empty() && file.readGridMetadata(it.gridName())->isType<openvdb::FloatGrid>())
        only = it.gridName(), ++floats;
    }
    if (name.empty() && floats != 1)
      throw VdbGridError(path + " holds " + (floats ? "several float grids" : "no float grid") +
                         (names.empty() ? std::string() : " (grids: " + names + ")") +
                         (floats ? ": say which with name:" : ""));
    const std::string wanted = name.empty() ? only : name;
    if (!file.hasGrid(wanted))
      throw VdbGridError(
          path + " has no grid named '" + wanted + "'" +
          (names.empty() ? std::string(" (it holds no grids)") : " (grids: " + names + ")"));
    base = file.readGrid(wanted);
    file.close();
  } catch (const openvdb::Exception& e) {
    throw VolumeFileError(path, 1, 1, std::string("not a readable OpenVDB file: ") + e.what());
  }
  const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base);
  if (!grid)
    throw VdbGridError("grid '" + base->getName() + "' of " + path + " holds " + base->valueType() +
                       " values; an iso-surface needs a float grid");
  const openvdb::math::Transform& xf = grid->transform();
  if (!xf.isLinear())
    throw VdbGridError("grid '" + base->getName() + "' of " + path +
                       " has a non-linear (frustum) transform; only axis-aligned voxels are "
                       "supported");
  const openvdb::math::Mat4d m = xf.baseMap()->getAffineMap()->getMat4();
  bool axis_aligned = true;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) axis_aligned = axis_aligned && (r == c || m(r, c) == 0);
  if (!axis_aligned)
    throw VdbGridError("grid '" + base->getName() + "' of " + path +
                       " has a rotated or sheared transform; only axis-aligned "
                       "voxels are supported");
  openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
  if (box.empty())
    throw VdbGridError("grid '" + base->getName() + "' of " + path + " has no active voxels");
  box.expand(1);
  const openvdb::Coord dim = box.dim();
  check_fits({std::uint64_t(dim.x()), std::uint64_t(dim.y()), std::uint64_t(dim.z())});
  ScalarGrid out;
  out.n = {dim.x(), dim.y(), dim.z()};
  if (!(m(0, 0) > 0 && m(1, 1) > 0 && m(2, 2) > 0))
    throw VdbGridError("grid '" + base->getName() + "' of " + path +
                       " mirrors an axis; only positive voxel sizes are supported");
  const openvdb::Vec3d lo = xf.indexToWorld(box.min());
  out.lo = {lo.x(), lo.y(), lo.z()};
  out.cell = {m(0, 0), m(1, 1), m(2, 2)};
  out.v.resize(std::size_t(dim.x()) * std::size_t(dim.y()) * std::size_t(dim.z()));
  openvdb::tools::Dense<float, openvdb::tools::LayoutXYZ> dense(box, out.v.data());
  openvdb::tools::copyToDense(*grid, dense);
  return out;
}

const VdbPlugin kPlugin{kVdbPluginAbiVersion, read_grid};

}  // namespace
}  // namespace raycast

extern "C" __attribute__((visibility("default"))) const raycast::VdbPlugin*
raycast_openvdb_plugin() {
  return &raycast::kPlugin;
}

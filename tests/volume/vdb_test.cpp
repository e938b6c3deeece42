// OpenVDB float grids as iso-surface input: a .vdb written here through the OpenVDB API loads as
// the same surface as a .raw grid of the same values, and every problem with the grid asked for
// is an error at the scene's `name` (or `grid`) field.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../support/cli_runner.h"
#include "io/scene_error.h"
#include "load/loader.h"
#include "volume/vdb_file.h"

#if RAYCAST_HAVE_OPENVDB
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#endif

namespace raycast {
namespace {

#if RAYCAST_HAVE_OPENVDB

constexpr double kVoxel = 0.125;          // binary fractions: the .raw sidecar's node positions
const openvdb::Vec3d kShift(1, -0.5, 2);  // come out exactly where the .vdb's are

// The field of a blob: 1 - r^2 / 4 voxels^2 in (positive part), at voxel centres.
float blob(int i, int j, int k) {
  const double r2 = (i - 2) * (i - 2) + (j + 1) * (j + 1) + 0.5 * k * k;
  return r2 < 16 ? static_cast<float>(1 - r2 / 16) : 0.f;
}

openvdb::FloatGrid::Ptr blob_grid(const std::string& name) {
  openvdb::initialize();
  auto grid = openvdb::FloatGrid::create(0.f);
  grid->setName(name);
  auto xf = openvdb::math::Transform::createLinearTransform(kVoxel);
  xf->postTranslate(kShift);
  grid->setTransform(xf);
  auto acc = grid->getAccessor();
  for (int k = -8; k <= 8; ++k)
    for (int j = -8; j <= 8; ++j)
      for (int i = -8; i <= 8; ++i)
        if (blob(i, j, k) > 0) acc.setValue(openvdb::Coord(i, j, k), blob(i, j, k));
  return grid;
}

void write_vdb(const std::string& file, openvdb::GridPtrVec grids) {
  openvdb::io::File f((test::temp_dir() / file).string());
  f.write(grids);
  f.close();
}

// The same values as a .raw grid over the active box grown by one voxel.
void write_raw_twin(const openvdb::FloatGrid& g) {
  openvdb::CoordBBox box = g.evalActiveVoxelBoundingBox();
  box.expand(1);
  std::string raw;
  for (int k = box.min().z(); k <= box.max().z(); ++k)
    for (int j = box.min().y(); j <= box.max().y(); ++j)
      for (int i = box.min().x(); i <= box.max().x(); ++i) {
        const float v = g.tree().getValue(openvdb::Coord(i, j, k));
        raw.append(reinterpret_cast<const char*>(&v), sizeof v);
      }
  test::write("twin.raw", raw);
  const openvdb::Vec3d lo = g.transform().indexToWorld(box.min());
  const openvdb::Vec3d hi = g.transform().indexToWorld(box.max());
  const openvdb::Coord n = box.dim();
  auto v3 = [](const openvdb::Vec3d& v) {
    return "[" + std::to_string(v.x()) + ", " + std::to_string(v.y()) + ", " +
           std::to_string(v.z()) + "]";
  };
  test::write("twin.json", "{\"dims\": [" + std::to_string(n.x()) + ", " + std::to_string(n.y()) +
                               ", " + std::to_string(n.z()) + "], \"min\": " + v3(lo) +
                               ", \"max\": " + v3(hi) + "}");
}

Scene load(const std::string& shape) {
  return load_scene_text("objects:\n  - isosurface: " + shape + "\n", "t.yaml",
                         test::temp_dir().string());
}

SceneError load_error(const std::string& shape) {
  try {
    load(shape);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << shape;
  return SceneError("", 0, 0, "");
}

TEST(VdbGrid, FloatGrid_LoadsAsTheSameSurfaceAsItsRawTwin) {
  const auto grid = blob_grid("density");
  write_vdb("blob.vdb", {grid});
  write_raw_twin(*grid);
  const Scene vdb = load("{grid: blob.vdb, name: density, iso: 0.5}");
  const Scene only = load("{grid: blob.vdb, iso: 0.5}");  // its only float grid
  const Scene raw = load("{grid: twin.raw, iso: 0.5}");
  int hits = 0;
  for (int a = -6; a <= 6; ++a)
    for (int b = -6; b <= 6; ++b) {
      const Vec3 target(1.25 + 0.05 * a, -0.625 + 0.05 * b, 2 + 0.03 * (a + b));
      const Ray ray{{-3, 1, -1}, target - Vec3(-3, 1, -1)};
      SceneHit h1, h2, h3;
      const bool hit = raw.intersect(ray, h1);
      ASSERT_EQ(vdb.intersect(ray, h2), hit);
      ASSERT_EQ(only.intersect(ray, h3), hit);
      if (!hit) continue;
      ++hits;
      EXPECT_EQ(h1.local.t, h2.local.t);
      EXPECT_EQ(h1.local.t, h3.local.t);
    }
  EXPECT_GT(hits, 40);
}

TEST(VdbGrid, MissingName_IsAnErrorAtTheNameFieldListingTheGrids) {
  write_vdb("two.vdb", {blob_grid("density"), blob_grid("temperature")});
  const SceneError e = load_error("{grid: two.vdb, name: dnesity, iso: 0.5}");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.column(), 39);  // the value of name:
  EXPECT_NE(e.message().find("no grid named 'dnesity'"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("'density', 'temperature'"), std::string::npos) << e.what();
  const SceneError which = load_error("{grid: two.vdb, iso: 0.5}");
  EXPECT_NE(which.message().find("several float grids"), std::string::npos) << which.what();
}

TEST(VdbGrid, NonFloatGrid_IsAnErrorNamingItsType) {
  auto ints = openvdb::Int32Grid::create(0);
  ints->setName("labels");
  ints->tree().setValue(openvdb::Coord(0, 0, 0), 3);
  write_vdb("ints.vdb", {ints});
  const SceneError e = load_error("{grid: ints.vdb, name: labels, iso: 0.5}");
  EXPECT_NE(e.message().find("holds int32 values"), std::string::npos) << e.what();
  const SceneError none = load_error("{grid: ints.vdb, iso: 0.5}");
  EXPECT_NE(none.message().find("no float grid"), std::string::npos) << none.what();
}

TEST(VdbGrid, RotatedOrEmptyGrid_IsAnError) {
  auto g = blob_grid("density");
  auto xf = openvdb::math::Transform::createLinearTransform(kVoxel);
  xf->postRotate(0.3, openvdb::math::Y_AXIS);
  g->setTransform(xf);
  write_vdb("rotated.vdb", {g});
  EXPECT_NE(load_error("{grid: rotated.vdb, iso: 0.5}").message().find("rotated"),
            std::string::npos);
  auto empty = openvdb::FloatGrid::create(0.f);
  empty->setName("nothing");
  write_vdb("empty.vdb", {empty});
  EXPECT_NE(load_error("{grid: empty.vdb, iso: 0.5}").message().find("no active voxels"),
            std::string::npos);
}

TEST(VdbGrid, SparseGridTooLargeWhenDense_IsRefusedWithTheBytesNeeded) {
  auto g = openvdb::FloatGrid::create(0.f);
  g->setName("far");
  g->tree().setValue(openvdb::Coord(0, 0, 0), 1.f);
  g->tree().setValue(openvdb::Coord(3000000, 3000000, 3000), 1.f);  // 2.7e16 nodes when dense
  write_vdb("far.vdb", {g});
  const SceneError e = load_error("{grid: far.vdb, iso: 0.5}");
  EXPECT_NE(e.message().find("needs"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("bytes"), std::string::npos) << e.what();
}

TEST(VdbGrid, NotAVdbFile_IsAnErrorNamingTheFile) {
  test::write("junk.vdb", "this is not an OpenVDB file\n");
  const SceneError e = load_error("{grid: junk.vdb, iso: 0.5}");
  EXPECT_NE(e.file().find("junk.vdb"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("OpenVDB"), std::string::npos) << e.what();
}

#else

TEST(VdbGrid, WithoutOpenVdb_TheFormatSaysSo) {
  EXPECT_FALSE(vdb_supported());
  GTEST_SKIP() << "built without OpenVDB (RAYCAST_OPENVDB=OFF)";
}

#endif

}  // namespace
}  // namespace raycast

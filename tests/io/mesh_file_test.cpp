// Mesh files through the scene loader: every format on small files written here, and broken files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "io/mesh_file.h"
#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast {
namespace {

namespace fs = std::filesystem;

class MeshFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("raycast_mesh_files_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& bytes) {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
  }
  Scene load(const std::string& yaml) { return load_scene_text(yaml, "scene.yaml", dir_.string()); }
  Scene load_file(const std::string& name, bool smooth = false) {
    return load("objects:\n  - mesh: {file: " + name + (smooth ? ", smooth: true" : "") + "}\n");
  }
  // Expects a SceneError at line 2, column `col` mentioning `words`.
  void expect_error(const std::string& name, const std::string& words) {
    try {
      load("objects:\n  - mesh: {file: " + name + "}\n");
      FAIL() << "no error for " << name;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.line(), 2) << e.what();
      EXPECT_EQ(e.column(), 18) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
  static const Mesh& mesh_of(const Scene& s, std::size_t i = 0) {
    return *std::get<MeshShape>(s.objects.at(i).shape).mesh;
  }
  static void expect_unit_triangle_hit(const Scene& s) {
    SceneHit h;
    ASSERT_TRUE(s.intersect(Ray{{0.25, 0.25, 1}, {0, 0, -1}}, h));
    EXPECT_DOUBLE_EQ(h.local.t, 1);
    EXPECT_EQ(h.local.prim, 0);
  }

  fs::path dir_;
};

// glTF is read through assimp: skipped by a build without it (OBJ, PLY and STL are our own).
#define SKIP_WITHOUT_ASSIMP() \
  if (!mesh_format_supported(".gltf")) GTEST_SKIP() << "built without assimp"

std::string binary_ply(const std::vector<float>& xyz,
                       const std::vector<std::vector<std::int32_t>>& faces, std::size_t cut = 0) {
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(xyz.size() / 3) +
      "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
      std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  s.append(reinterpret_cast<const char*>(xyz.data()), xyz.size() * 4);
  for (const auto& f : faces) {
    s.push_back(static_cast<char>(f.size()));
    s.append(reinterpret_cast<const char*>(f.data()), f.size() * 4);
  }
  if (cut) s.resize(s.size() - cut);
  return s;
}

std::string base64(const std::string& in) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < in.size(); i += 3) {
    std::uint32_t v = static_cast<std::uint8_t>(in[i]) << 16;
    if (i + 1 < in.size()) v |= static_cast<std::uint8_t>(in[i + 1]) << 8;
    if (i + 2 < in.size()) v |= static_cast<std::uint8_t>(in[i + 2]);
    out += k[v >> 18 & 63];
    out += k[v >> 12 & 63];
    out += i + 1 < in.size() ? k[v >> 6 & 63] : '=';
    out += i + 2 < in.size() ? k[v & 63] : '=';
  }
  return out;
}

TEST_F(MeshFiles, Obj_LoadsTrianglesAndQuads) {
  write(
      "a.obj",
      "# a triangle and a quad\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 -1\nv 1 0 -1\nv 1 1 -1\nv 0 1 -1\n"
      "f 1 2 3\nf 4 5 6 7\n");
  const Scene s = load_file("a.obj");
  EXPECT_EQ(mesh_of(s).triangle_count(), 3u);
  expect_unit_triangle_hit(s);
}

TEST_F(MeshFiles, PlyAscii_Loads) {
  write("a.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
        "float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 "
        "0\n3 0 1 2\n");
  const Scene s = load_file("a.ply");
  EXPECT_EQ(mesh_of(s).triangle_count(), 1u);
  expect_unit_triangle_hit(s);
}

TEST_F(MeshFiles, PlyBinary_LoadsWithOurReader) {
  write("b.ply", binary_ply({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, {{0, 1, 2}, {1, 3, 2}}));
  const MeshFileData d = load_mesh_file((dir_ / "b.ply").string());
  EXPECT_EQ(d.soup.positions.size(), 4u);
  ASSERT_EQ(d.soup.triangles.size(), 2u);
  EXPECT_EQ(d.soup.triangles[1][0], 1u);
  const Scene s = load_file("b.ply");
  EXPECT_EQ(mesh_of(s).triangle_count(), 2u);
  expect_unit_triangle_hit(s);
}

TEST_F(MeshFiles, Stl_Loads) {
  write(
      "a.stl",
      "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
      "endfacet\nendsolid t\n");
  const Scene s = load_file("a.stl");
  EXPECT_EQ(mesh_of(s).triangle_count(), 1u);
  expect_unit_triangle_hit(s);
}

TEST_F(MeshFiles, Gltf_LoadsEmbeddedBuffer) {
  SKIP_WITHOUT_ASSIMP();
  std::string buffer;
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::uint16_t idx[4] = {0, 1, 2, 0};
  buffer.append(reinterpret_cast<const char*>(p), sizeof p);
  buffer.append(reinterpret_cast<const char*>(idx), sizeof idx);
  write(
      "a.gltf",
      R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,)" +
          base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})");
  const Scene s = load_file("a.gltf");
  EXPECT_EQ(mesh_of(s).triangle_count(), 1u);
  expect_unit_triangle_hit(s);
}

TEST_F(MeshFiles, ClosedObjCube_IsClosedAndSmoothGetsNormals) {
  write("cube.obj",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\n"
        "f 4 1 5\nf 4 5 8\n");
  const Scene s = load_file("cube.obj", true);
  const Mesh& m = mesh_of(s);
  EXPECT_TRUE(m.closed());
  EXPECT_EQ(m.normals.size(), m.positions.size());
}

TEST_F(MeshFiles, InlineMesh_Loads) {
  const Scene s = load(
      "objects:\n  - mesh:\n      vertices: [[0,0,0],[1,0,0],[0,1,0]]\n      triangles: "
      "[[0,1,2]]\n");
  expect_unit_triangle_hit(s);
}

TEST_F(MeshFiles, InlineMesh_BadIndex_IsPositioned) {
  try {
    load(
        "objects:\n  - mesh:\n      vertices: [[0,0,0],[1,0,0],[0,1,0]]\n      triangles: "
        "[[0,1,3]]\n");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 4) << e.what();
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
  }
  try {
    load(
        "objects:\n  - mesh:\n      vertices: [[0,0,0],[1,0,0],[0,1,0]]\n      triangles: "
        "[[0,1,-2]]\n");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 4) << e.what();
  }
}

TEST_F(MeshFiles, Missing_IsPositionedError) { expect_error("nope.ply", "not found"); }

TEST_F(MeshFiles, UnsupportedExtension_IsPositionedError) {
  write("a.xyz", "1 2 3\n");
  expect_error("a.xyz", "unsupported");
}

TEST_F(MeshFiles, TruncatedBinaryPly_IsPositionedError) {
  write("t.ply", binary_ply({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}}, 5));
  expect_error("t.ply", "truncated");
  write("h.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\n");
  expect_error("h.ply", "truncated");
  write("c.ply",
        "ply\nformat binary_little_endian 1.0\nelement vertex 18446744073709551615\nproperty float "
        "x\n"
        "property float y\nproperty float z\nend_header\n");
  expect_error("c.ply", "truncated");
}

TEST_F(MeshFiles, OutOfRangeIndex_IsPositionedError) {
  write("r.ply", binary_ply({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 7}}));
  expect_error("r.ply", "out of range");
  write("r.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  expect_error("r.obj", "r.obj:4:7: vertex index 9 names no vertex");
}

TEST_F(MeshFiles, NaNVertex_IsPositionedError) {
  const float nan = std::nanf("");
  write("n.ply", binary_ply({0, 0, 0, 1, nan, 0, 0, 1, 0}, {{0, 1, 2}}));
  expect_error("n.ply", "not finite");
}

// Garbage in each assimp format: a positioned error, never a crash.
// assimp 5.2 leaks about 2 KB inside libassimp.so on some failed imports (LeakSanitizer shows only
// its frames); not ours to fix, so the sanitizer build skips these cases.
#if defined(__SANITIZE_ADDRESS__)
#define SKIP_WHERE_ASSIMP_LEAKS() GTEST_SKIP() << "assimp leaks on failed imports"
#else
#define SKIP_WHERE_ASSIMP_LEAKS() (void)0
#endif
TEST_F(MeshFiles, GarbageObj_IsPositionedError) {
  write("g.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
  expect_error("g.obj", "g.obj:4:6: a face needs at least 3 corners");
}

TEST_F(MeshFiles, TruncatedStl_IsPositionedError) {
  write("g.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n");
  expect_error("g.stl", "g.stl:4:1: expected 'vertex x y z'");
}

TEST_F(MeshFiles, TruncatedGltf_IsPositionedError) {
  SKIP_WITHOUT_ASSIMP();
  SKIP_WHERE_ASSIMP_LEAKS();
  write("g.gltf", "{\"asset\": ");
  expect_error("g.gltf", "cannot read");
}

TEST_F(MeshFiles, FileAndVertices_IsAnError) {
  write("b.ply", binary_ply({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}}));
  EXPECT_THROW(load("objects:\n  - mesh: {file: b.ply, vertices: [[0,0,0]]}\n"), SceneError);
}

}  // namespace
}  // namespace raycast

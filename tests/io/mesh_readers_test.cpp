// Our OBJ, STL and PLY (ASCII, both binary byte orders) readers: a random mesh written by the
// test in every format reads back as the same triangles (by corner positions), and broken files
// get errors naming file:line:column.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "io/mesh_file.h"

namespace raycast {
namespace {

namespace fs = std::filesystem;

struct Soup {
  std::vector<std::array<float, 3>> v;
  std::vector<std::vector<std::uint32_t>> faces;  // polygons of 3 to 6 corners
};

Soup random_soup(unsigned seed, int nv, int nf) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> x(-1e3f, 1e3f);
  std::uniform_int_distribution<int> corners(3, 6);
  Soup s;
  for (int i = 0; i < nv; ++i) s.v.push_back({x(rng), x(rng), x(rng)});
  std::uniform_int_distribution<std::uint32_t> vi(0, static_cast<std::uint32_t>(nv - 1));
  for (int f = 0; f < nf; ++f) {
    std::vector<std::uint32_t> face;
    const int n = corners(rng);
    for (int k = 0; k < n; ++k) face.push_back(vi(rng));
    s.faces.push_back(face);
  }
  return s;
}

// The triangles a fan of every face makes, as corner positions (what any reader must return,
// whatever it does with vertex numbering).
using Tri = std::array<std::array<float, 3>, 3>;
std::vector<Tri> fan(const Soup& s) {
  std::vector<Tri> out;
  for (const auto& f : s.faces)
    for (std::size_t k = 2; k < f.size(); ++k) out.push_back({s.v[f[0]], s.v[f[k - 1]], s.v[f[k]]});
  return out;
}
std::vector<Tri> triangles_of(const MeshFileData& d) {
  std::vector<Tri> out;
  for (const auto& t : d.soup.triangles) {
    Tri r;
    for (int k = 0; k < 3; ++k) {
      const Vec3f& p = d.soup.positions.at(t[k]);
      r[k] = {p.x, p.y, p.z};
    }
    out.push_back(r);
  }
  return out;
}

// Shortest decimal text that reads back as the same float.
std::string num(float f) {
  std::ostringstream o;
  o.precision(9);
  o << f;
  return o.str();
}

template <class T>
void put(std::string& s, T v, bool big = false) {
  char b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  if (big) std::reverse(b, b + sizeof v);
  s.append(b, sizeof v);
}

std::string as_obj(const Soup& s, bool negative) {
  std::ostringstream o;
  o << "# random\no thing\n";
  for (const auto& p : s.v) o << "v " << num(p[0]) << " " << num(p[1]) << " " << num(p[2]) << "\n";
  o << "vt 0 0\nusemtl none\n";
  const long n = static_cast<long>(s.v.size());
  for (const auto& f : s.faces) {
    o << "f";
    for (const std::uint32_t i : f) {
      o << " " << (negative ? static_cast<long>(i) - n : static_cast<long>(i) + 1);
      if (negative) o << "/1";
    }
    o << "\n";
  }
  return o.str();
}

std::string as_ply(const Soup& s, const std::string& format) {
  std::string o = "ply\nformat " + format +
                  " 1.0\ncomment end_header is not here\nelement vertex " +
                  std::to_string(s.v.size()) +
                  "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
                  "element face " +
                  std::to_string(s.faces.size()) +
                  "\nproperty list uchar int vertex_indices\nproperty list uchar float "
                  "texcoord\nend_header\n";
  const bool big = format == "binary_big_endian";
  for (const auto& p : s.v) {
    if (format == "ascii") {
      o += num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + " 255\n";
    } else {
      for (float c : p) put(o, c, big);
      put(o, std::uint8_t(255));
    }
  }
  for (const auto& f : s.faces) {
    if (format == "ascii") {
      std::ostringstream row;
      row << f.size();
      for (const std::uint32_t i : f) row << " " << i;
      o += row.str() + " 2 0.5 0.5\n";
    } else {
      put(o, static_cast<std::uint8_t>(f.size()));
      for (const std::uint32_t i : f) put(o, static_cast<std::int32_t>(i), big);
      put(o, std::uint8_t(2));
      put(o, 0.5f, big);
      put(o, 0.5f, big);
    }
  }
  return o;
}

std::string as_stl(const std::vector<Tri>& tris, bool binary) {
  std::string o;
  if (binary) {
    o = std::string("solid but binary") + std::string(64, ' ');
    put(o, static_cast<std::uint32_t>(tris.size()));
    for (const Tri& t : tris) {
      for (int k = 0; k < 3; ++k) put(o, 0.0f);
      for (const auto& p : t)
        for (float c : p) put(o, c);
      put(o, std::uint16_t(0));
    }
    return o;
  }
  o = "solid test\n";
  for (const Tri& t : tris) {
    o += "  facet normal 0 0 1\n    outer loop\n";
    for (const auto& p : t)
      o += "      vertex " + num(p[0]) + " " + num(p[1]) + " " + num(p[2]) + "\n";
    o += "    endloop\n  endfacet\n";
  }
  return o + "endsolid test\n";
}

class MeshReaders : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("raycast_mesh_readers_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  void expect_error(const std::string& name, const std::string& bytes, const std::string& words) {
    const std::string path = write(name, bytes);
    try {
      load_mesh_file(path);
      FAIL() << "no error for " << name << ", expected '" << words << "'";
    } catch (const MeshFileError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
  fs::path dir_;
};

TEST_F(MeshReaders, EveryFormat_ReadsTheSameTriangles) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Soup s = random_soup(seed, 200, 300);
    const std::vector<Tri> want = fan(s);
    const std::pair<std::string, std::string> files[] = {
        {"a.obj", as_obj(s, false)},
        {"b.obj", as_obj(s, true)},
        {"a.ply", as_ply(s, "ascii")},
        {"b.ply", as_ply(s, "binary_little_endian")},
        {"c.ply", as_ply(s, "binary_big_endian")},
        {"a.stl", as_stl(want, false)},
        {"b.stl", as_stl(want, true)},
    };
    for (const auto& [name, bytes] : files) {
      SCOPED_TRACE(name + " seed " + std::to_string(seed));
      const MeshFileData d = load_mesh_file(write(name, bytes));
      EXPECT_EQ(triangles_of(d), want);
      EXPECT_TRUE(d.normals.empty());
    }
  }
}

TEST_F(MeshReaders, Stl_WeldsCornersAtTheSamePosition) {
  const Soup s = random_soup(7, 50, 80);
  for (const bool binary : {false, true}) {
    const MeshFileData d =
        load_mesh_file(write(binary ? "w.stl" : "v.stl", as_stl(fan(s), binary)));
    std::size_t used = 0;
    std::vector<bool> seen(s.v.size());
    for (const auto& f : s.faces)
      for (const std::uint32_t i : f) used += !seen[i], seen[i] = true;
    EXPECT_EQ(d.soup.positions.size(), used);
  }
}

TEST_F(MeshReaders, Obj_NormalsWhenEveryCornerHasOne) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 2\nvn 0 0 1\n"
      "f 1//1 2//1 3//2\nf 2/1/2 4/1/2 3/1/1\n";
  const MeshFileData d = load_mesh_file(write("n.obj", obj));
  ASSERT_EQ(d.normals.size(), 4u);
  for (const Vec3f& n : d.normals) EXPECT_EQ(n, (Vec3f{0, 0, 1}));
  // One corner without a normal: none are used (make_mesh computes them).
  const MeshFileData e =
      load_mesh_file(write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3\n"));
  EXPECT_TRUE(e.normals.empty());
}

TEST_F(MeshReaders, Ply_NormalsAndDoubles) {
  std::string s =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty "
      "double z\nproperty float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
      "property list uchar uint vertex_index\nend_header\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n"
      "3 0 1 2\n";
  const MeshFileData d = load_mesh_file(write("n.ply", s));
  ASSERT_EQ(d.normals.size(), 3u);
  EXPECT_EQ(d.soup.triangles.size(), 1u);
}

TEST_F(MeshReaders, Obj_Errors_AreLineAndColumn) {
  expect_error("e1.obj", "v 0 0 0\nv 1 x 0\n", "e1.obj:2:5: expected a finite number, got 'x'");
  expect_error("e0.obj", "v 0 0 inf\n", "e0.obj:1:7: expected a finite number, got 'inf'");
  expect_error("e2.obj", "v 0 0\n", "e2.obj:1:6: a vertex needs x y z");
  expect_error("e3.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n",
               "e3.obj:4:7: expected a vertex index");
  expect_error("e4.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n",
               "e4.obj:4:7: vertex index -4 names no vertex");
  expect_error("e5.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n",
               "e5.obj:4:3: normal index 1 names no normal");
  expect_error("e6.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3.5\n",
               "e6.obj:4:7: expected a vertex index");
}

TEST_F(MeshReaders, Stl_Errors_AreLineAndColumn) {
  expect_error("e1.stl",
               "solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n",
               "e1.stl:6:1: a facet needs 3 vertices, got 2");
  expect_error("e2.stl",
               "solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
               "endloop\nendfacet\n",
               "no endsolid");
  expect_error("e3.stl", "solid\nvertex 0 0 0\n", "e3.stl:2:1: a vertex outside 'outer loop'");
  expect_error("e4.stl", "solid\nouter loop\nvertex 0 nan? 0\n",
               "e4.stl:3:10: expected a finite number");
  expect_error("e5.stl", "garbage", "neither a binary STL");
  expect_error("e6.stl", "", "neither a binary STL");
  std::string binary(84, '\0');
  put(binary, std::uint32_t(1000));
  binary.resize(80);
  put(binary, std::uint32_t(1000));  // 1000 facets promised, none there
  expect_error("e7.stl", binary, "neither a binary STL");
}

TEST_F(MeshReaders, Ply_Errors_AreLineAndColumn) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float "
      "z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  expect_error("e1.ply", head + "0 0 0\n1 0\n", "e1.ply:11:4: the row ends before its z value");
  expect_error("e2.ply", head + "0 0 0\n1 0 q\n",
               "e2.ply:11:5: z must be a finite number, got 'q'");
  expect_error("e3.ply", head + "0 0 0\n1 0 0\n", "truncated PLY file");
  expect_error("e4.ply", head + "0 0 0\n1 0 0\n3 0 1 1.5\n",
               "e4.ply:12:7: a vertex index must be a whole number");
  expect_error("e5.ply", head + "0 0 0\n1 0 0\n3 0 1 1 7\n", "e5.ply:12:9: more values than");
  expect_error("e6.ply", head + "0 0 0\n1 0 0\n-3 0 1 1\n", "e6.ply:12:1: bad list count");
  expect_error("e7.ply",
               "ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nend_header\n",
               "truncated PLY file");
  expect_error("e8.ply",
               "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\n"
               "property float y\nproperty float z\nend_header\n\x01\x02",
               "truncated PLY file");
  expect_error("e9.ply", "ply\nformat ascii 1.0\nelement face 0\nend_header\n",
               "e9.ply:2:1: the PLY file has no vertex element");
}

}  // namespace
}  // namespace raycast

// The binary PLY reader (memory map, parallel fast paths for packed float vertices and
// all-triangle faces, serial general path) on files written here: both paths give the same mesh,
// and bad input is refused with a MeshFileError before anything large is allocated.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "io/mesh_file.h"
#include "mesh/mesh.h"

namespace raycast {
namespace {

namespace fs = std::filesystem;

class PlyReader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("raycast_ply_reader_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  void expect_error(const std::string& bytes, const std::string& words) {
    const std::string path = write("bad.ply", bytes);
    try {
      load_mesh_file(path);
      FAIL() << "no error, expected '" << words << "'";
    } catch (const MeshFileError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
  fs::path dir_;
};

template <class T>
void put(std::string& s, T v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

// A PLY with float x y z (plus an extra property when `extra`), faces as uchar-count int lists.
std::string ply(const std::vector<float>& xyz, const std::vector<std::vector<std::int32_t>>& faces,
                bool extra = false, const std::string& count_override = "") {
  const std::size_t nv = xyz.size() / 3;
  std::string s = "ply\nformat binary_little_endian 1.0\ncomment made by a test\nelement vertex " +
                  std::to_string(nv) + "\nproperty float x\nproperty float y\nproperty float z\n" +
                  (extra ? "property uchar red\n" : "") + "element face " +
                  (count_override.empty() ? std::to_string(faces.size()) : count_override) +
                  "\nproperty list uchar int vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < nv; ++i) {
    for (int k = 0; k < 3; ++k) put(s, xyz[3 * i + k]);
    if (extra) put(s, std::uint8_t(7));
  }
  for (const auto& f : faces) {
    put(s, static_cast<std::uint8_t>(f.size()));
    for (std::int32_t v : f) put(s, v);
  }
  return s;
}

struct RandomMesh {
  std::vector<float> xyz;
  std::vector<std::vector<std::int32_t>> faces;
};

RandomMesh random_mesh(std::uint32_t seed, std::size_t nv, std::size_t nf, bool quads) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-5, 5);
  std::uniform_int_distribution<std::int32_t> idx(0, static_cast<std::int32_t>(nv) - 1);
  RandomMesh m;
  for (std::size_t i = 0; i < 3 * nv; ++i) m.xyz.push_back(u(rng));
  for (std::size_t i = 0; i < nf; ++i) {
    const int n = quads && i % 7 == 3 ? 4 : 3;
    std::vector<std::int32_t> f;
    for (int k = 0; k < n; ++k) f.push_back(idx(rng));
    m.faces.push_back(f);
  }
  return m;
}

// The triangles a fan of each face gives, in order.
std::vector<std::array<std::uint32_t, 3>> fans(const RandomMesh& m) {
  std::vector<std::array<std::uint32_t, 3>> out;
  for (const auto& f : m.faces)
    for (std::size_t k = 2; k < f.size(); ++k)
      out.push_back({std::uint32_t(f[0]), std::uint32_t(f[k - 1]), std::uint32_t(f[k])});
  return out;
}

TEST_F(PlyReader, AllTriangles_FastPathMatchesFile) {
  // Large enough for several parallel slabs of rows.
  const RandomMesh m = random_mesh(1, 5000, 1'100'000, false);
  const MeshFileData d = load_mesh_file(write("t.ply", ply(m.xyz, m.faces)));
  ASSERT_EQ(d.soup.positions.size(), 5000u);
  for (std::size_t i = 0; i < 5000; ++i) {
    EXPECT_EQ(d.soup.positions[i].x, m.xyz[3 * i]);
    EXPECT_EQ(d.soup.positions[i].z, m.xyz[3 * i + 2]);
  }
  EXPECT_EQ(d.soup.triangles, fans(m));
}

TEST_F(PlyReader, SomeQuads_GeneralPathFansThem) {
  const RandomMesh m = random_mesh(2, 300, 5000, true);
  const MeshFileData d = load_mesh_file(write("q.ply", ply(m.xyz, m.faces, true)));
  EXPECT_EQ(d.soup.triangles, fans(m));
  ASSERT_EQ(d.soup.positions.size(), 300u);
  EXPECT_EQ(d.soup.positions[299].y, m.xyz[3 * 299 + 1]);  // the extra vertex property skipped
}

TEST_F(PlyReader, DoubleCoordinatesAndNormals_Converted) {
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double "
      "y\nproperty double z\nproperty float nx\nproperty float ny\nproperty float nz\nelement face "
      "1\nproperty list uchar uint vertex_indices\nend_header\n";
  const double p[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 0.1, 0}};
  for (const auto& v : p) {
    for (double c : v) put(s, c);
    for (float n : {0.0f, 0.0f, 1.0f}) put(s, n);
  }
  put(s, std::uint8_t(3));
  for (std::uint32_t i : {0u, 1u, 2u}) put(s, i);
  const MeshFileData d = load_mesh_file(write("d.ply", s));
  ASSERT_EQ(d.soup.positions.size(), 3u);
  EXPECT_EQ(d.soup.positions[2].y, 0.1f);
  ASSERT_EQ(d.normals.size(), 3u);
  EXPECT_EQ(d.normals[1].z, 1.0f);
  EXPECT_EQ(d.soup.triangles.size(), 1u);
}

TEST_F(PlyReader, NegativeIndex_BecomesOutOfRange) {
  const MeshFileData d =
      load_mesh_file(write("n.ply", ply({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, -1, 2}})));
  ASSERT_EQ(d.soup.triangles.size(), 1u);
  EXPECT_EQ(d.soup.triangles[0][1], 0xFFFFFFFFu);
  EXPECT_THROW(make_mesh(d.soup.positions, d.soup.triangles), std::invalid_argument);
}

TEST_F(PlyReader, NaNVertex_ReadAsIsAndRefusedByMakeMesh) {
  const float nan = std::nanf("");
  const MeshFileData d =
      load_mesh_file(write("nan.ply", ply({0, 0, 0, nan, 0, 0, 0, 1, 0}, {{0, 1, 2}})));
  EXPECT_TRUE(std::isnan(d.soup.positions[1].x));
  EXPECT_THROW(make_mesh(d.soup.positions, d.soup.triangles), std::invalid_argument);
}

TEST_F(PlyReader, TruncatedFaces_Refused) {
  const RandomMesh m = random_mesh(3, 100, 1000, false);
  std::string s = ply(m.xyz, m.faces);
  s.resize(s.size() - 7);  // the last row cut: the fast path declines, the general path refuses
  expect_error(s, "truncated");
}

TEST_F(PlyReader, TruncatedVertices_Refused) {
  std::string s = ply({0, 0, 0, 1, 0, 0, 0, 1, 0}, {});
  s.resize(s.size() - 2);
  expect_error(s, "truncated");
}

TEST_F(PlyReader, HugeCounts_RefusedBeforeAllocating) {
  // 10^15 faces in a file of a few hundred bytes: refused from the header, not after trying to
  // allocate petabytes.
  expect_error(ply({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}}, false, "1000000000000000"),
               "truncated");
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4294967296000\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  expect_error(s, "truncated");
}

TEST_F(PlyReader, BadFaceCount_Refused) {
  // A row whose count is not 3 in the middle of triangles sends the reader to the general path,
  // which refuses a count that cannot be.
  std::string s =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float "
      "y\nproperty float z\nelement face 2\nproperty list int int vertex_indices\nend_header\n";
  for (int i = 0; i < 9; ++i) put(s, 0.5f * i);
  put(s, std::int32_t(3));
  for (std::int32_t i : {0, 1, 2}) put(s, i);
  put(s, std::int32_t(-5));
  expect_error(s, "bad vertex count");
}

TEST_F(PlyReader, BadHeaders_Refused) {
  expect_error("ply\nformat binary_little_endian 1.0\nelement vertex 3\n",
               "bad.ply:3:1: truncated PLY header (no end_header line)");
  expect_error("plx\nformat binary_little_endian 1.0\nend_header\n", "bad.ply:1:1: not a PLY file");
  expect_error("ply\nformat binary_little_endian 1.0\nelement vertex x\nend_header\n",
               "bad.ply:3:16: element count must be a whole number");
  expect_error("ply\nformat binary_little_endian 1.0\nproperty float x\nend_header\n",
               "bad.ply:3:1: a property before any element");
  expect_error(
      "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float q\nend_header\n"
      "0123",
      "the PLY vertex element has no x, y, z properties");
  expect_error("", "bad.ply:1:1: not a PLY file");
}

// Found by mesh_fuzz: assimp 5.2 never returned on an ASCII PLY whose header has no end_header
// line (here `element face 1 0` swallowed it); every header is now read line by line first.
TEST_F(PlyReader, HeaderWithoutEndHeaderOrWithStrayTokens_RefusedBeforeAnyReader) {
  expect_error(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
      "float z\nelement face 1 0\n3 0 1 2\n",
      "bad.ply:7:1: expected 'element NAME COUNT'");
  expect_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n0 0 0\n1 0 0\n",
               "bad.ply:5:1: unexpected PLY header line starting with '0'");
  expect_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x", "no end_header line");
  expect_error(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nelement face 1 0\nend_header\n",
      "bad.ply:5:1: expected 'element NAME COUNT'");
  expect_error("ply\nformat ascii 1.0\nelemnt vertex 3\nend_header\n",
               "bad.ply:3:1: unexpected PLY header line starting with 'elemnt'");
  expect_error("ply\nformat binary_middle_endian 1.0\nend_header\n",
               "bad.ply:2:8: unknown PLY format 'binary_middle_endian'");
}

// The PLY format ends the header at an `end_header` line, not at those letters anywhere: a
// comment that mentions end_header is still a comment.
TEST_F(PlyReader, EndHeaderInsideAComment_IsNotTheEndOfTheHeader) {
  std::string s =
      "ply\nformat binary_little_endian 1.0\ncomment written before end_header was known\n"
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 9; ++i) put(s, (i == 3 || i == 7) ? 1.0f : 0.0f);
  put(s, std::uint8_t(3));
  for (std::int32_t i : {0, 1, 2}) put(s, i);
  const MeshFileData m = load_mesh_file(write("comment.ply", s));
  EXPECT_EQ(m.soup.positions.size(), 3u);
  EXPECT_EQ(m.soup.triangles.size(), 1u);
}

}  // namespace
}  // namespace raycast

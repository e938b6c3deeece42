// Particle and grid readers: every format read back, every bad input a positioned error.
#include <gtest/gtest.h>

#include <cstring>

#include "../support/cli_runner.h"
#include "volume/grid_file.h"
#include "volume/particle_file.h"

namespace raycast {
namespace {

using test::write;

std::string bytes_of(const void* p, std::size_t n) {
  return std::string(static_cast<const char*>(p), n);
}

// Expects read(path) to throw VolumeFileError at line:column whose message contains `what`.
template <class Read>
void expect_error(Read&& read, const std::string& path, int line, int column,
                  const std::string& what) {
  try {
    read(path);
    ADD_FAILURE() << path << ": no error";
  } catch (const VolumeFileError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(e.message().find(what), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
  }
}

void expect_particle_error(const std::string& name, const std::string& text, int line, int column,
                           const std::string& what) {
  expect_error(read_particles, write(name, text), line, column, what);
}

const std::vector<Vec3> kThree = {{1, 2, 3}, {-0.5, 0.25, 1e-3}, {4, 5, 6}};

TEST(ParticleFile, TextFormats_Read) {
  EXPECT_EQ(read_particles(write("a.xyz", "1 2 3\n-0.5 0.25 1e-3\n\n4\t5 6\n")), kThree);
  EXPECT_EQ(read_particles(write("b.xyz", "x y z\n1 2 3\n-0.5 0.25 1e-3\n4 5 6")), kThree);
  EXPECT_EQ(read_particles(write("c.csv", "1,2,3\r\n-0.5, 0.25 ,1e-3\r\n4,5,6\r\n")), kThree);
  // A header naming the columns picks them.
  EXPECT_EQ(
      read_particles(write("d.csv", "id,z,y,x,vx\n0,3,2,1,9\n1,1e-3,0.25,-0.5,9\n2,6,5,4,9\n")),
      kThree);
}

TEST(ParticleFile, PlyAsciiAndBinary_Read) {
  EXPECT_EQ(
      read_particles(write("a.ply",
                           "ply\nformat ascii 1.0\ncomment hi\nelement vertex 3\n"
                           "property float x\nproperty float y\nproperty double z\n"
                           "property uchar red\nend_header\n1 2 3 0\n-0.5 0.25 1e-3 7\n4 5 6 1\n")),
      kThree);
  // Binary little endian: float x, double y, float z, and a face element after the vertices.
  std::string le =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property double y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  std::string be = le;
  be.replace(be.find("binary_little_endian"), 20, "binary_big_endian");
  for (const Vec3& p : kThree) {
    const float x = float(p.x), z = float(p.z);
    const double y = p.y;
    le += bytes_of(&x, 4) + bytes_of(&y, 8) + bytes_of(&z, 4);
    std::string bx = bytes_of(&x, 4), by = bytes_of(&y, 8), bz = bytes_of(&z, 4);
    std::reverse(bx.begin(), bx.end());
    std::reverse(by.begin(), by.end());
    std::reverse(bz.begin(), bz.end());
    be += bx + by + bz;
  }
  const std::vector<Vec3> got = read_particles(write("le.ply", le));
  ASSERT_EQ(got.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(got[i].x, double(float(kThree[i].x)));
    EXPECT_EQ(got[i].y, kThree[i].y);
  }
  EXPECT_EQ(read_particles(write("be.ply", be)), got);
  // Binary with a list element before the vertices.
  std::string pre =
      "ply\nformat binary_little_endian 1.0\nelement extra 1\n"
      "property list uchar int idx\nelement vertex 1\nproperty double x\n"
      "property double y\nproperty double z\nend_header\n";
  const unsigned char two = 2;
  const int idx[2] = {7, 8};
  const double xyz[3] = {1.5, 2.5, 3.5};
  pre += bytes_of(&two, 1) + bytes_of(idx, 8) + bytes_of(xyz, 24);
  EXPECT_EQ(read_particles(write("pre.ply", pre)), (std::vector<Vec3>{{1.5, 2.5, 3.5}}));
}

TEST(ParticleFile, BadText_PositionedErrors) {
  expect_particle_error("e1.xyz", "1 2 3\n4 5\n", 2, 4, "expected 3 values");
  expect_particle_error("e2.xyz", "1 2 3\n4 abc 6\n", 2, 3, "y must be a number");
  expect_particle_error("e3.csv", "1,2,3\n4,5,nan\n", 2, 5, "z must be finite");
  expect_particle_error("e4.csv", "1,2,3\n4,5,1e999\n", 2, 5, "z must be a number");
  expect_particle_error("e5.xyz", "", 1, 1, "no particles");
  expect_particle_error("e6.xyz", "x y z\n", 1, 1, "no particles");
  expect_particle_error("e7.txt", "1 2 3\n", 1, 1, "unknown particle format");
  expect_error(read_particles, test::temp_dir().string() + "/missing.xyz", 1, 1, "cannot open");
}

TEST(ParticleFile, BadPly_PositionedErrors) {
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  expect_particle_error("p1.ply", "plx\n", 1, 1, "not a PLY file");
  expect_particle_error("p2.ply", "ply\nformat ascii 1.0\nelement vertex 2\n", 3, 1,
                        "no end_header");
  expect_particle_error("p3.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", 2, 8,
                        "unknown PLY format");
  expect_particle_error("p4.ply", "ply\nformat ascii 1.0\nelement vertex -2\nend_header\n", 3, 16,
                        "whole number");
  expect_particle_error("p5.ply",
                        "ply\nformat ascii 1.0\nelement vertex 1\nproperty flot x\nend_header\n", 4,
                        10, "unknown PLY type");
  expect_particle_error(
      "p6.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n", 3, 1,
      "no x, y and z");
  expect_particle_error("p7.ply", "ply\nformat ascii 1.0\nelement face 1\nend_header\n", 2, 1,
                        "no vertex element");
  expect_particle_error("p8.ply", head + "1 2 3\n", 9, 1, "truncated");
  expect_particle_error("p9.ply", head + "1 2 3\n4 5\n", 9, 4, "expected 3 vertex values");
  expect_particle_error("p10.ply", head + "1 2 3\n4 inf 6\n", 9, 3, "y must be finite");
  expect_particle_error("p11.ply", "ply\nelement vertex 1\nend_header\n", 2, 1, "no format line");
  expect_particle_error("p12.ply", "ply\nformat ascii 1.0\nfoo\nend_header\n", 3, 1, "unexpected");
  // Binary: truncated data and NaN, at the line after the header.
  const std::string bin =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n"
      "property float x\nproperty float y\nproperty float z\nend_header\n";
  expect_particle_error("b1.ply", bin + "abcdefghijkl", 8, 1, "truncated PLY file");
  const float nan3[3] = {1, std::nanf(""), 2};
  std::string one = bin;
  one.replace(one.find("1000000000"), 10, "1");
  expect_particle_error("b2.ply", one + bytes_of(nan3, 12), 8, 1, "not finite");
}

void expect_grid_error(const std::string& json, const std::string& raw, const std::string& file,
                       int line, int column, const std::string& what) {
  static int n = 0;
  std::string base(1, 'g');
  base += std::to_string(n++);
  write(base + ".json", json);
  const std::string path = write(base + ".raw", raw);
  try {
    read_raw_grid(path);
    ADD_FAILURE() << json << ": no error";
  } catch (const VolumeFileError& e) {
    EXPECT_NE(e.file().find(base + file), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(e.message().find(what), std::string::npos) << e.what();
  }
}

TEST(GridFile, RawWithSidecar_Read) {
  std::vector<float> v(2 * 3 * 4);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(i) * 0.5f;
  write("ok.json",
        R"({"dims": [2, 3, 4], "min": [0, -1, 2], "max": [1, 1, 5], "type": "float32"})");
  const ScalarGrid g = read_raw_grid(write("ok.raw", bytes_of(v.data(), v.size() * 4)));
  EXPECT_EQ(g.n, (std::array<int, 3>{2, 3, 4}));
  EXPECT_EQ(g.lo, (Vec3{0, -1, 2}));
  EXPECT_EQ(g.cell, (Vec3{1, 1, 1}));
  EXPECT_EQ(g.v, v);
  EXPECT_EQ(g.at(1, 2, 3), 11.5f);
}

TEST(GridFile, BadInput_PositionedErrors) {
  const std::string ok8(8 * 4, '\0');
  expect_grid_error("{\"dims\": [2, 2, 2], \"min\": [0, 0, 0], \"max\": [1, 1, 1]", ok8, ".json", 1,
                    1, "not valid JSON");
  expect_grid_error("{\"dims\": [2, 2, 2],\n \"min\": [0, 0, 0]}", ok8, ".json", 1, 1,
                    "needs \"max\"");
  expect_grid_error("{\"dims\": [2, 1, 2], \"min\": [0, 0, 0], \"max\": [1, 1, 1]}", ok8, ".json",
                    1, 14, "whole numbers >= 2");
  expect_grid_error("{\"dims\": [2, 2, 2], \"min\": [0, 0, 0], \"max\": [1, 0, 1]}", ok8, ".json",
                    1, 50, "must exceed");
  expect_grid_error(
      "{\"dims\": [2, 2, 2], \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"type\": \"uint8\"}", ok8,
      ".json", 1, 65, "float32");
  expect_grid_error("{\"dims\": [2, 2, 2], \"min\": [0, 0, 0], \"max\": [1, 1, 1], \"spacing\": 1}",
                    ok8, ".json", 1, 57, "unknown key");
  expect_grid_error("{\"dims\": [2, 2, 2], \"min\": [0, \"a\", 0], \"max\": [1, 1, 1]}", ok8,
                    ".json", 1, 32, "finite numbers");
  expect_grid_error("{\"dims\": [2, 2, 2], \"min\": [0, 0, 0], \"max\": [1, 1, 1]}", ok8 + "x",
                    ".raw", 1, 1, "expected 32 bytes");
  std::string nan = ok8;
  const float f = std::nanf("");
  std::memcpy(&nan[12], &f, 4);
  expect_grid_error("{\"dims\": [2, 2, 2], \"min\": [0, 0, 0], \"max\": [1, 1, 1]}", nan, ".raw", 1,
                    1, "node (1, 1, 0)");
  // Too large for memory: refused before reading (the raw file is tiny), with the bytes needed.
  expect_grid_error("{\"dims\": [100000, 100000, 100000], \"min\": [0, 0, 0], \"max\": [1, 1, 1]}",
                    ok8, ".json", 1, 10, "needs 4");
  expect_error(read_raw_grid, test::temp_dir().string() + "/none.raw", 1, 1, "sidecar");
}

}  // namespace
}  // namespace raycast

// `mpirun -np 2 raycast ...` against the same command in one process, byte for byte: frames,
// tiles (fixed samples, adaptive antialiasing, AOVs) and ray batches (nearest, any, all); and
// failing ranks, which must end the job with a non-zero exit code that names the rank, never a
// hang (every run is under `timeout`). Skipped when raycast was built without RAYCAST_MPI.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "../support/cli_runner.h"

namespace raycast::test {
namespace {

const std::string kMpiexec = RAYCAST_MPIEXEC;  // empty without RAYCAST_MPI

/// A hang fails the test: timeout exits with 124 after this many seconds.
constexpr int kTimeout = 60;

std::string quote(const std::string& s) { return "'" + s + "'"; }

/// `mpirun` with 2 processes (or an MPMD line after "-np 1 ..."), on one machine whatever its
/// core count, as root where CI runs as root. ASan: leak checking is off in the MPI processes,
/// because OpenMPI 4.1 itself leaks in MPI_Init/MPI_Finalize (docs/distributed.md, "Testing").
Outcome mpirun(const std::string& tail) {
  const std::string launcher = "timeout -k 5 " + std::to_string(kTimeout) + " " + quote(kMpiexec) +
                               " --oversubscribe" + (geteuid() == 0 ? " --allow-run-as-root" : "");
  const char* asan = std::getenv("ASAN_OPTIONS");
  // Containers often forbid the cross-memory attach that OpenMPI's shared-memory transport uses
  // for large messages; plain copies work everywhere.
  const std::string env = std::string("ASAN_OPTIONS=") + (asan ? asan : "") +
                          ":detect_leaks=0 OMPI_MCA_btl_vader_single_copy_mechanism=none ";
  // Not run(), which starts the raycast binary itself: `VAR=... timeout ... mpirun ...` here.
  const fs::path dir = temp_dir();
  const std::string out = (dir / "stdout").string(), err = (dir / "stderr").string();
  const std::string cmd = env + launcher + " " + tail + " >" + quote(out) + " 2>" + quote(err);
  const int status = std::system(cmd.c_str());
  Outcome r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read(out);
  r.err = read(err);
  EXPECT_NE(r.code, 124) << "the MPI job hung (killed after " << kTimeout << " s)\n" << r.err;
  return r;
}

/// `mpirun -np 2 raycast ARGS`.
Outcome mpirun2(const std::string& args) {
  return mpirun("-np 2 " + quote(RAYCAST_BINARY) + " " + args);
}

#define SKIP_WITHOUT_MPI() \
  if (kMpiexec.empty()) GTEST_SKIP() << "raycast was built without RAYCAST_MPI"

std::string path(const std::string& name) { return (temp_dir() / name).string(); }

TEST(Mpi, Tiles_SameBytesAsOneProcess_WithAdaptiveAntialiasingAndAovs) {
  SKIP_WITHOUT_MPI();
  // 150 x 70: too few 64-pixel tiles for 2 ranks, so 16-pixel ones, 10 x 5, ragged at the right
  // and bottom.
  const std::string args = " --width 150 --height 70 --antialias 2,0.05,2 --aov depth,id";
  ASSERT_EQ(run("render -o " + quote(path("one.exr")) + args).code, 0);
  const Outcome r = mpirun2("render -o " + quote(path("two.exr")) + args);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* ext : {".exr", ".depth.pfm", ".id.pfm"}) {
    const std::string one = read(path(std::string("one") + ext));
    EXPECT_FALSE(one.empty()) << ext;
    EXPECT_TRUE(one == read(path(std::string("two") + ext))) << ext << " differs";
  }
  EXPECT_NE(r.err.find("100% (50 of 50 tiles)"), std::string::npos) << r.err;  // rank 0's progress
  EXPECT_NE(r.err.find("2 ranks"), std::string::npos) << r.err;
}

TEST(Mpi, Tiles_SameBytesAsOneProcess_FixedSamplesPng) {
  SKIP_WITHOUT_MPI();
  const std::string fixed = " --width 100 --height 80 --spp 3";
  ASSERT_EQ(run("render -o " + quote(path("one.png")) + fixed).code, 0);
  ASSERT_EQ(mpirun2("render -o " + quote(path("two.png")) + fixed).code, 0);
  EXPECT_TRUE(read(path("one.png")) == read(path("two.png")));
}

/// A scene over per-frame particle files p_0000.xyz .. p_0005.xyz with frame `missing` absent.
std::string frame_scene(int missing) {
  for (int f = 0; f <= 5; ++f) {
    const std::string name = "p_000" + std::to_string(f) + ".xyz";
    std::error_code ec;
    fs::remove(temp_dir() / name, ec);
    if (f != missing) write(name, "0 0 0\n0." + std::to_string(f) + " 0.1 0\n");
  }
  return write("frames.yaml",
               "camera: {type: perspective, position: [0, 0, -4], look_at: [0, 0, 0], up: [0, 1, "
               "0], fov: 40}\nimage: {width: 20, height: 14, samples: 2}\nobjects:\n  - "
               "isosurface: {particles: 'p_{frame:04d}.xyz', smoothing_length: 1}\n");
}

TEST(Mpi, Frames_SameBytesAsOneProcess) {
  SKIP_WITHOUT_MPI();
  const std::string scene = frame_scene(-1);
  ASSERT_EQ(run("render " + quote(scene) + " --frames 0-5 -o " + quote(path("a_{frame}.png"))).code,
            0);
  const Outcome r =
      mpirun2("render " + quote(scene) + " --frames 0-5 -o " + quote(path("b_{frame}.png")));
  ASSERT_EQ(r.code, 0) << r.err;
  for (int f = 0; f <= 5; ++f) {
    const std::string one = read(path("a_" + std::to_string(f) + ".png"));
    EXPECT_FALSE(one.empty());
    EXPECT_TRUE(one == read(path("b_" + std::to_string(f) + ".png"))) << "frame " << f;
  }
  EXPECT_NE(r.err.find("6 of 6 frames rendered on 2 ranks"), std::string::npos) << r.err;
}

TEST(Mpi, FrameFails_NonZeroExitNamesRankFrameAndFile_OtherFramesWritten) {
  SKIP_WITHOUT_MPI();
  const std::string scene = frame_scene(4);
  const Outcome r =
      mpirun2("render " + quote(scene) + " --frames 0-5 -o " + quote(path("c_{frame}.png")));
  EXPECT_NE(r.code, 0);
  // "raycast render: rank R: frame 4 (k/6) failed: .../p_0004.xyz:1:1: cannot open the file"
  const auto at = r.err.find(": frame 4 (");
  ASSERT_NE(at, std::string::npos) << r.err;
  const std::string line = r.err.substr(r.err.rfind('\n', at) + 1);
  EXPECT_EQ(line.find("raycast render: rank "), 0u) << line;
  EXPECT_NE(line.find("p_0004.xyz"), std::string::npos) << line;
  EXPECT_NE(r.err.find("5 of 6 frames rendered on 2 ranks"), std::string::npos) << r.err;
  EXPECT_FALSE(read(path("c_5.png")).empty());
}

TEST(Mpi, RankCannotLoadTheScene_NonZeroExitNamesTheRank) {
  SKIP_WITHOUT_MPI();
  // MPMD: rank 0 gets a good scene, rank 1 a missing one.
  const std::string good = write("good.yaml",
                                 "image: {width: 8, height: 8}\nobjects:\n  - "
                                 "sphere: {center: [0, 0, 5], radius: 1}\n");
  const std::string out = quote(path("never.png"));
  const Outcome r = mpirun("-np 1 " + quote(RAYCAST_BINARY) + " render " + quote(good) + " -o " +
                           out + " : -np 1 " + quote(RAYCAST_BINARY) + " render " +
                           quote(path("missing.yaml")) + " -o " + out);
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("raycast render: rank 1: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("missing.yaml: cannot open the scene file"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("rank 0:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("never.png")));
}

/// n binary rays (8 float64 each) from a fixed pseudo-random sequence, aimed around the origin.
std::string binary_rays(int n) {
  std::vector<double> v;
  unsigned s = 12345;
  auto next = [&] {
    return double(s = s * 1103515245u + 12345u) / double(1u << 31) - 1;
  };  // [-1, 1)
  for (int i = 0; i < n; ++i) {
    const double o[3] = {3 * next(), 3 * next(), -4}, target[3] = {next(), next(), next()};
    v.insert(v.end(), {o[0], o[1], o[2], target[0] - o[0], target[1] - o[1], target[2] - o[2], 0,
                       std::numeric_limits<double>::infinity()});
  }
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
}

class MpiRayBatch : public ::testing::TestWithParam<std::string> {};

TEST_P(MpiRayBatch, SameBytesAsOneProcess) {
  SKIP_WITHOUT_MPI();
  const std::string mode = GetParam();
  const std::string scene = std::string(RAYCAST_SOURCE_DIR) + "/scenes/csg.yaml";
  const std::string rays = write("rays" + mode + ".bin", binary_rays(1001));  // odd: unequal slices
  const std::string one = path("one" + mode + ".bin"), two = path("two" + mode + ".bin");
  write("two" + mode + ".bin", std::string(100000, 'x'));  // longer than the answers: cut
  const std::string args = "cast " + quote(scene) + " --binary --rays " + quote(rays) + " " + mode;
  ASSERT_EQ(run(args + " -o " + quote(one)).code, 0);
  const Outcome r = mpirun2(args + " -o " + quote(two));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("1001 rays answered on 2 ranks"), std::string::npos) << r.err;
  const std::string expected = read(one);
  EXPECT_GE(expected.size(), 1001u * 8);
  EXPECT_TRUE(expected == read(two)) << "the answers differ";
}

INSTANTIATE_TEST_SUITE_P(EveryMode, MpiRayBatch, ::testing::Values("", "--any", "--all"),
                         [](const auto& info) {
                           return info.param.empty() ? std::string("nearest")
                                                     : info.param.substr(2);
                         });

TEST(Mpi, RayBatchTruncated_TheLastRankNamesTheRecord) {
  SKIP_WITHOUT_MPI();
  const std::string scene = std::string(RAYCAST_SOURCE_DIR) + "/scenes/sphere.yaml";
  const std::string rays = write("cut.bin", binary_rays(10) + std::string(10, '\0'));
  const Outcome r = mpirun2("cast " + quote(scene) + " --binary --rays " + quote(rays) + " -o " +
                            quote(path("cut_out.bin")));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("raycast cast: rank 1: " + rays +
                       ": ray 11: truncated record (10 of 64 "
                       "bytes)"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace raycast::test

#pragma once
// `raycast bench`: deterministic ray sets traced by raycast and, side by side in the same process,
// by Embree 3 when the build has it (docs/cli.md).
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace raycast {

enum class BenchRays { kPrimary, kIncoherent, kShadow };

struct BenchOptions {
  std::string scene;       // a scene file, or
  std::string mesh_file;   // a mesh file, or
  std::string procedural;  // NAME:TRIANGLES (sphere, forest)
  BenchRays rays = BenchRays::kPrimary;
  bool vs_embree = false;
  bool packets = false;  // primary rays in packets of 8 (rows of 8 pixels); Embree: rtcIntersect8
  int packet_width = 8;  // 8 or 16 (16: rtcIntersect16; raycast's 16-lane kernel with AVX-512)
  int threads = 0;       // 0: all cores
  int repeat = 3;        // tracing passes; the fastest counts
  int width = 1024;      // primary rays: width x height pinhole camera
  int height = 1024;
  MeshBvhConfig bvh;  // for --mesh and --procedural (tuning: leaf size, bins, traversal cost)
};

/// One benchmark ray, in double (Embree gets it rounded to float).
struct BenchRay {
  Vec3 o, d;
  double tmin = 0, tmax = kInfinity;
};

struct BenchResult {
  std::string what;      // the mesh or scene
  std::string ray_kind;  // primary, incoherent, shadow
  bool packets = false;
  int packet_width = 0;  // 8 or 16 with packets
  std::uint64_t triangles = 0;
  std::uint64_t rays = 0;
  std::uint64_t hits = 0;
  int threads = 0;
  double raycast_build_ms = 0, raycast_mrays = 0, raycast_bytes_per_tri = 0,
         raycast_total_bytes_per_tri = 0;
  bool embree = false;
  double embree_build_ms = 0, embree_mrays = 0, embree_bytes_per_tri = 0;
  // CPU time of the process (all threads) during the builds: steadier than wall time on a
  // shared machine.
  double raycast_build_cpu_ms = 0, embree_build_cpu_ms = 0;
  double ratio = 0;
  double raycast_mrays_cpu = 0, embree_mrays_cpu = 0;  // rays per CPU second (all threads)
  std::uint64_t disagree = 0, disagree_hit = 0, disagree_t = 0, disagree_prim = 0;
};

/// Parses "primary", "incoherent" or "shadow"; throws SceneError otherwise.
BenchRays parse_bench_rays(const std::string& s);

/// Runs the benchmark. Throws SceneError for bad input (files, names) and when --vs embree is
/// asked of a build without Embree.
BenchResult run_bench(const BenchOptions& options);

/// The result as text lines, or as one JSON object.
std::string format_bench(const BenchResult& r, bool json);

/// Deterministic ray sets (the same whatever the thread count). Primary: a width x height
/// pinhole camera (fov 40) looking at the centre of `box` from outside. Incoherent: origins
/// uniform in `box`, directions uniform on the sphere.
std::vector<BenchRay> primary_rays(const Aabb& box, int width, int height);
std::vector<BenchRay> incoherent_rays(const Aabb& box, std::size_t count);
/// The point light of the shadow rays: above and to the side of `box`.
Vec3 bench_light(const Aabb& box);

}  // namespace raycast

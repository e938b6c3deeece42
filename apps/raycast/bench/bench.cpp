#include "bench/bench.h"

#include "math/isa.h"

#include <sys/resource.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include "bench/embree_peer.h"
#include "geometry/spawn.h"
#include "io/mesh_file.h"
#include "io/scene_error.h"
#include "load/loader.h"
#include "math/lane_array.h"
#include "mesh/mesh_packet16.h"
#include "mesh/procedural.h"

namespace raycast {

namespace {

// SplitMix64 (Steele et al. 2014): the i-th ray's random numbers depend only on i.
std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

double uniform(std::uint64_t& state) {
  state = splitmix(state);
  return (state >> 11) * 0x1p-53;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// CPU seconds (user + system) of the whole process so far.
double cpu_seconds() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Runs `pass` `repeat` times; returns the fastest wall time in seconds and sets `cpu` to the
// fewest CPU seconds of a pass (summed over threads: robust to other processes on the machine).
template <class F>
double best_of(int repeat, F&& pass, double& cpu) {
  double best = kInfinity;
  cpu = kInfinity;
  for (int i = 0; i < std::max(repeat, 1); ++i) {
    const auto start = std::chrono::steady_clock::now();
    const double c0 = cpu_seconds();
    pass();
    best = std::min(best, seconds_since(start));
    cpu = std::min(cpu, cpu_seconds() - c0);
  }
  return best;
}

std::shared_ptr<const Mesh> bench_mesh(const BenchOptions& o, std::string& what) {
  TriangleSoup soup;
  std::vector<Vec3f> normals;
  if (!o.mesh_file.empty()) {
    what = o.mesh_file;
    try {
      MeshFileData d = load_mesh_file(o.mesh_file);
      soup = std::move(d.soup);
    } catch (const MeshFileError& e) {
      throw SceneError(o.mesh_file, 0, 0, e.what());
    }
  } else {
    what = "procedural " + o.procedural;
    const auto colon = o.procedural.find(':');
    if (colon == std::string::npos)
      throw SceneError("--procedural", 0, 0,
                       "expected NAME:TRIANGLES (sphere:1000000), got " + o.procedural);
    const std::string name = o.procedural.substr(0, colon), count = o.procedural.substr(colon + 1);
    double n = 0;
    try {
      std::size_t used = 0;
      n = std::stod(count, &used);
      if (used != count.size()) throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
      throw SceneError("--procedural", 0, 0,
                       "the triangle count must be a number, got '" + count + "'");
    }
    try {
      soup = make_procedural_mesh(name, static_cast<std::size_t>(std::max(0.0, std::min(n, 4e9))));
    } catch (const std::invalid_argument& e) {
      throw SceneError("--procedural", 0, 0, e.what());
    }
  }
  try {
    MeshOptions options;
    options.bvh = o.bvh;
    return make_mesh(std::move(soup.positions), std::move(soup.triangles), {}, options);
  } catch (const std::invalid_argument& e) {
    throw SceneError(what, 0, 0, e.what());
  }
}

std::string json_escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
      continue;
    }
    out += c;
  }
  return out;
}

bool t_differs(double a, double b) {
  return std::abs(a - b) > 1e-4 * std::max(std::abs(a), std::abs(b));
}

}  // namespace

BenchRays parse_bench_rays(const std::string& s) {
  if (s == "primary") return BenchRays::kPrimary;
  if (s == "incoherent") return BenchRays::kIncoherent;
  if (s == "shadow") return BenchRays::kShadow;
  throw SceneError("--rays", 0, 0, "expected primary, incoherent or shadow, got " + s);
}

Vec3 bench_light(const Aabb& box) {
  const Vec3 c = box.centre();
  const double r = 0.5 * length(box.extent());
  return c + Vec3{0.6, 1.2, 1.5} * r;
}

std::vector<BenchRay> primary_rays(const Aabb& box, int width, int height) {
  const Vec3 c = box.centre();
  const double radius = std::max(0.5 * length(box.extent()), 1e-30);
  const double fov = 40 * std::numbers::pi / 180;
  const Vec3 view = normalize(Vec3{0.3, 0.4, 1.0});
  const Vec3 eye = c + (radius / std::sin(fov / 2)) * view;
  const Vec3 forward = -view;
  const Vec3 right = normalize(cross(forward, Vec3{0, 1, 0}));
  const Vec3 up = cross(right, forward);
  const double half_h = std::tan(fov / 2), half_w = half_h * width / height;
  std::vector<BenchRay> rays(static_cast<std::size_t>(width) * height);
  tbb::parallel_for(0, height, [&](int j) {
    for (int i = 0; i < width; ++i) {
      const double x = (2 * (i + 0.5) / width - 1) * half_w,
                   y = (1 - 2 * (j + 0.5) / height) * half_h;
      rays[static_cast<std::size_t>(j) * width + i] =
          BenchRay{eye, forward + x * right + y * up, 0, kInfinity};
    }
  });
  return rays;
}

std::vector<BenchRay> incoherent_rays(const Aabb& box, std::size_t count) {
  std::vector<BenchRay> rays(count);
  tbb::parallel_for(std::size_t(0), count, [&](std::size_t i) {
    std::uint64_t s = i * 0x2545F4914F6CDD1Dull + 17;
    const Vec3 o{box.lo.x + uniform(s) * (box.hi.x - box.lo.x),
                 box.lo.y + uniform(s) * (box.hi.y - box.lo.y),
                 box.lo.z + uniform(s) * (box.hi.z - box.lo.z)};
    const double z = 2 * uniform(s) - 1, phi = 2 * std::numbers::pi * uniform(s);
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    rays[i] = BenchRay{o, {r * std::cos(phi), r * std::sin(phi), z}, 0, kInfinity};
  });
  return rays;
}

namespace {

// The bench's scene: a file, or one mesh (from a file or procedural) as the only object.
Scene bench_scene(const BenchOptions& o, BenchResult& r) {
  Scene scene;
  if (!o.scene.empty()) {
    scene = load_scene_file(o.scene);
    r.what = o.scene;
    return scene;
  }
  const auto mesh = bench_mesh(o, r.what);
  scene.materials.emplace_back();
  Object obj;
  obj.shape = MeshShape{mesh};
  obj.material = 0;
  obj.entry = 0;
  scene.objects.push_back(std::move(obj));
  scene.entries = 1;
  scene.build();
  return scene;
}

// The scene's meshes (for the peer), their triangles, build times and bytes into r.
std::vector<PeerMesh> measure_meshes(const Scene& scene, const BenchOptions& o, BenchResult& r) {
  std::vector<PeerMesh> peer_meshes;
  std::size_t bvh_bytes = 0, total_bytes = 0;
  double mesh_build_ms = 0;
  for (const Object& obj : scene.objects)
    if (const auto* m = std::get_if<MeshShape>(&obj.shape)) {
      r.triangles += m->mesh->triangle_count();
      mesh_build_ms += m->mesh->build_ms;
      r.raycast_build_cpu_ms += m->mesh->build_cpu_ms;
      bvh_bytes += m->mesh->bvh_bytes();
      total_bytes += m->mesh->memory_bytes();
      peer_meshes.push_back({m->mesh, obj.xf});
    } else if (o.vs_embree) {
      throw SceneError(o.scene, 0, 0, "--vs embree needs a scene made of meshes only");
    }
  r.raycast_build_ms = mesh_build_ms + scene.build_ms();
  const double tris = std::max<double>(1, static_cast<double>(r.triangles));
  r.raycast_bytes_per_tri = (bvh_bytes + scene.accel_bytes()) / tris;
  r.raycast_total_bytes_per_tri = (total_bytes + scene.accel_bytes()) / tris;
  return peer_meshes;
}

// --packets: the one mesh of the scene, traced in packets of 8 or 16 consecutive rays.
const MeshShape* packet_mesh(const Scene& scene, const BenchOptions& o) {
  if (!o.packets) return nullptr;
  if (o.rays != BenchRays::kPrimary)
    throw SceneError("--packets", 0, 0, "packets are for primary (coherent) rays only");
  const MeshShape* mesh = nullptr;
  if (scene.objects.size() == 1 && !scene.objects[0].xf)
    mesh = std::get_if<MeshShape>(&scene.objects[0].shape);
  if (!mesh)
    throw SceneError("--packets", 0, 0, "packets need a scene of one mesh without a transform");
  if (o.packet_width != 8 && o.packet_width != 16)
    throw SceneError("--packets", 0, 0, "packets of 8 or 16 rays");
  return mesh;
}

const SceneHit kMissHit{};

// Packets of `width` consecutive rays: intersect8, or intersect16 (one 16-lane packet with
// AVX-512). Uninitialised lanes (LaneArray) and the miss copied from a constant: a default Ray /
// LocalHit array per packet, and a miss built on the stack field by field then copied out with
// wider loads (a store-forwarding stall), were about half of this loop's samples in perf.
void trace_packets(const MeshShape& mesh, std::size_t width, const std::vector<BenchRay>& rs,
                   std::vector<SceneHit>& out) {
  const std::size_t packets = (rs.size() + width - 1) / width;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, packets, 128),
                    [&](const tbb::blocked_range<std::size_t>& b) {
                      for (std::size_t p = b.begin(); p < b.end(); ++p) {
                        LaneArray<Ray, 16> ray;
                        LaneArray<LocalHit, 16> local;
                        int mask = 0;
                        for (std::size_t l = 0; l < width; ++l) {
                          const std::size_t i = p * width + l;
                          if (i >= rs.size()) break;
                          ray[l] = Ray{rs[i].o, rs[i].d, rs[i].tmin, rs[i].tmax};
                          if (is_valid(ray[l])) mask |= 1 << l;
                        }
                        const int found = width == 16
                                              ? intersect16(mesh, ray.data(), mask, local.data())
                                              : intersect8(mesh, ray.data(), mask, local.data());
                        for (std::size_t l = 0; l < width && p * width + l < rs.size(); ++l) {
                          SceneHit& h = out[p * width + l];
                          if (found >> l & 1) {
                            h.local = local[static_cast<int>(l)];
                            h.object = 0;
                          } else {
                            h = kMissHit;
                          }
                        }
                      }
                    });
}

// Nearest hits, one ray at a time: straight into out[i], a miss copied from kMissHit (a local
// SceneHit written field by field and then copied out with 16-byte loads waited on the store
// buffer, loads spanning two stores, on every ray).
void trace_rays(const Scene& scene, const std::vector<BenchRay>& rs, std::vector<SceneHit>& out) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rs.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& b) {
                      for (std::size_t i = b.begin(); i < b.end(); ++i) {
                        const BenchRay& q = rs[i];
                        if (!scene.intersect(Ray{q.o, q.d, q.tmin, q.tmax}, out[i]))
                          out[i] = kMissHit;
                      }
                    });
}

// Shadow rays from the primary hits (offset by their error bounds) towards the bench's light.
std::vector<BenchRay> shadow_rays(const Scene& scene, const Aabb& box,
                                  const std::vector<BenchRay>& rays,
                                  const std::vector<SceneHit>& hits) {
  const Vec3 light = bench_light(box);
  std::vector<BenchRay> shadow;
  shadow.reserve(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (!hits[i].valid()) continue;
    const Ray ray{rays[i].o, rays[i].d, rays[i].tmin, rays[i].tmax};
    const SurfaceInfo si = scene.surface(ray, hits[i]);
    const Vec3 p = offset_ray_origin(si, light - si.p);
    shadow.push_back(BenchRay{p, light - p, 0, 1});
  }
  return shadow;
}

// Embree on the same rays: its times and its disagreements with raycast's answers into r.
void run_peer(const Scene& scene, const std::vector<PeerMesh>& meshes, int threads,
              const BenchOptions& o, const std::vector<BenchRay>& rays,
              const std::vector<SceneHit>& hits, const std::vector<std::uint8_t>& blocked,
              BenchResult& r) {
  const EmbreePeer peer(meshes, threads);
  r.embree = true;
  r.embree_build_ms = peer.build_ms();
  r.embree_build_cpu_ms = peer.build_cpu_ms();
  r.embree_bytes_per_tri = peer.bytes() / std::max<double>(1, static_cast<double>(r.triangles));
  double seconds = 0, cpu = 0;
  if (o.rays == BenchRays::kShadow) {
    std::vector<std::uint8_t> eb(rays.size());
    seconds = best_of(
        o.repeat, [&] { peer.occluded(rays, eb); }, cpu);
    for (std::size_t i = 0; i < rays.size(); ++i)
      if (eb[i] != blocked[i]) ++r.disagree_hit;
    r.disagree = r.disagree_hit;
  } else {
    std::vector<PeerHit> eh(rays.size());
    seconds = best_of(
        o.repeat,
        [&] {
          if (o.packets && o.packet_width == 16)
            peer.intersect16(rays, eh);
          else if (o.packets)
            peer.intersect8(rays, eh);
          else
            peer.intersect(rays, eh);
        },
        cpu);
    // The peer's geometry index is the position among the scene's meshes: map it back.
    std::vector<std::int32_t> object_of;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
      if (std::holds_alternative<MeshShape>(scene.objects[i].shape))
        object_of.push_back(static_cast<std::int32_t>(i));
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const SceneHit& a = hits[i];
      const PeerHit& b = eh[i];
      if (a.valid() != (b.geometry >= 0)) {
        ++r.disagree_hit;
        ++r.disagree;
        continue;
      }
      if (!a.valid()) continue;
      const bool dt = t_differs(a.local.t, b.t);
      const bool dp = a.object != object_of[b.geometry] || a.local.prim != b.prim;
      r.disagree_t += dt;
      r.disagree_prim += dp;
      r.disagree += dt || dp;
    }
  }
  r.embree_mrays = r.rays / seconds / 1e6;
  r.embree_mrays_cpu = r.rays / cpu / 1e6;
  r.ratio = r.raycast_mrays / r.embree_mrays;
}

}  // namespace

BenchResult run_bench(const BenchOptions& o) {
  if (o.vs_embree && !EmbreePeer::available())
    throw SceneError("--vs embree", 0, 0,
                     "this build has no Embree (install libembree-dev and reconfigure)");
  const int threads =
      o.threads > 0 ? o.threads : static_cast<int>(tbb::info::default_concurrency());
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(threads));
  BenchResult r;
  r.threads = threads;
  r.ray_kind = o.rays == BenchRays::kPrimary
                   ? "primary"
                   : (o.rays == BenchRays::kIncoherent ? "incoherent" : "shadow");
  const Scene scene = bench_scene(o, r);
  const std::vector<PeerMesh> peer_meshes = measure_meshes(scene, o, r);
  const Aabb box =
      scene.finite_bounds().is_empty() ? Aabb{{-1, -1, -1}, {1, 1, 1}} : scene.finite_bounds();

  std::vector<BenchRay> rays =
      o.rays == BenchRays::kIncoherent
          ? incoherent_rays(box, static_cast<std::size_t>(o.width) * o.height)
          : primary_rays(box, o.width, o.height);
  std::vector<SceneHit> hits(rays.size());
  const MeshShape* packets = packet_mesh(scene, o);
  r.packets = packets != nullptr;
  if (packets) r.packet_width = o.packet_width;
  auto trace = [&](const std::vector<BenchRay>& rs, std::vector<SceneHit>& out) {
    if (packets)
      trace_packets(*packets, static_cast<std::size_t>(o.packet_width), rs, out);
    else
      trace_rays(scene, rs, out);
  };
  if (o.rays == BenchRays::kShadow) {
    trace(rays, hits);
    rays = shadow_rays(scene, box, rays, hits);
  }
  r.rays = rays.size();

  std::vector<std::uint8_t> blocked;
  double seconds = 0, cpu = 0;
  if (o.rays == BenchRays::kShadow) {
    blocked.assign(rays.size(), 0);
    seconds = best_of(
        o.repeat,
        [&] {
          tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024),
                            [&](const tbb::blocked_range<std::size_t>& b) {
                              for (std::size_t i = b.begin(); i < b.end(); ++i) {
                                const BenchRay& q = rays[i];
                                blocked[i] = scene.occluded(Ray{q.o, q.d, q.tmin, q.tmax});
                              }
                            });
        },
        cpu);
    for (std::uint8_t b : blocked) r.hits += b;
  } else {
    seconds = best_of(
        o.repeat, [&] { trace(rays, hits); }, cpu);
    for (const SceneHit& h : hits) r.hits += h.valid();
  }
  r.raycast_mrays = r.rays / seconds / 1e6;
  r.raycast_mrays_cpu = r.rays / cpu / 1e6;
  if (o.vs_embree) run_peer(scene, peer_meshes, threads, o, rays, hits, blocked, r);
  return r;
}

std::string format_bench(const BenchResult& r, bool json) {
  char buf[8192];
  std::string out;
  if (json) {
    std::snprintf(buf, sizeof buf,
                  "{\"what\": \"%s\", \"ray_kind\": \"%s\", \"triangles\": %llu, \"rays\": %llu, "
                  "\"hits\": %llu, "
                  "\"threads\": %d, \"raycast_build_ms\": %.3f, \"raycast_mrays\": %.4f, "
                  "\"raycast_mrays_cpu\": %.4f, \"isa\": \"%s\", \"raycast_build_cpu_ms\": %.3f, "
                  "\"packets\": %s",
                  json_escape(r.what).c_str(), r.ray_kind.c_str(),
                  static_cast<unsigned long long>(r.triangles),
                  static_cast<unsigned long long>(r.rays), static_cast<unsigned long long>(r.hits),
                  r.threads, r.raycast_build_ms, r.raycast_mrays, r.raycast_mrays_cpu,
                  isa_name(active_isa()), r.raycast_build_cpu_ms, r.packets ? "true" : "false");
    out = buf;
    if (r.packets) {
      std::snprintf(buf, sizeof buf, ", \"packet_width\": %d", r.packet_width);
      out += buf;
    }
    if (r.triangles > 0)  // else null: per triangle means nothing without triangles
      std::snprintf(buf, sizeof buf,
                    ", \"raycast_bytes_per_tri\": %.2f, \"raycast_total_bytes_per_tri\": %.2f",
                    r.raycast_bytes_per_tri, r.raycast_total_bytes_per_tri);
    else
      std::snprintf(buf, sizeof buf,
                    ", \"raycast_bytes_per_tri\": null, \"raycast_total_bytes_per_tri\": null");
    out += buf;
    if (r.embree) {
      std::snprintf(
          buf, sizeof buf,
          ", \"embree_build_ms\": %.3f, \"embree_mrays\": %.4f, \"embree_bytes_per_tri\": %.2f, "
          "\"ratio\": %.4f, \"embree_mrays_cpu\": %.4f, \"ratio_cpu\": %.4f, \"disagree\": %llu, "
          "\"disagree_hit\": %llu, \"disagree_t\": %llu, "
          "\"disagree_prim\": %llu, \"embree_build_cpu_ms\": %.3f, \"build_ratio_cpu\": %.4f",
          r.embree_build_ms, r.embree_mrays, r.embree_bytes_per_tri, r.ratio, r.embree_mrays_cpu,
          r.raycast_mrays_cpu / r.embree_mrays_cpu, static_cast<unsigned long long>(r.disagree),
          static_cast<unsigned long long>(r.disagree_hit),
          static_cast<unsigned long long>(r.disagree_t),
          static_cast<unsigned long long>(r.disagree_prim), r.embree_build_cpu_ms,
          r.raycast_build_cpu_ms > 0 ? r.embree_build_cpu_ms / r.raycast_build_cpu_ms : 0.0);
      out += buf;
    }
    return out + "}\n";
  }
  std::snprintf(buf, sizeof buf,
                "%s: %s (%llu triangles)\nrays: %s%s, %llu rays (%llu hit), %d threads, isa %s\n"
                "raycast: build %.1f ms, %.3f Mrays/s",
                r.triangles > 0 ? "mesh" : "scene", r.what.c_str(),
                static_cast<unsigned long long>(r.triangles), r.ray_kind.c_str(),
                r.packets ? (r.packet_width == 16 ? " (packets of 16)" : " (packets of 8)") : "",
                static_cast<unsigned long long>(r.rays), static_cast<unsigned long long>(r.hits),
                r.threads, isa_name(active_isa()), r.raycast_build_ms, r.raycast_mrays);
  out = buf;
  // Bytes per triangle only mean something when there are triangles.
  if (r.triangles > 0) {
    std::snprintf(buf, sizeof buf, ", %.1f bytes/triangle (BVH; %.1f with mesh storage)",
                  r.raycast_bytes_per_tri, r.raycast_total_bytes_per_tri);
    out += buf;
  }
  out += "\n";
  if (r.embree) {
    std::snprintf(
        buf, sizeof buf,
        "embree:  build %.1f ms, %.3f Mrays/s, %.1f bytes/triangle\n"
        "ratio raycast/embree: %.3f; disagree: %llu rays (hit/miss %llu, t %llu, prim %llu)\n",
        r.embree_build_ms, r.embree_mrays, r.embree_bytes_per_tri, r.ratio,
        static_cast<unsigned long long>(r.disagree),
        static_cast<unsigned long long>(r.disagree_hit),
        static_cast<unsigned long long>(r.disagree_t),
        static_cast<unsigned long long>(r.disagree_prim));
    out += buf;
  }
  return out;
}

}  // namespace raycast

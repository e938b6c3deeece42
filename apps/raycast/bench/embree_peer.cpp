#include "bench/embree_peer.h"

#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#ifdef RAYCAST_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace raycast {

#ifdef RAYCAST_HAVE_EMBREE

namespace {

std::atomic<std::int64_t> g_embree_bytes{0};

bool monitor(void* /*user*/, ssize_t bytes, bool /*post*/) {
  g_embree_bytes += bytes;
  return true;
}

}  // namespace

// CPU milliseconds (user + system, all threads) of the process so far.
static double cpu_ms() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return 1e3 * (u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-3 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct EmbreePeer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  double build_ms = 0;
  double build_cpu_ms = 0;
  std::size_t bytes = 0;
  std::vector<const Mesh*> meshes;
  std::vector<std::vector<float>> vertices;  // world-space copies, padded as Embree requires
};

EmbreePeer::EmbreePeer(const std::vector<PeerMesh>& meshes, int threads)
    : impl_(std::make_unique<Impl>()) {
  const std::string config = threads > 0 ? "threads=" + std::to_string(threads) : "";
  impl_->device = rtcNewDevice(config.c_str());
  if (!impl_->device) throw std::runtime_error("Embree: cannot create a device");
  rtcSetDeviceMemoryMonitorFunction(impl_->device, monitor, nullptr);
  impl_->scene = rtcNewScene(impl_->device);
  impl_->vertices.resize(meshes.size());
  for (std::size_t g = 0; g < meshes.size(); ++g) {
    const Mesh& m = *meshes[g].mesh;
    impl_->meshes.push_back(&m);
    auto& v = impl_->vertices[g];
    v.resize(m.positions.size() * 3 + 1);  // one float of padding: Embree reads 16 bytes per vertex
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      Vec3 p(m.positions[i]);
      if (meshes[g].xf) p = meshes[g].xf->point(p);
      v[3 * i] = static_cast<float>(p.x);
      v[3 * i + 1] = static_cast<float>(p.y);
      v[3 * i + 2] = static_cast<float>(p.z);
    }
    RTCGeometry geom = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, v.data(), 0,
                               3 * sizeof(float), m.positions.size());
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, m.triangles.data(),
                               0, 3 * sizeof(std::uint32_t), m.triangles.size());
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(impl_->scene, geom, static_cast<unsigned>(g));
    rtcReleaseGeometry(geom);
  }
  g_embree_bytes = 0;
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_ms();
  rtcCommitScene(impl_->scene);
  impl_->build_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  impl_->build_cpu_ms = cpu_ms() - cpu_start;
  impl_->bytes = static_cast<std::size_t>(std::max<std::int64_t>(0, g_embree_bytes.load()));
  if (rtcGetDeviceError(impl_->device) != RTC_ERROR_NONE)
    throw std::runtime_error("Embree: scene build failed");
}

EmbreePeer::~EmbreePeer() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

double EmbreePeer::build_ms() const { return impl_->build_ms; }
double EmbreePeer::build_cpu_ms() const { return impl_->build_cpu_ms; }
std::size_t EmbreePeer::bytes() const { return impl_->bytes; }
bool EmbreePeer::available() { return true; }

namespace {

void set_ray(RTCRay& r, const BenchRay& b) {
  r.org_x = static_cast<float>(b.o.x);
  r.org_y = static_cast<float>(b.o.y);
  r.org_z = static_cast<float>(b.o.z);
  r.dir_x = static_cast<float>(b.d.x);
  r.dir_y = static_cast<float>(b.d.y);
  r.dir_z = static_cast<float>(b.d.z);
  r.tnear = static_cast<float>(b.tmin);
  r.tfar = static_cast<float>(b.tmax);
  r.time = 0;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
}

}  // namespace

void EmbreePeer::intersect(std::span<const BenchRay> rays, std::span<PeerHit> out) const {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      RTCIntersectContext ctx;
                      rtcInitIntersectContext(&ctx);
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        RTCRayHit rh;
                        set_ray(rh.ray, rays[i]);
                        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                        rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
                        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                        rtcIntersect1(impl_->scene, &ctx, &rh);
                        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
                          out[i] = PeerHit{};
                        } else {
                          const Mesh& m = *impl_->meshes[rh.hit.geomID];
                          out[i] = PeerHit{rh.ray.tfar, static_cast<std::int32_t>(rh.hit.geomID),
                                           static_cast<std::int32_t>(m.source[rh.hit.primID])};
                        }
                      }
                    });
}

void EmbreePeer::occluded(std::span<const BenchRay> rays, std::span<std::uint8_t> out) const {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      RTCIntersectContext ctx;
                      rtcInitIntersectContext(&ctx);
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        RTCRay ray;
                        set_ray(ray, rays[i]);
                        rtcOccluded1(impl_->scene, &ctx, &ray);
                        out[i] = ray.tfar < 0 ? 1 : 0;
                      }
                    });
}

namespace {

// rtcIntersect8 or rtcIntersect16 (K rays) over consecutive groups of K rays, coherent flag set.
template <int K, class RayHitK, class IntersectK>
void intersect_packets(RTCScene scene, const std::vector<const Mesh*>& meshes,
                       std::span<const BenchRay> rays, std::span<PeerHit> out,
                       IntersectK intersect_k) {
  const std::size_t packets = (rays.size() + K - 1) / K;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, packets, 128),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      RTCIntersectContext ctx;
                      rtcInitIntersectContext(&ctx);
                      ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
                      for (std::size_t p = r.begin(); p < r.end(); ++p) {
                        alignas(64) int valid[K];
                        alignas(64) RayHitK rh;
                        for (int l = 0; l < K; ++l) {
                          const std::size_t i = p * K + l;
                          valid[l] = i < rays.size() ? -1 : 0;
                          const BenchRay& b = rays[i < rays.size() ? i : rays.size() - 1];
                          rh.ray.org_x[l] = static_cast<float>(b.o.x);
                          rh.ray.org_y[l] = static_cast<float>(b.o.y);
                          rh.ray.org_z[l] = static_cast<float>(b.o.z);
                          rh.ray.dir_x[l] = static_cast<float>(b.d.x);
                          rh.ray.dir_y[l] = static_cast<float>(b.d.y);
                          rh.ray.dir_z[l] = static_cast<float>(b.d.z);
                          rh.ray.tnear[l] = static_cast<float>(b.tmin);
                          rh.ray.tfar[l] = static_cast<float>(b.tmax);
                          rh.ray.time[l] = 0;
                          rh.ray.mask[l] = 0xFFFFFFFFu;
                          rh.ray.id[l] = 0;
                          rh.ray.flags[l] = 0;
                          rh.hit.geomID[l] = RTC_INVALID_GEOMETRY_ID;
                          rh.hit.primID[l] = RTC_INVALID_GEOMETRY_ID;
                          rh.hit.instID[0][l] = RTC_INVALID_GEOMETRY_ID;
                        }
                        intersect_k(valid, scene, &ctx, &rh);
                        for (int l = 0; l < K; ++l) {
                          const std::size_t i = p * K + l;
                          if (i >= rays.size()) break;
                          if (rh.hit.geomID[l] == RTC_INVALID_GEOMETRY_ID) {
                            out[i] = PeerHit{};
                          } else {
                            const Mesh& m = *meshes[rh.hit.geomID[l]];
                            out[i] =
                                PeerHit{rh.ray.tfar[l], static_cast<std::int32_t>(rh.hit.geomID[l]),
                                        static_cast<std::int32_t>(m.source[rh.hit.primID[l]])};
                          }
                        }
                      }
                    });
}

}  // namespace

void EmbreePeer::intersect8(std::span<const BenchRay> rays, std::span<PeerHit> out) const {
  intersect_packets<8, RTCRayHit8>(impl_->scene, impl_->meshes, rays, out, rtcIntersect8);
}

void EmbreePeer::intersect16(std::span<const BenchRay> rays, std::span<PeerHit> out) const {
  intersect_packets<16, RTCRayHit16>(impl_->scene, impl_->meshes, rays, out, rtcIntersect16);
}

#else

struct EmbreePeer::Impl {};

EmbreePeer::EmbreePeer(const std::vector<PeerMesh>&, int) {
  throw std::runtime_error("this build has no Embree (install libembree-dev and reconfigure)");
}
EmbreePeer::~EmbreePeer() = default;
double EmbreePeer::build_ms() const { return 0; }
double EmbreePeer::build_cpu_ms() const { return 0; }
std::size_t EmbreePeer::bytes() const { return 0; }
bool EmbreePeer::available() { return false; }
void EmbreePeer::intersect(std::span<const BenchRay>, std::span<PeerHit>) const {}
void EmbreePeer::occluded(std::span<const BenchRay>, std::span<std::uint8_t>) const {}
void EmbreePeer::intersect8(std::span<const BenchRay>, std::span<PeerHit>) const {}
void EmbreePeer::intersect16(std::span<const BenchRay>, std::span<PeerHit>) const {}

#endif

}  // namespace raycast

#include "cast/cast.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <istream>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "io/scene_error.h"
#include "scene/ray_batch.h"

namespace raycast {

namespace {

constexpr std::size_t kBatch = 1 << 16;  // rays answered per parallel batch

struct Answer {
  SceneHit hit;
  SurfaceInfo surface;
  bool blocked = false;
  std::vector<Crossing> crossings;
  std::vector<Vec3> normals;
};

void check_ray(const Ray& r, const CastOptions& opt, long line) {
  const char* why = nullptr;
  if (!is_finite(r.o))
    why = "ray origin must be finite";
  else if (!is_finite(r.d) || length_squared(r.d) == 0 || !std::isfinite(length_squared(r.d)))
    why = "ray direction must be finite and non-zero";
  else if (std::isnan(r.tmin) || std::isnan(r.tmax) || r.tmin > r.tmax)
    why = "tmin must be <= tmax (and neither NaN)";
  else if (!is_valid(r))
    why =
        "ray out of range: |o| must be below about 1.3e154 and |d| within about [1.5e-154, "
        "1.3e154]";
  if (why) {
    if (opt.binary) throw SceneError(opt.source, 0, 0, "ray " + std::to_string(line) + ": " + why);
    throw SceneError(opt.source, static_cast<int>(line), 1, why);
  }
}

// Parses one text line into a ray; returns false for blank and comment lines.
bool parse_line(const std::string& text, long line, const CastOptions& opt, Ray& ray) {
  std::size_t i = text.find_first_not_of(" \t\r");
  if (i == std::string::npos || text[i] == '#') return false;
  double v[8];
  int n = 0;
  const char* s = text.c_str();
  const char* p = s + i;
  while (*p) {
    while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
    if (!*p) break;
    if (n == 8)
      throw SceneError(opt.source, static_cast<int>(line), static_cast<int>(p - s) + 1,
                       "too many numbers (expected ox oy oz dx dy dz [tmin [tmax]])");
    char* end = nullptr;
    v[n] = std::strtod(p, &end);
    if (end == p || (*end && *end != ' ' && *end != '\t' && *end != '\r'))
      throw SceneError(opt.source, static_cast<int>(line), static_cast<int>(p - s) + 1,
                       "expected a number");
    ++n;
    p = end;
  }
  if (n < 6)
    throw SceneError(
        opt.source, static_cast<int>(line), 1,
        "expected ox oy oz dx dy dz [tmin [tmax]], got " + std::to_string(n) + " numbers");
  ray.o = {v[0], v[1], v[2]};
  ray.d = {v[3], v[4], v[5]};
  ray.tmin = n > 6 ? v[6] : 0;
  ray.tmax = n > 7 ? v[7] : kInfinity;
  check_ray(ray, opt, line);
  return true;
}

void answer(const Scene& scene, const Ray& ray, CastMode mode, Answer& a) {
  switch (mode) {
    case CastMode::kNearest:
      a.hit = SceneHit{};
      if (scene.intersect(ray, a.hit)) a.surface = scene.surface(ray, a.hit);
      break;
    case CastMode::kAny:
      a.blocked = scene.occluded(ray);
      break;
    case CastMode::kAll:
      scene.intersect_all(ray, a.crossings);
      a.normals.clear();
      for (const Crossing& c : a.crossings)
        a.normals.push_back(scene.surface(ray, SceneHit{c.local, c.object}).n);
      break;
  }
}

// The nearest hits of rays[begin, end): as answer() one by one, with coherent runs of rays
// traced as packets (scene/ray_batch.h).
void answer_nearest(const Scene& scene, const std::vector<Ray>& rays, std::size_t begin,
                    std::size_t end, std::vector<Answer>& answers) {
  const std::size_t n = end - begin;
  std::vector<SceneHit> hits(n);
  std::vector<std::uint8_t> found(n);
  intersect_batch(scene, std::span(rays).subspan(begin, n), hits, found);
  for (std::size_t k = 0; k < n; ++k) {
    Answer& a = answers[begin + k];
    a.hit = hits[k];
    if (found[k]) a.surface = scene.surface(rays[begin + k], a.hit);
  }
}

void write_text(const Scene& scene, const Answer& a, CastMode mode, std::string& buf) {
  char tmp[512];
  switch (mode) {
    case CastMode::kNearest:
      if (!a.hit.valid()) {
        buf += "inf nan nan nan nan nan nan nan nan -1 -1\n";
        return;
      } else {
        const SurfaceInfo& s = a.surface;
        std::snprintf(tmp, sizeof tmp,
                      "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %d %d\n",
                      a.hit.local.t, s.p.x, s.p.y, s.p.z, s.n.x, s.n.y, s.n.z, s.u, s.v,
                      scene.objects[a.hit.object].entry, a.hit.local.prim);
        buf += tmp;
      }
      return;
    case CastMode::kAny:
      buf += a.blocked ? "1\n" : "0\n";
      return;
    case CastMode::kAll:
      buf += std::to_string(a.crossings.size());
      for (std::size_t i = 0; i < a.crossings.size(); ++i) {
        const Vec3& n = a.normals[i];
        std::snprintf(tmp, sizeof tmp, " %.17g %.17g %.17g %.17g %d", a.crossings[i].t, n.x, n.y,
                      n.z, scene.objects[a.crossings[i].object].entry);
        buf += tmp;
      }
      buf += '\n';
      return;
  }
}

void write_binary(const Scene& scene, const Answer& a, CastMode mode, std::vector<double>& buf) {
  const double nan = std::nan("");
  switch (mode) {
    case CastMode::kNearest:
      if (!a.hit.valid()) {
        buf.insert(buf.end(), {kInfinity, nan, nan, nan, nan, nan, nan, nan, nan, -1.0, -1.0});
      } else {
        const SurfaceInfo& s = a.surface;
        buf.insert(buf.end(),
                   {a.hit.local.t, s.p.x, s.p.y, s.p.z, s.n.x, s.n.y, s.n.z, s.u, s.v,
                    double(scene.objects[a.hit.object].entry), double(a.hit.local.prim)});
      }
      return;
    case CastMode::kAny:
      buf.push_back(a.blocked ? 1.0 : 0.0);
      return;
    case CastMode::kAll:
      buf.push_back(double(a.crossings.size()));
      for (std::size_t i = 0; i < a.crossings.size(); ++i)
        buf.insert(buf.end(), {a.crossings[i].t, a.normals[i].x, a.normals[i].y, a.normals[i].z,
                               double(scene.objects[a.crossings[i].object].entry)});
      return;
  }
}

}  // namespace

void run_cast(const Scene& scene, std::istream& in, std::ostream& out, const CastOptions& opt) {
  static_assert(sizeof(double) == 8);
  std::vector<Ray> rays;
  std::vector<Answer> answers;
  std::string line;
  long line_no = 0, record = opt.first_record;
  bool done = false;
  while (!done) {
    rays.clear();
    if (opt.binary) {
      double v[8];
      while (rays.size() < kBatch) {
        in.read(reinterpret_cast<char*>(v), sizeof v);
        const auto got = in.gcount();
        if (got == 0) {
          done = true;
          break;
        }
        ++record;
        if (got != sizeof v)
          throw SceneError(opt.source, 0, 0,
                           "ray " + std::to_string(record) + ": truncated record (" +
                               std::to_string(got) + " of 64 bytes)");
        Ray r{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6], v[7]};
        check_ray(r, opt, record);
        rays.push_back(r);
      }
    } else {
      while (rays.size() < kBatch) {
        if (!std::getline(in, line)) {
          done = true;
          break;
        }
        ++line_no;
        Ray r;
        if (parse_line(line, line_no, opt, r)) rays.push_back(r);
      }
    }
    answers.resize(rays.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), 256),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        if (opt.mode == CastMode::kNearest)
                          return answer_nearest(scene, rays, range.begin(), range.end(), answers);
                        for (std::size_t i = range.begin(); i != range.end(); ++i)
                          answer(scene, rays[i], opt.mode, answers[i]);
                      });
    if (opt.binary) {
      std::vector<double> buf;
      for (const Answer& a : answers) write_binary(scene, a, opt.mode, buf);
      out.write(reinterpret_cast<const char*>(buf.data()),
                static_cast<std::streamsize>(buf.size() * 8));
    } else {
      std::string buf;
      for (const Answer& a : answers) write_text(scene, a, opt.mode, buf);
      out << buf;
    }
  }
  out.flush();
}

}  // namespace raycast

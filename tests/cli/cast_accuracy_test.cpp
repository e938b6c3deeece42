// `raycast cast` on a scene with every basic shape answers random rays to 1e-9 relative in t,
// against references written independently here (geometric sphere, plane-then-inside tests).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

struct V {
  double x, y, z;
};
V operator+(V a, V b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V operator-(V a, V b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V operator*(double s, V a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V a, V b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V cross(V a, V b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double norm(V a) { return std::sqrt(dot(a, a)); }

struct RayR {
  V o, d;
};

// One reference crossing: t, the outward normal, and how far the decision was from flipping
// (distance to a rim, or to tangency), for skipping rays the two methods may legitimately split.
struct Cross {
  double t;
  V n;
  double margin;
};

using Reference = std::function<std::vector<Cross>(const RayR&)>;

// Sphere by the geometric solution; optionally cut (z range relative to the centre, phi_max).
Reference sphere(V c, double r, double z_min = -1e300, double z_max = 1e300, double phi_deg = 360) {
  return [=](const RayR& ray) {
    std::vector<Cross> out;
    const double dd = dot(ray.d, ray.d);
    const double tc = dot(c - ray.o, ray.d) / dd;
    const V f = ray.o + tc * ray.d - c;
    const double h2 = r * r - dot(f, f);
    if (h2 < 0) return out;
    const double half = std::sqrt(h2 / dd);
    for (double t : {tc - half, tc + half}) {
      const V q = ray.o + t * ray.d - c;
      double phi = std::atan2(q.y, q.x);
      if (phi < 0) phi += 2 * kPi;
      double margin = std::sqrt(h2);
      const bool cut = phi_deg < 360 || z_min > -r || z_max < r;
      if (cut) {
        margin = std::min({margin, std::abs(q.z - z_min), std::abs(q.z - z_max)});
        if (phi_deg < 360)
          margin = std::min({margin, phi * r, std::abs(phi - phi_deg * kPi / 180) * r});
        if (q.z < z_min || q.z > z_max || (phi_deg < 360 && phi > phi_deg * kPi / 180)) {
          out.push_back(
              {-1e300, {0, 0, 0}, margin});  // a rejected crossing still carries its margin
          continue;
        }
      }
      out.push_back({t, (1 / r) * q, margin});
    }
    return out;
  };
}

// A convex polygon given by its plane and an inside test on the plane point.
Reference planar(V p0, V n, std::function<double(V)> inside_margin) {
  return [=](const RayR& ray) {
    std::vector<Cross> out;
    const double dn = dot(n, ray.d);
    if (dn == 0) return out;
    const double t = dot(n, p0 - ray.o) / dn;
    const double m = inside_margin(ray.o + t * ray.d);
    out.push_back({m >= 0 ? t : -1e300, (1 / norm(n)) * n, std::abs(m)});
    return out;
  };
}

Reference triangle(V a, V b, V c) {
  const V n = cross(b - a, c - a);
  return planar(a, n, [=](V p) {
    const double area = norm(n);
    return std::min({dot(cross(b - a, p - a), n), dot(cross(c - b, p - b), n),
                     dot(cross(a - c, p - c), n)}) /
           area / std::max({norm(b - a), norm(c - b), norm(a - c)});
  });
}

Reference parallelogram(V o, V u, V v) {
  const V n = cross(u, v);
  return planar(o, n, [=](V p) {
    const V r = p - o;
    const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), det = uu * vv - uv * uv;
    const double a = (dot(u, r) * vv - dot(v, r) * uv) / det,
                 b = (dot(v, r) * uu - dot(u, r) * uv) / det;
    return std::min({a, 1 - a, b, 1 - b});
  });
}

// Annulus in the plane through c with normal n; phi measured in the (e1, e2) frame.
Reference annulus(V c, V n, double r_out, double r_in, V e1, V e2, double phi_deg) {
  return planar(c, n, [=](V p) {
    const V q = p - c;
    const double x = dot(q, e1), y = dot(q, e2), r = std::hypot(x, y);
    double m = std::min(r_out - r, r - r_in);
    if (phi_deg < 360) {
      double phi = std::atan2(y, x);
      if (phi < 0) phi += 2 * kPi;
      m = std::min({m, phi * r, (phi_deg * kPi / 180 - phi) * r});
    }
    return m;
  });
}

Reference box(V lo, V hi) {
  return [=](const RayR& ray) {
    std::vector<Cross> out;
    const double o[3] = {ray.o.x, ray.o.y, ray.o.z}, d[3] = {ray.d.x, ray.d.y, ray.d.z};
    const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    for (int face = 0; face < 6; ++face) {
      const int a = face / 2;
      if (d[a] == 0) continue;
      const double t = ((face % 2 ? h[a] : l[a]) - o[a]) / d[a];
      double m = 1e300;
      for (int k = 1; k <= 2; ++k) {
        const int c = (a + k) % 3;
        const double x = o[c] + t * d[c];
        m = std::min({m, x - l[c], h[c] - x});
      }
      V n{0, 0, 0};
      (a == 0 ? n.x : a == 1 ? n.y : n.z) = face % 2 ? 1 : -1;
      out.push_back({m >= 0 ? t : -1e300, n, std::abs(m)});
    }
    return out;
  };
}

fs::path temp_dir() {
  const fs::path dir =
      fs::temp_directory_path() / ("raycast_accuracy_test_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

// Removes this process's temporary folder once every test has run.
class RemoveTempDir : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(temp_dir(), ec);
  }
};
const auto* const kRemoveTempDir = ::testing::AddGlobalTestEnvironment(new RemoveTempDir);

TEST(CastAccuracy, EveryBasicShape_TMatchesIndependentReferenceTo1e9) {
  const std::string scene = R"(objects:
  - sphere: {center: [0, 0, 0], radius: 1}
  - sphere: {radius: 0.5}
    transform: [{scale: 2}, {translate: [3, 0, 0]}]
  - box: {min: [-1, 2, -1], max: [1, 4, 1]}
  - triangle: {vertices: [[2.5, 2.5, -1], [5, 2.5, -0.5], [4, 5, 1]]}
  - parallelogram: {origin: [-4.5, -1, -1], u: [2, 0, 0.5], v: [0, 2, 0.25]}
  - disk: {radius: 1.2, inner_radius: 0.3, height: 0.5, phi_max: 270}
    transform: [{translate: [0, -3, 0]}]
  - disk: {center: [3, -3, 0], normal: [1, 1, 1], radius: 1.1, inner_radius: 0.2}
  - plane: {normal: [0, 0, 1], point: [0, 0, -6]}
  - sphere: {center: [-3, 3, 0], radius: 1.2, z_min: -0.5, z_max: 0.7, phi_max: 200}
)";
  // The center/normal disk measures phi from make_frame(n); a whole disk does not need it.
  const V dn{1 / std::sqrt(3.0), 1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
  V e1 = cross(dn, {0, 0, 1});
  e1 = (1 / norm(e1)) * e1;
  const V e2 = cross(dn, e1);
  const std::vector<Reference> refs = {
      sphere({0, 0, 0}, 1),
      sphere({3, 0, 0}, 1),
      box({-1, 2, -1}, {1, 4, 1}),
      triangle({2.5, 2.5, -1}, {5, 2.5, -0.5}, {4, 5, 1}),
      parallelogram({-4.5, -1, -1}, {2, 0, 0.5}, {0, 2, 0.25}),
      annulus({0, -3, 0.5}, {0, 0, 1}, 1.2, 0.3, {1, 0, 0}, {0, 1, 0}, 270),
      annulus({3, -3, 0}, dn, 1.1, 0.2, e1, e2, 360),
      planar({0, 0, -6}, {0, 0, 1}, [](V) { return 1e300; }),
      sphere({-3, 3, 0}, 1.2, -0.5, 0.7, 200),
  };

  const unsigned seed = 271828;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ox(-6, 6), oz(-3, 8), aim(-5, 5), az(-2, 2), len(0.2, 5);
  std::vector<RayR> rays;
  std::ostringstream text;
  text.precision(17);
  for (int i = 0; i < 4000; ++i) {
    RayR r;
    r.o = {ox(rng), ox(rng), oz(rng)};
    V target{aim(rng), aim(rng), az(rng)};
    r.d = target - r.o;
    r.d = (len(rng) / norm(r.d)) * r.d;
    rays.push_back(r);
    text << r.o.x << ' ' << r.o.y << ' ' << r.o.z << ' ' << r.d.x << ' ' << r.d.y << ' ' << r.d.z
         << '\n';
  }
  const fs::path dir = temp_dir();
  std::ofstream(dir / "all.yaml") << scene;
  std::ofstream(dir / "rays.txt") << text.str();
  const std::string cmd = std::string("'") + RAYCAST_BINARY + "' cast '" +
                          (dir / "all.yaml").string() + "' --rays '" + (dir / "rays.txt").string() +
                          "' >'" + (dir / "out.txt").string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  std::ifstream out(dir / "out.txt");
  int checked = 0, hits_per_object[9] = {};
  for (std::size_t i = 0; i < rays.size(); ++i) {
    std::string line;
    ASSERT_TRUE(std::getline(out, line)) << "missing answer " << i;
    std::istringstream row(line);
    std::vector<double> v;
    for (std::string tok; row >> tok;) v.push_back(std::strtod(tok.c_str(), nullptr));
    ASSERT_EQ(v.size(), 11u) << line;
    // Reference: the nearest accepted crossing with t >= 0 over all objects.
    double best = INFINITY, second = INFINITY, min_margin = INFINITY;
    int best_obj = -1;
    V best_n{0, 0, 0};
    for (std::size_t k = 0; k < refs.size(); ++k)
      for (const Cross& c : refs[k](rays[i])) {
        min_margin = std::min(min_margin, c.margin);
        if (c.t < 0) continue;
        if (c.t < best) {
          second = best;
          best = c.t;
          best_obj = static_cast<int>(k);
          best_n = c.n;
        } else {
          second = std::min(second, c.t);
        }
      }
    // Skip rays within rounding of a rim or tangency, or with two objects at (nearly) one t.
    if (min_margin < 1e-7 || second - best < 1e-7 * (1 + best)) continue;
    ++checked;
    if (best_obj < 0) {
      EXPECT_EQ(line, "inf nan nan nan nan nan nan nan nan -1 -1") << "ray " << i;
      continue;
    }
    ++hits_per_object[best_obj];
    EXPECT_EQ(static_cast<int>(v[9]), best_obj) << "ray " << i << ": " << line;
    EXPECT_NEAR(v[0], best, 1e-9 * best) << "ray " << i << " object " << best_obj;
    EXPECT_NEAR(v[4], best_n.x, 1e-9) << "ray " << i << " object " << best_obj;
    EXPECT_NEAR(v[5], best_n.y, 1e-9) << "ray " << i << " object " << best_obj;
    EXPECT_NEAR(v[6], best_n.z, 1e-9) << "ray " << i << " object " << best_obj;
  }
  EXPECT_GT(checked, 3500);
  for (int k = 0; k < 9; ++k) EXPECT_GT(hits_per_object[k], 10) << "object " << k << " rarely hit";
}

}  // namespace

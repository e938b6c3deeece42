// Failure rates of a plain closed-form quartic (textbook Ferrari on the ray's raw coefficients)
// against the torus's isolating solver, on ordinary and grazing rays; and their cost per ray.
// Run: build/release/bench/torus_quartic_bench  (prints a table; no Google Benchmark flags).
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <vector>

#include "geometry/torus.h"

using namespace raycast;

namespace {

// The textbook Ferrari solution: depressed quartic, Cardano for the resolvent cubic, two
// quadratics by the plain formula. No scaling, no polishing: what a first implementation does.
int naive_ferrari(double a, double b, double c, double d, double e, double* roots) {
  const double B = b / a, C = c / a, D = d / a, E = e / a;
  const double p = C - 3 * B * B / 8;
  const double q = D - B * C / 2 + B * B * B / 8;
  const double r = E - B * D / 4 + B * B * C / 16 - 3 * B * B * B * B / 256;
  int n = 0;
  auto quadratic = [&](double qa, double qb, double qc) {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return;
    const double s = std::sqrt(disc);
    roots[n++] = (-qb - s) / (2 * qa) - B / 4;
    roots[n++] = (-qb + s) / (2 * qa) - B / 4;
  };
  if (std::abs(q) < 1e-14) {  // biquadratic
    const double disc = p * p - 4 * r;
    if (disc < 0) return 0;
    for (double z : {(-p - std::sqrt(disc)) / 2, (-p + std::sqrt(disc)) / 2}) {
      if (z < 0) continue;
      roots[n++] = std::sqrt(z) - B / 4;
      roots[n++] = -std::sqrt(z) - B / 4;
    }
    return n;
  }
  // Resolvent m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0: a positive root by Cardano.
  const double a2 = p, a1 = p * p / 4 - r, a0 = -q * q / 8;
  const double Q = (3 * a1 - a2 * a2) / 9, R = (9 * a2 * a1 - 27 * a0 - 2 * a2 * a2 * a2) / 54;
  const double disc = Q * Q * Q + R * R;
  double m;
  if (disc >= 0) {
    const double s = std::sqrt(disc);
    m = std::cbrt(R + s) + std::cbrt(R - s) - a2 / 3;
  } else {
    const double theta = std::acos(R / std::sqrt(-Q * Q * Q));
    m = 2 * std::sqrt(-Q) * std::cos(theta / 3) - a2 / 3;
  }
  if (!(m > 0)) return 0;
  const double s = std::sqrt(2 * m);
  quadratic(1, s, p / 2 + m - q / (2 * s));
  quadratic(1, -s, p / 2 + m + q / (2 * s));
  return n;
}

// The nearest root in [0, inf) by naive Ferrari on the ray's raw quartic in t.
bool naive_intersect(const Torus& s, const Ray& ray, double& t_hit) {
  const Vec3 o = ray.o, d = ray.d;
  const double R2 = s.major_radius * s.major_radius;
  const double dd = dot(d, d), od = dot(o, d), G = dot(o, o) + R2 - s.minor_radius * s.minor_radius;
  const double c4 = dd * dd, c3 = 4 * dd * od;
  const double c2 = 4 * od * od + 2 * dd * G - 4 * R2 * (d.x * d.x + d.y * d.y);
  const double c1 = 4 * od * G - 8 * R2 * (o.x * d.x + o.y * d.y);
  const double c0 = G * G - 4 * R2 * (o.x * o.x + o.y * o.y);
  double r[4];
  const int n = naive_ferrari(c4, c3, c2, c1, c0, r);
  t_hit = kInfinity;
  for (int i = 0; i < n; ++i)
    if (r[i] >= ray.tmin && r[i] < t_hit && std::isfinite(r[i])) t_hit = r[i];
  return t_hit < kInfinity;
}

long double f_ld(const Torus& s, const Ray& r, long double t) {
  const long double x = r.o.x + t * r.d.x, y = r.o.y + t * r.d.y, z = r.o.z + t * r.d.z;
  const long double R2 = (long double)s.major_radius * s.major_radius;
  const long double a = x * x + y * y + z * z + R2 - (long double)s.minor_radius * s.minor_radius;
  return a * a - 4 * R2 * (x * x + y * y);
}

// The exact first root near t0 by long-double bisection on [lo, hi] where f changes sign.
long double bisect_ld(const Torus& s, const Ray& r, long double lo, long double hi) {
  long double flo = f_ld(s, r, lo);
  for (int i = 0; i < 200; ++i) {
    const long double m = 0.5L * (lo + hi);
    if (m <= lo || m >= hi) break;
    const long double fm = f_ld(s, r, m);
    if ((fm < 0) == (flo < 0)) {
      lo = m;
      flo = fm;
    } else {
      hi = m;
    }
  }
  return 0.5L * (lo + hi);
}

struct Tally {
  int rays = 0, missed = 0, inaccurate = 0;
  double worst = 0;
};

void report(const char* what, const char* solver, const Tally& t) {
  std::printf(
      "%-34s %-10s rays %6d  missed %6d (%6.2f%%)  |dt|/t > 1e-6: %6d (%6.2f%%)  worst %.1e\n",
      what, solver, t.rays, t.missed, 100.0 * t.missed / t.rays, t.inaccurate,
      100.0 * t.inaccurate / t.rays, t.worst);
}

}  // namespace

int main() {
  for (double minor : {0.25, 0.02}) {
    const Torus torus = make_torus(1.0, minor);
    for (double distance : {3.0, 30.0, 300.0}) {
      for (double depth : {1e-2, 1e-4, 1e-6, 1e-8}) {
        // Tangent at a random surface point, moved `depth` into the solid, starting `distance`
        // back.
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> u(0, 1);
        Tally naive, ours;
        for (int i = 0; i < 20000; ++i) {
          const double phi = 2 * M_PI * u(rng), theta = 2 * M_PI * u(rng);
          const Vec3 radial{std::cos(phi), std::sin(phi), 0};
          const Vec3 n = std::cos(theta) * radial + Vec3{0, 0, std::sin(theta)};
          const Vec3 p = torus.major_radius * radial + torus.minor_radius * n;
          Vec3 a, b;
          make_frame(n, a, b);
          const double w = 2 * M_PI * u(rng);
          const Vec3 tangent = std::cos(w) * a + std::sin(w) * b;
          const Ray ray{p - depth * n - distance * tangent, tangent};
          // The true first crossing: bisect f from the ray's start to the inside point.
          long double lo = 0;
          // Step forward to bracket the first sign change before the inside point.
          const int steps = 1000 + static_cast<int>(distance) * 20;
          long double truth = -1;
          long double prev = f_ld(torus, ray, 0);
          for (int k = 1; k <= steps; ++k) {
            const long double t = (long double)distance * k / steps;
            const long double f = f_ld(torus, ray, t);
            if ((f < 0) != (prev < 0)) {
              truth = bisect_ld(torus, ray, lo, t);
              break;
            }
            lo = t;
            prev = f;
          }
          if (truth < 0) continue;
          for (int which = 0; which < 2; ++which) {
            Tally& tl = which == 0 ? naive : ours;
            ++tl.rays;
            double t;
            bool hit;
            if (which == 0) {
              hit = naive_intersect(torus, ray, t);
            } else {
              LocalHit h;
              hit = intersect(torus, ray, h);
              t = h.t;
            }
            if (!hit) {
              ++tl.missed;
              continue;
            }
            // A root before the reference's is a close pair the sampling stepped over when the
            // function really vanishes there (checked in long double); it is then correct.
            if (t < (double)truth && std::abs((double)f_ld(torus, ray, t)) < 1e-9) continue;
            const double rel = std::abs(t - (double)truth) / (double)truth;
            if (rel > 1e-6) ++tl.inaccurate;
            if (rel > tl.worst) tl.worst = rel;
          }
        }
        char what[96];
        std::snprintf(what, sizeof what, "r %.2f depth %.0e distance %.0f", minor, depth, distance);
        report(what, "naive", naive);
        report(what, "isolating", ours);
      }
    }
  }
  // Cost per ray on ordinary rays (a random mix of hits and misses).
  const Torus torus = make_torus(1.0, 0.25);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Ray> rays;
  for (int i = 0; i < 200000; ++i) {
    const Vec3 o{4 * u(rng), 4 * u(rng), 4 * u(rng)};
    rays.push_back(Ray{o, Vec3{1.3 * u(rng), 1.3 * u(rng), 0.3 * u(rng)} - o});
  }
  for (int which = 0; which < 2; ++which) {
    // CPU time, not wall time: the machine may be shared.
    const std::clock_t start = std::clock();
    int hits = 0;
    for (const Ray& r : rays) {
      double t;
      LocalHit h;
      hits += which == 0 ? naive_intersect(torus, r, t) : intersect(torus, r, h);
    }
    const double ns = 1e9 * double(std::clock() - start) / CLOCKS_PER_SEC / rays.size();
    std::printf("ordinary rays: %-10s %.1f ns/ray (%d hits of %zu)\n",
                which == 0 ? "naive" : "isolating", ns, hits, rays.size());
  }
  return 0;
}

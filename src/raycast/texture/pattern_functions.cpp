// The raw pattern functions (texture/pattern.h raw_pattern), each written from its definition in
// POV-Ray 3.7's reference: what it is a function of, its period, its range.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "texture/pattern.h"

namespace raycast::texture {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

std::int64_t floor_int(double v) {
  // Far cells (beyond 2^52, or NaN) all land in one: no undefined conversion.
  if (!(std::abs(v) < 0x1p52)) return 0;
  return std::int64_t(std::floor(v));
}

// A well-mixed 64-bit hash of a lattice cell and a salt (splitmix64's finaliser).
std::uint64_t cell_hash(std::int64_t x, std::int64_t y, std::int64_t z, std::uint64_t salt) {
  std::uint64_t h = std::uint64_t(x) * 0x9E3779B97F4A7C15ULL ^
                    std::uint64_t(y) * 0xC2B2AE3D27D4EB4FULL ^
                    std::uint64_t(z) * 0x165667B19E3779F9ULL ^ salt;
  h ^= h >> 30;
  h *= 0xBF58476D1CE4E5B9ULL;
  h ^= h >> 27;
  h *= 0x94D049BB133111EBULL;
  h ^= h >> 31;
  return h;
}
double unit(std::uint64_t h) { return double(h >> 11) * (1.0 / double(1ULL << 53)); }

// Crackle (Worley's cellular texture): one feature point per unit cell; the value is the
// distance to the second nearest minus the distance to the nearest (POV-Ray's default form
// <-1, 1, 0> with metric 2), which is 0 on the cells' borders.
double crackle(const Vec3& p) {
  const std::int64_t cx = floor_int(p.x), cy = floor_int(p.y), cz = floor_int(p.z);
  // Squared distances while searching (the square root is monotone: the same two points).
  double d1 = 1e30, d2 = 1e30;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        const std::uint64_t h = cell_hash(cx + i, cy + j, cz + k, 0xC7AC);
        const Vec3 f{double(cx + i) + unit(h),
                     double(cy + j) + unit(cell_hash(cx + i, cy + j, cz + k, h)),
                     double(cz + k) + unit(h * 0x2545F4914F6CDD1DULL)};
        const double d = length_squared(f - p);
        if (d < d1) {
          d2 = d1;
          d1 = d;
        } else if (d < d2) {
          d2 = d;
        }
      }
  return std::clamp(std::sqrt(d2) - std::sqrt(d1), 0.0, 1.0);
}

// The wave centres of ripples and waves: ten fixed points in the unit cube about the origin.
Vec3 wave_centre(int k) {
  const std::uint64_t h = cell_hash(k, 7 * k + 1, 13 * k + 2, 0x3A7E5);
  return {unit(h) - 0.5, unit(cell_hash(k, 0, 0, h)) - 0.5, unit(cell_hash(0, k, 0, h)) - 0.5};
}

double ripples(const Vec3& p, bool damped) {
  double sum = 0, weights = 0;
  for (int k = 0; k < 10; ++k) {
    const double d = length(p - wave_centre(k));
    const double w = damped ? 1 / (1 + d) : 1;
    sum += w * std::cos(kTwoPi * d);
    weights += w;
  }
  return 0.5 + 0.5 * sum / weights;
}

// Brick: rows of height brick_size.y; bricks along x (and z) shifted half a brick on odd rows;
// 0 in the mortar (width `mortar` about every joint), 1 in a brick.
double brick(const Vec3& p, const Vec3& size, double mortar) {
  const double row = std::floor(p.y / size.y);
  const bool odd = std::fmod(std::abs(row), 2.0) == 1;
  const double x = p.x + (odd ? 0.5 * size.x : 0), z = p.z + (odd ? 0.5 * size.z : 0);
  auto in_mortar = [&](double v, double s) {
    const double f = v - s * std::floor(v / s);
    return f < 0.5 * mortar || f > s - 0.5 * mortar;
  };
  return in_mortar(x, size.x) || in_mortar(p.y, size.y) || in_mortar(z, size.z) ? 0 : 1;
}

// Flat-topped hexagons of side 1 in the x-z plane, coloured 0, 1, 2 so that no two neighbours
// share a value: the nearest centre by cube-coordinate rounding, coloured by (q - r) mod 3.
double hexagon(const Vec3& p) {
  const double q = p.x * (2.0 / 3.0), r = -p.x / 3.0 + p.z / std::sqrt(3.0);
  const double cq = q, cr = r, cs = -q - r;
  double rq = std::round(cq), rr = std::round(cr);
  const double rs = std::round(cs);
  const double dq = std::abs(rq - cq), dr = std::abs(rr - cr), ds = std::abs(rs - cs);
  if (dq > dr && dq > ds)
    rq = -rr - rs;
  else if (dr > ds)
    rr = -rq - rs;
  const double m = std::fmod(rq - rr, 3.0);
  return m < 0 ? m + 3 : m;
}

// Six triangles around each hexagon's centre: the sector (0 to 5) of the point's angle about
// the nearest centre.
double triangular(const Vec3& p) {
  const double s = std::sqrt(3.0);
  // Centres on the lattice (i + j/2, j*sqrt(3)/2): the nearest of the candidates around p.
  const double j0 = std::floor(p.z / (0.5 * s));
  Vec3 best{0, 0, 0};
  double best_d = 1e30;
  for (double j = j0 - 1; j <= j0 + 2; ++j) {
    const double i0 = std::floor(p.x - 0.5 * j);
    for (double i = i0 - 1; i <= i0 + 2; ++i) {
      const Vec3 c{i + 0.5 * j, 0, j * 0.5 * s};
      const double d = (p.x - c.x) * (p.x - c.x) + (p.z - c.z) * (p.z - c.z);
      if (d < best_d) best_d = d, best = c;
    }
  }
  const double a = std::atan2(p.z - best.z, p.x - best.x);  // (-pi, pi]
  const double sector = std::floor((a + std::numbers::pi) / (kTwoPi / 6));
  return std::clamp(sector, 0.0, 5.0);
}

// Spirals about the z axis: the value grows by 1 per unit of radius and by `arms` per turn, so
// a full turn crosses `arms` bands (the same along z).
double spiral(const Vec3& p, double arms, int sign) {
  const double r = std::sqrt(p.x * p.x + p.y * p.y);
  const double theta = std::atan2(p.y, p.x) / kTwoPi;  // turns, in (-0.5, 0.5]
  return r + sign * arms * theta;
}

double quilted(const Vec3& p, double c0, double c1) {
  // 1 at a unit cell's centre, 0 on its faces: the pillows of a quilt.
  auto dist = [](double v) { return std::abs(v - std::floor(v) - 0.5) * 2; };
  const double t = 1 - std::max({dist(p.x), dist(p.y), dist(p.z)});
  // The cubic Bezier from 0 to 1 with the two controls (POV-Ray's control0 and control1).
  const double s = 1 - t;
  return 3 * s * s * t * c0 + 3 * s * t * t * c1 + t * t * t;
}

}  // namespace

double raw_pattern(const Pattern& pt, const Vec3& p) {
  const int g = pt.noise_generator;
  switch (pt.kind) {
    case PatternKind::kAgate: {
      const double turb = turbulence_value(p, 7, 0.5, 2, g);
      const double s = std::sin(kTwoPi * (p.z + pt.amount * turb));
      return std::pow(0.5 + 0.5 * s, 0.77);
    }
    case PatternKind::kBoxed:
      return 1 - std::min(1.0, std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
    case PatternKind::kBozo:
    case PatternKind::kBumps:
    case PatternKind::kSpotted:
      return noise(p, g);
    case PatternKind::kBrick:
      return brick(p, pt.vector, pt.amount);
    case PatternKind::kCells:
      return unit(cell_hash(floor_int(p.x), floor_int(p.y), floor_int(p.z), 0xCE11));
    case PatternKind::kChecker:
      return double((floor_int(p.x) + floor_int(p.y) + floor_int(p.z)) & 1);
    case PatternKind::kCrackle:
      return crackle(p);
    case PatternKind::kCylindrical:
      return 1 - std::min(1.0, std::sqrt(p.x * p.x + p.z * p.z));
    case PatternKind::kDents: {
      const double n = noise(p, g);
      return n * n * n;
    }
    case PatternKind::kImage: {
      // Where the image does not reach (once), POV-Ray's image_pattern reads 0.
      double u = 0, v = 0;
      if (!pt.image || !image_uv(*pt.image, p, u, v)) return 0;
      return std::clamp(image_grey(image_sample(*pt.image, u, v)), 0.0, 1.0);
    }
    case PatternKind::kFunction:
      return function_pattern_value(pt.function.get(), p);
    case PatternKind::kGradient:
      return dot(p, pt.vector);
    case PatternKind::kGranite: {
      double sum = 0, f = 1;
      for (int i = 0; i < 6; ++i, f *= 2) sum += std::abs(noise(4 * f * p, g) - 0.5) / f;
      // Doubled: the octaves' deviations from 0.5 average about 0.15, and granite's colour
      // maps expect values spread over [0, 1].
      return std::min(1.0, 2 * sum);
    }
    case PatternKind::kHexagon:
      return hexagon(p);
    case PatternKind::kLeopard: {
      const double s = std::sin(p.x) + std::sin(p.y) + std::sin(p.z);
      return s * s / 9;
    }
    case PatternKind::kMarble:
      return p.x + pt.turbulence.amount.x * turbulence_value(p, pt.turbulence.octaves,
                                                             pt.turbulence.omega,
                                                             pt.turbulence.lambda, g);
    case PatternKind::kOnion:
      return length(p);
    case PatternKind::kPlanar:
      return 1 - std::min(1.0, std::abs(p.y));
    case PatternKind::kQuilted:
      return quilted(p, pt.amount, pt.amount2);
    case PatternKind::kRadial:
      return std::atan2(p.x, p.z) / kTwoPi + 0.5;
    case PatternKind::kRipples:
      return ripples(p, false);
    case PatternKind::kSpherical:
      return 1 - std::min(1.0, length(p));
    case PatternKind::kSpiral1:
      return spiral(p, pt.amount, 1);
    case PatternKind::kSpiral2: {
      const double a = spiral(p, pt.amount, 1), b = spiral(p, pt.amount, -1);
      return std::abs((a - std::floor(a)) - (b - std::floor(b)));
    }
    case PatternKind::kSquare:
      return double((floor_int(p.x) & 1) + 2 * (floor_int(p.z) & 1));
    case PatternKind::kTriangular:
      return triangular(p);
    case PatternKind::kWaves:
      return ripples(p, true);
    case PatternKind::kWood:
      return std::sqrt(p.x * p.x + p.y * p.y);
    case PatternKind::kWrinkles: {
      double sum = 0, f = 1;
      // Fractal noise: ten octaves of signed noise, each half as strong and twice as fine.
      for (int i = 0; i < 10; ++i, f *= 2) sum += (noise(f * p, g) - 0.5) / f;
      return std::clamp(0.5 + sum, 0.0, 1.0);
    }
  }
  return 0;
}

}  // namespace raycast::texture

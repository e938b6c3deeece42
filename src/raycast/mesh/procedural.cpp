#include "mesh/procedural.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raycast {

namespace {

double bumps(const Vec3& p) {
  return std::sin(5 * p.x + 1) * std::sin(7 * p.y + 2) * std::sin(6 * p.z + 3) +
         0.35 * std::sin(23 * p.x + 17 * p.y) * std::sin(19 * p.z + 0.5);
}

// Appends an octa-sphere to `out`.
void append_octa_sphere(TriangleSoup& out, int n, double displacement, const Vec3& centre,
                        double radius) {
  const int side = 2 * n + 1;
  // Lattice points (i, j, k) with |i| + |j| + |k| = n; two per (i, j) (k > 0 and k < 0) or one.
  std::vector<std::uint32_t> index(static_cast<std::size_t>(side) * side * 2, 0);
  auto slot = [&](int i, int j, int k) -> std::uint32_t& {
    return index[(static_cast<std::size_t>(i + n) * side + (j + n)) * 2 + (k < 0 ? 1 : 0)];
  };
  for (int i = -n; i <= n; ++i)
    for (int j = -(n - std::abs(i)); j <= n - std::abs(i); ++j) {
      const int kk = n - std::abs(i) - std::abs(j);
      for (int k : {kk, -kk}) {
        const Vec3 dir = normalize(Vec3{double(i), double(j), double(k)});
        const double r = radius * (1 + displacement * bumps(dir));
        slot(i, j, k) = static_cast<std::uint32_t>(out.positions.size());
        out.positions.push_back(Vec3f(centre + r * dir));
        if (kk == 0) break;
      }
    }
  auto add = [&](int a0, int b0, int c0, int a1, int b1, int c1, int a2, int b2, int c2) {
    // Wind counter-clockwise seen from outside (checked on the undisplaced lattice).
    const Vec3 p0{double(a0), double(b0), double(c0)}, p1{double(a1), double(b1), double(c1)},
        p2{double(a2), double(b2), double(c2)};
    std::array<std::uint32_t, 3> t{slot(a0, b0, c0), slot(a1, b1, c1), slot(a2, b2, c2)};
    if (dot(cross(p1 - p0, p2 - p0), p0 + p1 + p2) < 0) std::swap(t[1], t[2]);
    out.triangles.push_back(t);
  };
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sz : {1, -1})
        for (int a = 0; a < n; ++a)
          for (int b = 0; b < n - a; ++b) {
            const int c = n - a - b;
            add(sx * a, sy * b, sz * c, sx * (a + 1), sy * b, sz * (c - 1), sx * a, sy * (b + 1),
                sz * (c - 1));
            if (b < n - a - 1)
              add(sx * (a + 1), sy * b, sz * (c - 1), sx * (a + 1), sy * (b + 1), sz * (c - 2),
                  sx * a, sy * (b + 1), sz * (c - 1));
          }
}

double terrain_height(double x, double y) {
  return 0.15 * std::sin(0.7 * x + 0.3) * std::cos(0.5 * y) + 0.05 * std::sin(2.3 * x + 1.7 * y);
}

std::uint32_t hash(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

double unit(std::uint32_t h) { return (h >> 8) * (1.0 / 16777216.0); }

}  // namespace

TriangleSoup make_octa_sphere(int n, double displacement, const Vec3& centre, double radius) {
  TriangleSoup out;
  append_octa_sphere(out, std::max(n, 1), displacement, centre, radius);
  return out;
}

TriangleSoup make_procedural_mesh(const std::string& name, std::size_t triangles) {
  if (triangles < 8 || triangles > (std::size_t(1) << 31))
    throw std::invalid_argument("the triangle count must be in [8, 2^31]");
  TriangleSoup out;
  if (name == "sphere") {
    const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(triangles / 8.0))));
    out.positions.reserve(4 * std::size_t(n) * n + 2);
    out.triangles.reserve(8 * std::size_t(n) * n);
    append_octa_sphere(out, n, 0.05, {0, 0, 0}, 1);
    return out;
  }
  if (name == "forest") {
    // Terrain: a g x g grid of quads over [-L, L]^2 in x, y (z up), two triangles each.
    const double extent = 10;
    const int g = std::max(1, static_cast<int>(std::sqrt(triangles / 20.0)));
    for (int j = 0; j <= g; ++j)
      for (int i = 0; i <= g; ++i) {
        const double x = -extent + 2 * extent * i / g, y = -extent + 2 * extent * j / g;
        out.positions.push_back(Vec3f(Vec3{x, y, terrain_height(x, y)}));
      }
    for (int j = 0; j < g; ++j)
      for (int i = 0; i < g; ++i) {
        const std::uint32_t a = j * (g + 1) + i, b = a + 1, c = a + g + 1, d = c + 1;
        out.triangles.push_back({a, b, d});
        out.triangles.push_back({a, d, c});
      }
    // Trees: octa-spheres of 8 n^2 triangles (n = 16: 2048 each) on a jittered grid.
    const std::size_t left =
        triangles > out.triangles.size() ? triangles - out.triangles.size() : 0;
    const int n = 16;
    const std::size_t trees = std::max<std::size_t>(1, left / (8 * n * n));
    const int cells = static_cast<int>(std::ceil(std::sqrt(double(trees))));
    const double cell = 2 * extent / cells;
    for (std::size_t t = 0; t < trees; ++t) {
      const int ci = static_cast<int>(t % cells), cj = static_cast<int>(t / cells);
      const auto h = hash(static_cast<std::uint32_t>(t) * 2654435761u + 12345u);
      const double r = cell * (0.25 + 0.2 * unit(hash(h)));
      const double x = -extent + cell * (ci + 0.5) + (unit(hash(h + 1)) - 0.5) * 0.3 * cell;
      const double y = -extent + cell * (cj + 0.5) + (unit(hash(h + 2)) - 0.5) * 0.3 * cell;
      append_octa_sphere(out, n, 0.15, {x, y, terrain_height(x, y) + 0.8 * r}, r);
    }
    return out;
  }
  throw std::invalid_argument("unknown procedural mesh '" + name + "' (expected sphere or forest)");
}

}  // namespace raycast

#include "geometry/polyhedron.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace raycast {

namespace {

using Plane4 = std::array<double, 4>;

Vec3 normal_of(const Plane4& p) { return {p[0], p[1], p[2]}; }

// Solves the k x k system A x = b (k <= 4) by Gaussian elimination with partial pivoting;
// false when singular (a pivot below kSingular relative to the row scale of unit normals).
bool solve(int k, double a[4][5], double x[4]) {
  constexpr double kSingular = 1e-12;
  for (int c = 0; c < k; ++c) {
    int piv = c;
    for (int r = c + 1; r < k; ++r)
      if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
    if (!(std::abs(a[piv][c]) > kSingular)) return false;
    for (int j = 0; j <= k; ++j) std::swap(a[c][j], a[piv][j]);
    for (int r = c + 1; r < k; ++r) {
      const double f = a[r][c] / a[c][c];
      for (int j = c; j <= k; ++j) a[r][j] -= f * a[c][j];
    }
  }
  for (int r = k - 1; r >= 0; --r) {
    double s = a[r][k];
    for (int j = r + 1; j < k; ++j) s -= a[r][j] * x[j];
    x[r] = s / a[r][r];
  }
  return true;
}

// An orthonormal basis of the span of the normals (rank 1 to 3), by Gram-Schmidt.
int normal_basis(const std::vector<Plane4>& planes, Vec3 basis[3]) {
  constexpr double kIndependent = 1e-9;  // smallest residual of a unit normal that adds a direction
  int k = 0;
  for (const Plane4& p : planes) {
    Vec3 v = normal_of(p);
    for (int i = 0; i < k; ++i) v -= dot(v, basis[i]) * basis[i];
    const double len = length(v);
    if (len > kIndependent) basis[k++] = v / len;
    if (k == 3) break;
  }
  return k;
}

// The Chebyshev-centre linear program: the largest s (capped at `cap`) with n_i . p + s <= -d_i
// for all i, p restricted to the normals' span (so the feasible set is pointed and the optimum
// is a vertex). Enumerates every vertex: subsets of k + 1 constraints.
double largest_inscribed_radius(const std::vector<Plane4>& planes, double cap, double tol) {
  Vec3 basis[3];
  const int k = normal_basis(planes, basis);
  const int dim = k + 1, m = static_cast<int>(planes.size()) + 1;
  // Row i: coefficients over (alpha_0..alpha_{k-1}, s) and right-hand side; the last row s <= cap.
  std::vector<std::array<double, 5>> rows(m);
  for (int i = 0; i + 1 < m; ++i) {
    for (int j = 0; j < k; ++j) rows[i][j] = dot(normal_of(planes[i]), basis[j]);
    rows[i][k] = 1;
    rows[i][4] = -planes[i][3];
  }
  rows[m - 1] = {0, 0, 0, 0, cap};
  rows[m - 1][k] = 1;
  double best = -kInfinity;
  int idx[4];
  for (int i = 0; i < dim; ++i) idx[i] = i;
  while (true) {
    double a[4][5], x[4] = {};
    for (int r = 0; r < dim; ++r) {
      for (int c = 0; c < dim; ++c) a[r][c] = rows[idx[r]][c];
      a[r][dim] = rows[idx[r]][4];
    }
    if (solve(dim, a, x) && x[k] > best) {
      bool feasible = true;
      for (int i = 0; i < m && feasible; ++i) {
        double lhs = 0;
        for (int c = 0; c < dim; ++c) lhs += rows[i][c] * x[c];
        feasible = lhs <= rows[i][4] + tol;
      }
      if (feasible) best = x[k];
    }
    // Next combination of dim indices out of m.
    int p = dim - 1;
    while (p >= 0 && idx[p] == m - dim + p) --p;
    if (p < 0) break;
    ++idx[p];
    for (int q = p + 1; q < dim; ++q) idx[q] = idx[q - 1] + 1;
  }
  return best;
}

// The unit directions q along some n_i x n_j with n . q <= 0 for every plane: when the normals
// span space, these include every edge of the recession cone, so the polyhedron is bounded
// exactly when there are none. Holds for empty sets too (the cone is theirs).
std::vector<Vec3> receding_directions(const std::vector<Plane4>& planes) {
  constexpr double kRecession = 1e-9;  // a direction this close to feasible counts as receding
  std::vector<Vec3> out;
  const std::size_t m = planes.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j) {
      const Vec3 q = cross(normal_of(planes[i]), normal_of(planes[j]));
      const double len = length(q);
      if (!(len > 1e-12)) continue;
      for (double sign : {1.0, -1.0}) {
        bool recedes = true;
        for (std::size_t l = 0; l < m && recedes; ++l)
          recedes = sign * dot(normal_of(planes[l]), q) / len <= kRecession;
        if (recedes) out.push_back((sign / len) * q);
      }
    }
  return out;
}

// Every point where three planes meet that satisfies all planes to within tol: O(n^3) systems.
std::vector<Vec3> feasible_vertices(const std::vector<Plane4>& planes, double tol) {
  std::vector<Vec3> out;
  const std::size_t m = planes.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t l = j + 1; l < m; ++l) {
        double a[4][5], x[4] = {};
        const std::size_t id[3] = {i, j, l};
        for (int r = 0; r < 3; ++r) {
          for (int c = 0; c < 3; ++c) a[r][c] = planes[id[r]][c];
          a[r][3] = -planes[id[r]][3];
        }
        if (!solve(3, a, x)) continue;
        const Vec3 v{x[0], x[1], x[2]};
        bool feasible = true;
        for (std::size_t q = 0; q < m && feasible; ++q)
          feasible = dot(normal_of(planes[q]), v) + planes[q][3] <= tol;
        if (feasible) out.push_back(v);
      }
  return out;
}

// The smallest slack -(n_i . c + d_i) over the planes: > 0 when c is strictly inside.
double slack(const std::vector<Plane4>& planes, const Vec3& c) {
  double s = kInfinity;
  for (const Plane4& q : planes) s = std::min(s, -(dot(normal_of(q), c) + q[3]));
  return s;
}

}  // namespace

Polyhedron make_polyhedron(const std::vector<std::array<double, 4>>& given) {
  if (given.empty()) throw std::invalid_argument("needs at least 1 plane");
  if (given.size() > kMaxPolyhedronPlanes)
    throw std::invalid_argument("has " + std::to_string(given.size()) + " planes; at most " +
                                std::to_string(kMaxPolyhedronPlanes) + " are supported");
  Polyhedron p;
  double scale = 1;
  for (std::size_t i = 0; i < given.size(); ++i) {
    const Plane4& g = given[i];
    const double len = length(normal_of(g));
    if (!std::isfinite(g[3]) || !(len > 0) || !std::isfinite(len))
      throw std::invalid_argument("planes[" + std::to_string(i) +
                                  "] must be finite with a non-zero normal");
    p.planes.push_back({g[0] / len, g[1] / len, g[2] / len, g[3] / len});
    scale = std::max(scale, std::abs(g[3] / len));
  }
  const double tol = kPolyhedronTolerance * scale;
  const char* kEmpty = "is empty: no point is strictly inside every plane";
  Vec3 basis[3];
  if (normal_basis(p.planes, basis) < 3) {
    // Normals in a plane or along a line (a prism, a slab): the linear program is small here.
    if (!(largest_inscribed_radius(p.planes, scale, tol) > tol))
      throw std::invalid_argument(kEmpty);
    return p;
  }
  // A pointed polyhedron is conv(vertices) + cone(receding directions); when it has an interior,
  // a combination with positive weights on all of them lies strictly inside. O(n^3).
  const std::vector<Vec3> vertices = feasible_vertices(p.planes, tol);
  if (vertices.empty()) throw std::invalid_argument(kEmpty);
  const std::vector<Vec3> rays = receding_directions(p.planes);
  Vec3 c;
  Aabb b;
  for (const Vec3& v : vertices) {
    c += v;
    b.grow(v);
  }
  c /= static_cast<double>(vertices.size());
  for (const Vec3& r : rays) c += r / static_cast<double>(rays.size());
  if (!(slack(p.planes, c) > tol)) throw std::invalid_argument(kEmpty);
  if (rays.empty()) {
    const Vec3 pad = Vec3{tol, tol, tol} + 1e-9 * (abs(b.lo) + abs(b.hi));
    p.hull = {b.lo - pad, b.hi + pad};
  }
  return p;
}

Aabb bounds(const Polyhedron& p) { return p.hull; }

namespace {

struct Crossings {
  double t_in = -kInfinity, t_out = kInfinity;
  int part_in = kNoSurface, part_out = kNoSurface;
};

// Kay-Kajiya over the planes: t_in is the largest entry, t_out the smallest exit; stops as
// soon as t_in > t_out or the interval leaves [lo, hi].
bool crossings(const Polyhedron& p, const Vec3& o, const Vec3& d, double lo, double hi,
               Crossings& c) {
  for (std::size_t i = 0; i < p.planes.size(); ++i) {
    const auto& q = p.planes[i];
    const double nd = q[0] * d.x + q[1] * d.y + q[2] * d.z;
    const double dist = q[0] * o.x + q[1] * o.y + q[2] * o.z + q[3];
    if (nd == 0) {
      if (dist > 0) return false;  // parallel and outside this plane
      continue;
    }
    const double t = -dist / nd;
    if (nd < 0) {
      if (t > c.t_in) c.t_in = t, c.part_in = static_cast<int>(i);
    } else if (t < c.t_out) {
      c.t_out = t, c.part_out = static_cast<int>(i);
    }
    if (c.t_in > c.t_out || c.t_out < lo || c.t_in > hi) return false;
  }
  return true;
}

}  // namespace

bool intersect(const Polyhedron& p, const Ray& ray, LocalHit& hit) {
  Crossings c;
  if (!crossings(p, ray.o, ray.d, ray.tmin, ray.tmax, c)) return false;
  if (c.t_in >= ray.tmin && c.part_in != kNoSurface) {
    hit = LocalHit{.t = c.t_in, .part = c.part_in};
    return true;
  }
  if (c.t_out <= ray.tmax && c.part_out != kNoSurface) {
    hit = LocalHit{.t = c.t_out, .part = c.part_out};
    return true;
  }
  return false;
}

bool occluded(const Polyhedron& p, const Ray& ray) {
  LocalHit h;
  return intersect(p, ray, h);
}

void spans(const Polyhedron& p, const Ray& ray, SpanList& out) {
  Crossings c;
  if (!crossings(p, ray.o, ray.d, -kInfinity, kInfinity, c)) return;
  out.add(LocalHit{.t = c.t_in, .part = c.part_in}, LocalHit{.t = c.t_out, .part = c.part_out});
}

SurfaceInfo surface(const Polyhedron& p, const Ray& ray, const LocalHit& hit) {
  SurfaceInfo si;
  const auto& q = p.planes[static_cast<std::size_t>(hit.part)];
  const Vec3 n = normal_of(q);
  Vec3 x = ray.at(hit.t);
  x -= (dot(n, x) + q[3]) * n;  // onto the plane
  si.p = x;
  si.p_error = gamma(8) * abs(x) + gamma(4) * std::abs(q[3]) * abs(n);
  si.n = n;
  si.shading_n = n;
  return si;
}

bool contains(const Polyhedron& p, const Vec3& x) {
  for (const auto& q : p.planes)
    if (q[0] * x.x + q[1] * x.y + q[2] * x.z + q[3] > 0) return false;
  return true;
}

}  // namespace raycast

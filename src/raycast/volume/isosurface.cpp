#include "volume/isosurface.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/clipped_solid.h"
#include "math/quadratic.h"

namespace raycast {

namespace {

// Bisection and Newton steps of the bracketed cubic solver: 64 halvings reach the last bit of a
// double bracket; the rest is Newton's quick convergence.
constexpr int kMaxSolverSteps = 100;

// The ray in grid index space: node (i, j, k) at integer coordinates, cells are unit cubes.
struct GridRay {
  Vec3 q;  // (o - lo) / cell
  Vec3 d;  // d / cell
};

GridRay grid_ray(const ScalarGrid& g, const Ray& ray) {
  GridRay r;
  for (int a = 0; a < 3; ++a) {
    r.q[a] = (ray.o[a] - g.lo[a]) / g.cell[a];
    r.d[a] = ray.d[a] / g.cell[a];
  }
  return r;
}

// A cubic g(s) = ((c3 s + c2) s + c1) s + c0 along the ray in one cell, s = t - t0.
struct Cubic {
  double c0, c1, c2, c3;
  double operator()(double s) const { return ((c3 * s + c2) * s + c1) * s + c0; }
  double slope(double s) const { return (3 * c3 * s + 2 * c2) * s + c1; }
};

// The trilinear field minus iso along the ray inside cell (i, j, k), about t0 (Parker et al. 1998:
// interpolate along w, then v, then u, each step a product of linear factors in s).
Cubic cell_cubic(const ScalarGrid& g, double iso, const GridRay& r, const int c[3], double t0,
                 float corner[8]) {
  double a[3], b[3];
  for (int k = 0; k < 3; ++k) {
    a[k] = r.q[k] + t0 * r.d[k] - c[k];  // local coordinate at s = 0
    b[k] = r.d[k];                       // its rate
  }
  // Along w: for each (u, v) corner pair, a linear e + s f.
  double e[2][2], f[2][2];
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const double v0 = corner[(0 * 2 + j) * 2 + i], v1 = corner[(1 * 2 + j) * 2 + i];
      e[j][i] = v0 + a[2] * (v1 - v0);
      f[j][i] = b[2] * (v1 - v0);
    }
  // Along v: for each u, a quadratic p0 + p1 s + p2 s^2.
  double p[2][3];
  for (int i = 0; i < 2; ++i) {
    const double de = e[1][i] - e[0][i], df = f[1][i] - f[0][i];
    p[i][0] = e[0][i] + a[1] * de;
    p[i][1] = f[0][i] + a[1] * df + b[1] * de;
    p[i][2] = b[1] * df;
  }
  // Along u: the cubic.
  const double d0 = p[1][0] - p[0][0], d1 = p[1][1] - p[0][1], d2 = p[1][2] - p[0][2];
  Cubic cu;
  cu.c0 = p[0][0] + a[0] * d0 - iso;
  cu.c1 = p[0][1] + a[0] * d1 + b[0] * d0;
  cu.c2 = p[0][2] + a[0] * d2 + b[0] * d1;
  cu.c3 = b[0] * d2;
  (void)g;
  return cu;
}

void load_corners(const ScalarGrid& g, const int c[3], float out[8]) {
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) out[(k * 2 + j) * 2 + i] = g.at(c[0] + i, c[1] + j, c[2] + k);
}

// The root of g in [lo, hi] where g's sign class (g > 0) differs at the two ends and g is
// monotone: Newton's method safeguarded by bisection, to the last bit.
double bracketed_root(const Cubic& g, double lo, double hi) {
  const bool lo_in = g(lo) > 0;
  double s = 0.5 * (lo + hi);
  for (int k = 0; k < kMaxSolverSteps; ++k) {
    const double gs = g(s);
    if (gs == 0) return s;
    if ((gs > 0) == lo_in)
      lo = s;
    else
      hi = s;
    const double slope = g.slope(s);
    double next = slope != 0 ? s - gs / slope : lo;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == s || next <= lo || next >= hi) break;
    s = next;
  }
  return std::abs(g(lo)) < std::abs(g(hi)) ? lo : hi;
}

// Amanatides and Woo 1987: visits the cells of size `scale` (in index units) that the ray crosses
// for t in [ta, tb], in order, within the inclusive index box [lo, hi]; visit(idx, t0, t1) returns
// false to stop (then dda returns false).
template <class Visit>
bool dda(const GridRay& r, int scale, const int lo[3], const int hi[3], double ta, double tb,
         Visit&& visit) {
  int idx[3], step[3];
  double next[3];
  auto boundary = [&](int a) {
    if (step[a] == 0) return kInfinity;
    const double plane = double(step[a] > 0 ? idx[a] + 1 : idx[a]) * scale;
    return (plane - r.q[a]) / r.d[a];
  };
  for (int a = 0; a < 3; ++a) {
    const double x = (r.q[a] + ta * r.d[a]) / scale;
    const double fl = std::floor(x);
    idx[a] = fl < lo[a] ? lo[a] : (fl > hi[a] ? hi[a] : static_cast<int>(fl));
    step[a] = r.d[a] > 0 ? 1 : (r.d[a] < 0 ? -1 : 0);
    next[a] = boundary(a);
  }
  double t = ta;
  for (;;) {
    const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
    const double end = std::max(t, std::min(next[a], tb));
    if (!visit(idx, t, end)) return false;
    if (!(next[a] < tb)) return true;
    t = end;
    idx[a] += step[a];
    if (idx[a] < lo[a] || idx[a] > hi[a]) return true;
    next[a] = boundary(a);
  }
}

// The walk of one line through the grid: the inside/outside state carried from cell to cell, so
// that crossings alternate even where two cells' rounded cubics disagree at their shared face.
template <class Emit>
class Walker {
 public:
  Walker(const IsoData& d, const Ray& ray, bool skip, Emit& emit)
      : d_(d), g_(d.grid), r_(grid_ray(d.grid, ray)), skip_(skip), emit_(emit) {}

  // Returns false when emit asked to stop.
  bool run(const BoxChord& chord, double ta, double tb) {
    at_entry_ = ta == chord.t0;
    entry_face_ = chord.face0;
    inside_ = false;
    fresh_ = true;
    const int cells[3] = {g_.n[0] - 2, g_.n[1] - 2, g_.n[2] - 2};
    const int zero[3] = {0, 0, 0};
    bool go;
    if (skip_) {
      const int macro_hi[3] = {d_.macro_n[0] - 1, d_.macro_n[1] - 1, d_.macro_n[2] - 1};
      go = dda(r_, kMacroCell, zero, macro_hi, ta, tb, [&](const int m[3], double t0, double t1) {
        const std::size_t mi =
            (std::size_t(m[2]) * d_.macro_n[1] + m[1]) * std::size_t(d_.macro_n[0]) + m[0];
        const double mn = d_.macro_min[mi], mx = d_.macro_max[mi];
        if (mx <= d_.iso) return uniform(false, t0);
        if (mn > d_.iso) return uniform(true, t0);
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
          lo[a] = m[a] * kMacroCell;
          hi[a] = std::min(lo[a] + kMacroCell - 1, cells[a]);
        }
        return dda(r_, 1, lo, hi, t0, t1,
                   [&](const int c[3], double s0, double s1) { return cell(c, s0, s1); });
      });
    } else {
      go = dda(r_, 1, zero, cells, ta, tb,
               [&](const int c[3], double s0, double s1) { return cell(c, s0, s1); });
    }
    if (!go) return false;
    if (tb == chord.t1 && inside_) {
      IsoCrossing x;
      x.hit = LocalHit{chord.t1, -1, kFacePart + chord.face1, 0, 0};
      x.entering = false;
      inside_ = false;
      return emit_(x);
    }
    return true;
  }

 private:
  // A crossing at t0 where the state carried in differs from the class found at t0.
  bool reconcile(bool cls, double t0, double cell_index) {
    const bool was_fresh = fresh_;
    fresh_ = false;
    if (cls == inside_) return true;
    if (was_fresh && !at_entry_) {  // the walk starts inside the grid: take the state as found
      inside_ = cls;
      return true;
    }
    inside_ = cls;
    IsoCrossing x;
    x.entering = cls;
    if (was_fresh)
      x.hit = LocalHit{t0, -1, kFacePart + entry_face_, 0, 0};
    else
      x.hit = LocalHit{t0, -1, kCurvedPart, 0, cell_index};
    return emit_(x);
  }

  bool uniform(bool cls, double t0) { return reconcile(cls, t0, 0); }

  bool cell(const int c[3], double t0, double t1) {
    float corner[8];
    load_corners(g_, c, corner);
    const double ci = double(g_.index(c[0], c[1], c[2]));
    if (skip_) {
      const float mn = *std::min_element(corner, corner + 8);
      const float mx = *std::max_element(corner, corner + 8);
      if (mx <= d_.iso) return uniform(false, t0);
      if (mn > d_.iso) return uniform(true, t0);
    }
    const Cubic g = cell_cubic(g_, d_.iso, r_, c, t0, corner);
    if (!reconcile(g(0) > 0, t0, ci)) return false;
    const double len = t1 - t0;
    if (!(len > 0)) return true;
    // Marmitt et al. 2004: split [0, len] at the roots of g' so that g is monotone on each piece.
    double split[4];
    int n = 0;
    split[n++] = 0;
    double r0, r1;
    const int nr = solve_quadratic(3 * g.c3, 2 * g.c2, g.c1, r0, r1);
    if (nr >= 1 && r0 > 0 && r0 < len) split[n++] = r0;
    if (nr >= 2 && r1 > 0 && r1 < len && r1 > split[n - 1]) split[n++] = r1;
    split[n++] = len;
    double bound = std::abs(d_.iso);
    for (float v : corner) bound = std::max(bound, double(std::abs(v)));
    bound *= gamma(24);
    for (int i = 0; i + 1 < n; ++i) {
      const double b = split[i + 1];
      const bool cls = g(b) > 0;
      if (cls == inside_) continue;
      const double s = bracketed_root(g, split[i], b);
      const double slope = std::abs(g.slope(s));
      IsoCrossing x;
      x.entering = cls;
      x.hit = LocalHit{t0 + s, -1, kCurvedPart, slope > 0 ? std::min(bound / slope, len) : len, ci};
      x.hit.a += 2 * kMachineEpsilon * std::abs(t0 + s);
      inside_ = cls;
      if (!emit_(x)) return false;
    }
    return true;
  }

  const IsoData& d_;
  const ScalarGrid& g_;
  GridRay r_;
  bool skip_;
  Emit& emit_;
  bool inside_ = false, fresh_ = true, at_entry_ = false;
  int entry_face_ = -1;
};

// Calls emit(IsoCrossing) for each crossing with t in [ta, tb] (clipped to the grid), in order.
template <class Emit>
void walk(const IsoData& d, const Ray& ray, double ta, double tb, bool skip, Emit&& emit) {
  BoxChord chord;
  if (!box_chord(d.grid.box(), ray, chord)) return;
  const double lo = std::max(ta, chord.t0), hi = std::min(tb, chord.t1);
  if (!(lo <= hi)) return;
  Walker<std::remove_reference_t<Emit>> w(d, ray, skip, emit);
  w.run(chord, lo, hi);
}

// The cell holding a hit (its linear index in b), clamped to the grid.
void cell_of(const ScalarGrid& g, double b, int c[3]) {
  auto i = static_cast<std::size_t>(b);
  c[0] = int(i % std::size_t(g.n[0]));
  i /= std::size_t(g.n[0]);
  c[1] = int(i % std::size_t(g.n[1]));
  c[2] = int(i / std::size_t(g.n[1]));
  for (int a = 0; a < 3; ++a) c[a] = std::clamp(c[a], 0, g.n[a] - 2);
}

}  // namespace

Isosurface make_isosurface(ScalarGrid grid, double iso) {
  if (!std::isfinite(iso) || iso < 0)
    throw std::invalid_argument("iso must be finite and >= 0, got " + std::to_string(iso));
  for (int a = 0; a < 3; ++a) {
    if (grid.n[a] < 2) throw std::invalid_argument("a grid needs at least 2 nodes per axis");
    if (!(grid.cell[a] > 0) || !std::isfinite(grid.cell[a]) || !std::isfinite(grid.lo[a]))
      throw std::invalid_argument("the grid's spacing must be finite and > 0");
  }
  if (grid.v.size() != std::size_t(grid.n[0]) * grid.n[1] * grid.n[2])
    throw std::invalid_argument("the grid's value count does not match its dimensions");
  for (float v : grid.v)
    if (!std::isfinite(v)) throw std::invalid_argument("the grid holds a value that is not finite");
  auto d = std::make_shared<IsoData>();
  d->iso = iso;
  for (int a = 0; a < 3; ++a) d->macro_n[a] = (grid.n[a] - 2) / kMacroCell + 1;
  const std::size_t count = std::size_t(d->macro_n[0]) * d->macro_n[1] * d->macro_n[2];
  d->macro_min.assign(count, kInfinity);
  d->macro_max.assign(count, -kInfinity);
  // Each node belongs to the macro-cells of every cell it is a corner of.
  for (int k = 0; k < grid.n[2]; ++k)
    for (int j = 0; j < grid.n[1]; ++j)
      for (int i = 0; i < grid.n[0]; ++i) {
        const float v = grid.at(i, j, k);
        const int idx[3] = {i, j, k};
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
          // cells i - 1 and i (those that exist), then their macro-cells
          const int c0 = std::max(idx[a] - 1, 0), c1 = std::min(idx[a], grid.n[a] - 2);
          lo[a] = c0 / kMacroCell;
          hi[a] = c1 / kMacroCell;
        }
        for (int mz = lo[2]; mz <= hi[2]; ++mz)
          for (int my = lo[1]; my <= hi[1]; ++my)
            for (int mx = lo[0]; mx <= hi[0]; ++mx) {
              const std::size_t m = (std::size_t(mz) * d->macro_n[1] + my) * d->macro_n[0] + mx;
              d->macro_min[m] = std::min(d->macro_min[m], v);
              d->macro_max[m] = std::max(d->macro_max[m], v);
            }
      }
  for (int mz = 0; mz < d->macro_n[2]; ++mz)
    for (int my = 0; my < d->macro_n[1]; ++my)
      for (int mx = 0; mx < d->macro_n[0]; ++mx) {
        const std::size_t m = (std::size_t(mz) * d->macro_n[1] + my) * d->macro_n[0] + mx;
        if (!(d->macro_max[m] > iso)) continue;
        const int mi[3] = {mx, my, mz};
        Aabb b;
        for (int a = 0; a < 3; ++a) {
          b.lo[a] = grid.lo[a] + double(mi[a] * kMacroCell) * grid.cell[a];
          b.hi[a] =
              grid.lo[a] + double(std::min((mi[a] + 1) * kMacroCell, grid.n[a] - 1)) * grid.cell[a];
        }
        d->inside_bounds.grow(b);
      }
  if (d->inside_bounds.is_empty()) d->inside_bounds = grid.box();
  d->grid = std::move(grid);
  return Isosurface{std::move(d)};
}

std::vector<IsoCrossing> iso_crossings(const IsoData& d, const Ray& ray, double ta, double tb,
                                       bool skip_empty) {
  std::vector<IsoCrossing> out;
  walk(d, ray, ta, tb, skip_empty, [&](const IsoCrossing& x) {
    out.push_back(x);
    return true;
  });
  return out;
}

Aabb bounds(const Isosurface& s) { return s.data->inside_bounds; }

bool intersect(const Isosurface& s, const Ray& ray, LocalHit& hit) {
  bool found = false;
  walk(*s.data, ray, ray.tmin, ray.tmax, true, [&](const IsoCrossing& x) {
    if (x.hit.t < ray.tmin || x.hit.t > ray.tmax) return true;
    hit = x.hit;
    found = true;
    return false;
  });
  return found;
}

bool occluded(const Isosurface& s, const Ray& ray) {
  LocalHit h;
  return intersect(s, ray, h);
}

void spans(const Isosurface& s, const Ray& ray, SpanList& out) {
  bool open = false;
  LocalHit in;
  walk(*s.data, ray, -kInfinity, kInfinity, true, [&](const IsoCrossing& x) {
    if (x.entering) {
      in = x.hit;
      open = true;
    } else if (open) {
      out.add(in, x.hit);
      open = false;
    }
    return true;
  });
}

SurfaceInfo surface(const Isosurface& s, const Ray& ray, const LocalHit& hit) {
  const ScalarGrid& g = s.data->grid;
  SurfaceInfo si;
  Vec3 p = ray.at(hit.t);
  if (hit.part >= kFacePart) {
    const int face = hit.part - kFacePart;
    const Aabb box = g.box();
    p[face / 2] = face % 2 ? box.hi[face / 2] : box.lo[face / 2];
    si.n = box_face_normal(face);
    si.p_error = gamma(4) * abs(p);
  } else {
    int c[3];
    cell_of(g, hit.b, c);
    float corner[8];
    load_corners(g, c, corner);
    double w[3];
    for (int a = 0; a < 3; ++a) w[a] = std::clamp((p[a] - g.lo[a]) / g.cell[a] - c[a], 0.0, 1.0);
    // The seed's gradient of the trilinear field: d/dx of the weights, over the cell's size.
    Vec3 grad;
    double f = 0;
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const double v = corner[(k * 2 + j) * 2 + i];
          const double wu = i ? w[0] : 1 - w[0], wv = j ? w[1] : 1 - w[1], ww = k ? w[2] : 1 - w[2];
          grad.x += (i ? 1 : -1) * wv * ww * v / g.cell.x;
          grad.y += (j ? 1 : -1) * wu * ww * v / g.cell.y;
          grad.z += (k ? 1 : -1) * wu * wv * v / g.cell.z;
          f += wu * wv * ww * v;
        }
    const double gl = length(grad);
    // The normal points out of the solid {field > iso}: against the gradient.
    si.n = gl > 0 && std::isfinite(gl) ? -grad / gl : -normalize(ray.d);
    si.p_error = gamma(16) * abs(p) + hit.a * abs(ray.d);
    const double dist = 2 * std::abs(f - s.data->iso) / gl;
    if (std::isfinite(dist)) si.p_error += dist * abs(si.n);
  }
  si.shading_n = si.n;
  si.p = p;
  return si;
}

bool contains(const Isosurface& s, const Vec3& p) { return sample(s.data->grid, p) > s.data->iso; }

}  // namespace raycast

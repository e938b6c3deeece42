#include "mesh/height_field.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace raycast {

namespace {

using HfIndex = std::uint32_t;

// A vertex normal as POV-Ray forms it: the mean of the unit normals of the four triangles that
// the vertex makes with its neighbours along x and z, in the grid's own units (a column per
// step, 65536 per unit of height), brought to the unit square by the inverse transpose of the
// scaling.
Vec3 hf_grid_normal(const HeightGrid& g, int i, int j) {
  auto at = [&](int a, int b) {
    return Vec3{double(a), g.y[std::size_t(b) * std::size_t(g.width) + std::size_t(a)] * 65536.0,
                double(b)};
  };
  auto inside = [&](int a, int b) { return a >= 0 && b >= 0 && a < g.width && b < g.depth; };
  const int di[4] = {1, 0, -1, 0}, dj[4] = {0, 1, 0, -1};
  const Vec3 p = at(i, j);
  Vec3 sum{0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const int k2 = (k + 1) % 4;
    if (!inside(i + di[k], j + dj[k]) || !inside(i + di[k2], j + dj[k2])) continue;
    Vec3 n = cross(at(i + di[k2], j + dj[k2]) - p, at(i + di[k], j + dj[k]) - p);
    if (n.y < 0) n = -n;
    sum += normalize(n);
  }
  const Vec3 s{sum.x * (g.width - 1), sum.y * 65536.0, sum.z * (g.depth - 1)};
  const double l = length(s);
  return l > 0 ? s / l : Vec3{0, 1, 0};
}

struct HfBuilder {
  const HeightFieldOptions& o;
  HeightFieldTriangles out;

  HfIndex add(const Vec3& p, const Vec3& n) {
    const double z = o.mirror_z ? -p.z : p.z;
    out.soup.positions.push_back(
        {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(z)});
    if (o.smooth) {
      const Vec3 m = normalize(Vec3{n.x, n.y, o.mirror_z ? -n.z : n.z});
      out.normals.push_back(
          {static_cast<float>(m.x), static_cast<float>(m.y), static_cast<float>(m.z)});
    }
    return static_cast<HfIndex>(out.soup.positions.size() - 1);
  }
  void triangle(HfIndex a, HfIndex b, HfIndex c) {
    // Mirroring z reverses the winding: two corners swap to keep the normal facing up.
    out.soup.triangles.push_back(o.mirror_z ? std::array<HfIndex, 3>{a, c, b}
                                            : std::array<HfIndex, 3>{a, b, c});
  }
  // The part of triangle (a, b, c) at or above the water (corners given by grid index), as one
  // or two triangles; new corners where an edge crosses the water.
  void clipped(const Vec3* p, const Vec3* n, const HfIndex* v) {
    const double w = o.water_level;
    int above = 0;
    for (int k = 0; k < 3; ++k) above += p[k].y >= w;
    if (above == 3) return triangle(v[0], v[1], v[2]);
    if (above == 0) return;
    HfIndex poly[4];
    int m = 0;
    for (int k = 0; k < 3; ++k) {
      const int k2 = (k + 1) % 3;
      const bool in = p[k].y >= w, in2 = p[k2].y >= w;
      if (in) poly[m++] = v[k];
      if (in != in2) {
        const double s = (w - p[k].y) / (p[k2].y - p[k].y);
        Vec3 q = p[k] + s * (p[k2] - p[k]);
        q.y = w;
        poly[m++] = add(q, n[k] + s * (n[k2] - n[k]));
      }
    }
    for (int k = 1; k + 1 < m; ++k) triangle(poly[0], poly[k], poly[k + 1]);
  }
};

}  // namespace

HeightGrid height_grid_of(const HeightImage& image) {
  HeightGrid g{image.width, image.height, {}};
  g.y.resize(std::size_t(image.width) * std::size_t(image.height));
  for (int z = 0; z < image.height; ++z)
    for (int x = 0; x < image.width; ++x)
      g.y[std::size_t(z) * std::size_t(image.width) + std::size_t(x)] =
          image.at(x, image.height - 1 - z) / 65536.0;
  return g;
}

HeightFieldTriangles height_field_triangles(const HeightGrid& g, const HeightFieldOptions& o) {
  if (g.width < 2 || g.depth < 2)
    throw std::invalid_argument("a height field needs at least 2 x 2 heights, got " +
                                std::to_string(g.width) + " x " + std::to_string(g.depth));
  if (g.y.size() != std::size_t(g.width) * std::size_t(g.depth))
    throw std::invalid_argument("a height field's grid must hold width x depth heights");
  for (double y : g.y)
    if (!std::isfinite(y)) throw std::invalid_argument("a height field's heights must be finite");
  HfBuilder b{o, {}};
  const std::size_t n = g.y.size();
  b.out.soup.positions.reserve(n);
  std::vector<Vec3> p(n), nn(n, Vec3{0, 1, 0});
  for (int j = 0; j < g.depth; ++j)
    for (int i = 0; i < g.width; ++i) {
      const std::size_t k = std::size_t(j) * std::size_t(g.width) + std::size_t(i);
      p[k] = {double(i) / (g.width - 1), g.y[k], double(j) / (g.depth - 1)};
      if (o.smooth) nn[k] = hf_grid_normal(g, i, j);
      b.add(p[k], nn[k]);
    }
  b.out.soup.triangles.reserve(2 * std::size_t(g.width - 1) * std::size_t(g.depth - 1));
  for (int j = 0; j + 1 < g.depth; ++j)
    for (int i = 0; i + 1 < g.width; ++i) {
      const HfIndex v00 = HfIndex(j * g.width + i), v10 = v00 + 1, v01 = v00 + HfIndex(g.width),
                    v11 = v01 + 1;
      const HfIndex t1[3] = {v00, v01, v10}, t2[3] = {v11, v10, v01};
      for (const HfIndex* t : {t1, t2}) {
        const Vec3 tp[3] = {p[t[0]], p[t[1]], p[t[2]]}, tn[3] = {nn[t[0]], nn[t[1]], nn[t[2]]};
        b.clipped(tp, tn, t);
      }
    }
  return std::move(b.out);
}

std::shared_ptr<const Mesh> make_height_field(const HeightGrid& grid,
                                              const HeightFieldOptions& options) {
  HeightFieldTriangles t = height_field_triangles(grid, options);
  MeshOptions mo;
  mo.smooth = options.smooth;
  return make_mesh(std::move(t.soup.positions), std::move(t.soup.triangles), std::move(t.normals),
                   mo);
}

}  // namespace raycast

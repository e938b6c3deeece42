#include "render/explain_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "render/integrator.h"

namespace raycast {

namespace {

/// Grid cells across the drawing for the cross-section (and down, by the aspect ratio).
constexpr int kGridColumns = 200;
/// Drawing width in SVG units.
constexpr double kWidth = 800;
/// How far a ray that hits nothing is drawn, as a fraction of the drawing's extent.
constexpr double kMissLength = 0.35;
/// A direction counts as lying in the plane when its out-of-plane part is below this.
constexpr double kInPlane = 1e-6;

/// The plane of the drawing: origin and two orthonormal axes.
struct Plane2 {
  Vec3 o, e1, e2;
  double x(const Vec3& p) const { return dot(p - o, e1); }
  double y(const Vec3& p) const { return dot(p - o, e2); }
  Vec3 at(double u, double v) const { return o + u * e1 + v * e2; }
  bool holds(const Vec3& d) const {
    const Vec3 n = cross(e1, e2);
    return std::abs(dot(normalize(d), n)) < kInPlane;
  }
};

Plane2 drawing_plane(const Scene& scene, const Explanation& e) {
  const Vec3 d = normalize(e.root.ray.d);
  Vec3 side = e.root.hit ? e.root.hit->n : camera_or_default(scene).up;
  Vec3 e2 = side - dot(side, d) * d;
  if (!(length(e2) > 1e-6)) {
    side = camera_or_default(scene).up;
    e2 = side - dot(side, d) * d;
  }
  if (!(length(e2) > 1e-6)) {
    Vec3 s, t;
    make_frame(d, s, t);
    e2 = s;
  }
  return {e.root.ray.o, d, normalize(e2)};
}

/// A segment to draw, in plane coordinates.
struct Segment {
  double x0, y0, x1, y1;
  const char* style;  // camera, reflection, refraction, shadow, blocked
  bool projected;     // the ray leaves the plane
};

struct Drawing {
  std::vector<Segment> segments;
  std::vector<std::pair<double, double>> hits, crosses;
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  void extend(double x, double y) {
    xmin = std::min(xmin, x);
    xmax = std::max(xmax, x);
    ymin = std::min(ymin, y);
    ymax = std::max(ymax, y);
  }
};

/// The ray tree's segments (misses get their length later, from the extent of the rest).
void collect(const Plane2& plane, const ExplainedRay& r, Drawing& out,
             std::vector<std::pair<Ray, const char*>>& misses) {
  const char* style = ray_kind_name(r.kind);
  const bool projected = !plane.holds(r.ray.d);
  if (!r.hit) {
    misses.push_back({r.ray, style});
    return;
  }
  const Vec3 p = r.hit->si.p;
  out.segments.push_back(
      {plane.x(r.ray.o), plane.y(r.ray.o), plane.x(p), plane.y(p), style, projected});
  out.hits.push_back({plane.x(p), plane.y(p)});
  out.extend(plane.x(r.ray.o), plane.y(r.ray.o));
  out.extend(plane.x(p), plane.y(p));
  for (const ExplainedLight& l : r.hit->lights) {
    if (!l.sample.shadow_ray) continue;
    const Ray& s = l.sample.shadow;
    const bool blocked = !(max_component(l.sample.visibility) > 0) && l.blocker >= 0;
    const bool to_infinity = !(s.tmax < kInfinity);
    const double t_end = blocked ? l.blocker_t : to_infinity ? 0 : 1;
    if (to_infinity && !blocked) {
      misses.push_back({s, "shadow"});
      continue;
    }
    const Vec3 end = s.at(t_end);
    out.segments.push_back({plane.x(s.o), plane.y(s.o), plane.x(end), plane.y(end),
                            blocked ? "blocked" : "shadow", !plane.holds(s.d)});
    if (blocked) out.crosses.push_back({plane.x(end), plane.y(end)});
    out.extend(plane.x(end), plane.y(end));
  }
  for (const ExplainedRay& child : r.children) collect(plane, child, out, misses);
}

std::string color_hex(const Color& c) {
  char text[8];
  auto byte = [](double v) { return int(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.x), byte(c.y), byte(c.z));
  return text;
}

/// The cross-section: per grid cell the first closed object containing its centre (-1: none),
/// drawn as one rectangle per run of equal cells in a row.
std::string cross_section(const Scene& scene, const Plane2& plane, const Drawing& d, double scale,
                          int rows) {
  const double cell = (d.xmax - d.xmin) / kGridColumns;
  std::vector<int> owner(std::size_t(kGridColumns) * std::size_t(rows), -1);
  std::vector<std::size_t> solids;
  for (std::size_t k = 0; k < scene.objects.size(); ++k)
    if (is_closed(scene.objects[k])) solids.push_back(k);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < kGridColumns; ++i) {
      const Vec3 p = plane.at(d.xmin + (i + 0.5) * cell, d.ymax - (j + 0.5) * cell);
      for (std::size_t k : solids)
        if (contains(scene.objects[k], p)) {
          owner[std::size_t(j) * kGridColumns + std::size_t(i)] = int(k);
          break;
        }
    }
  std::string svg;
  char text[256];
  const double side = cell * scale;
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < kGridColumns;) {
      const int k = owner[std::size_t(j) * kGridColumns + std::size_t(i)];
      int end = i + 1;
      while (end < kGridColumns && owner[std::size_t(j) * kGridColumns + std::size_t(end)] == k)
        ++end;
      if (k >= 0) {
        std::snprintf(text, sizeof text,
                      "<rect x=\"%.2f\" y=\"%.2f\" width=\"%.2f\" height=\"%.2f\" fill=\"%s\" "
                      "fill-opacity=\"0.45\"/>\n",
                      i * side, j * side, (end - i) * side + 0.3, side + 0.3,
                      color_hex(id_color(scene.objects[std::size_t(k)].entry)).c_str());
        svg += text;
      }
      i = end;
    }
  return svg;
}

const char* stroke_of(const std::string& style) {
  if (style == "camera") return "stroke=\"#000\" stroke-width=\"2\"";
  if (style == "reflection") return "stroke=\"#1f4fd8\" stroke-width=\"2\"";
  if (style == "refraction") return "stroke=\"#138a36\" stroke-width=\"2\"";
  if (style == "blocked") return "stroke=\"#c0392b\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\"";
  return "stroke=\"#e69500\" stroke-width=\"1.5\" stroke-dasharray=\"6 4\"";
}

}  // namespace

std::string explain_svg(const Scene& scene, const Explanation& e) {
  const Plane2 plane = drawing_plane(scene, e);
  Drawing d;
  std::vector<std::pair<Ray, const char*>> misses;
  collect(plane, e.root, d, misses);
  double extent = std::max({d.xmax - d.xmin, d.ymax - d.ymin, 1.0});
  for (const auto& [ray, style] : misses) {
    const Vec3 end = ray.o + (kMissLength * extent) * normalize(ray.d);
    d.segments.push_back(
        {plane.x(ray.o), plane.y(ray.o), plane.x(end), plane.y(end), style, !plane.holds(ray.d)});
    d.extend(plane.x(ray.o), plane.y(ray.o));
    d.extend(plane.x(end), plane.y(end));
  }
  extent = std::max({d.xmax - d.xmin, d.ymax - d.ymin, 1e-3});
  const double margin = 0.12 * extent;
  d.xmin -= margin;
  d.xmax += margin;
  d.ymin -= margin;
  d.ymax += margin;
  const double scale = kWidth / (d.xmax - d.xmin);
  const int rows =
      std::max(1, int(std::ceil((d.ymax - d.ymin) / (d.xmax - d.xmin) * kGridColumns)));
  const double height = rows * (d.xmax - d.xmin) / kGridColumns * scale;
  auto sx = [&](double x) { return (x - d.xmin) * scale; };
  auto sy = [&](double y) { return (d.ymax - y) * scale; };

  char text[512];
  std::snprintf(text, sizeof text,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                "viewBox=\"0 0 %.2f %.2f\" font-family=\"sans-serif\" font-size=\"12\">\n"
                "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" "
                "markerWidth=\"7\" markerHeight=\"7\" orient=\"auto-start-reverse\">"
                "<path d=\"M0,0 L10,5 L0,10 z\" fill=\"context-stroke\"/></marker></defs>\n"
                "<rect width=\"100%%\" height=\"100%%\" fill=\"#fff\"/>\n",
                kWidth, height, kWidth, height);
  std::string svg = text;
  svg += "<g class=\"cross-section\">\n" + cross_section(scene, plane, d, scale, rows) + "</g>\n";
  svg += "<g class=\"rays\">\n";
  for (const Segment& s : d.segments) {
    std::snprintf(text, sizeof text,
                  "<line class=\"%s\" x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" %s%s "
                  "marker-end=\"url(#arrow)\"/>\n",
                  s.style, sx(s.x0), sy(s.y0), sx(s.x1), sy(s.y1), stroke_of(s.style),
                  s.projected ? " stroke-opacity=\"0.55\"" : "");
    svg += text;
  }
  for (const auto& [x, y] : d.hits) {
    std::snprintf(text, sizeof text, "<circle class=\"hit\" cx=\"%.2f\" cy=\"%.2f\" r=\"3.5\"/>\n",
                  sx(x), sy(y));
    svg += text;
  }
  for (const auto& [x, y] : d.crosses) {
    const double cx = sx(x), cy = sy(y);
    std::snprintf(text, sizeof text,
                  "<path class=\"blocker\" d=\"M%.2f,%.2f l10,10 m0,-10 l-10,10\" "
                  "stroke=\"#c0392b\" stroke-width=\"2.5\"/>\n",
                  cx - 5, cy - 5);
    svg += text;
  }
  svg += "</g>\n";
  std::snprintf(text, sizeof text,
                "<text x=\"8\" y=\"16\">pixel (%d, %d): camera black, reflection blue, "
                "refraction green, shadow dashed (red: blocked); faint: out of the plane</text>\n",
                e.x, e.y);
  svg += text;
  svg += "</svg>\n";
  return svg;
}

}  // namespace raycast

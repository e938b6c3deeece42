#include "render/ray_stats.h"

#include <algorithm>
#include <cstdio>
#include <functional>

#include "mesh/mesh.h"

namespace raycast {

namespace {

/// Counts nodes, leaves, depth and leaf sizes below one child reference.
void walk_tree(const MeshBvh& bvh, std::uint32_t ref, int level, MeshTreeStats& s,
               std::size_t& references) {
  s.depth = std::max(s.depth, level);
  if (ref & kLeafBit) {
    const std::uint32_t first = ref & 0x1FFFFFFFu;
    const std::uint32_t groups = ((ref >> 29) & 3u) + 1;
    int count = 0;
    for (std::uint32_t g = first; g < first + groups && g < bvh.groups.size(); ++g)
      for (std::uint32_t id : bvh.groups[g].id) count += id != kNoTriangle;
    ++s.leaves;
    references += std::size_t(count);
    s.max_leaf = std::max(s.max_leaf, count);
    return;
  }
  ++s.nodes;
  const bool q = bvh.quantised;
  const std::uint8_t used = q ? bvh.qnodes[ref].used : bvh.nodes[ref].used;
  for (int c = 0; c < kNodeWidth; ++c)
    if (used >> c & 1)
      walk_tree(bvh, q ? bvh.qnodes[ref].child[c] : bvh.nodes[ref].child[c], level + 1, s,
                references);
}

std::string count_text(std::uint64_t n, std::uint64_t total) {
  char line[96];
  std::snprintf(line, sizeof line, "%12llu  %5.1f %%", static_cast<unsigned long long>(n),
                total > 0 ? 100.0 * double(n) / double(total) : 0.0);
  return line;
}

}  // namespace

std::vector<MeshTreeStats> mesh_tree_stats(const Scene& scene) {
  std::vector<MeshTreeStats> out;
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const auto* shape = std::get_if<MeshShape>(&scene.objects[k].shape);
    if (!shape || !shape->mesh || shape->mesh->bvh.empty()) continue;
    const MeshBvh& bvh = shape->mesh->bvh;
    MeshTreeStats s;
    s.object = std::int32_t(k);
    s.triangles = shape->mesh->triangles.size();
    std::size_t references = 0;
    walk_tree(bvh, bvh.root, 1, s, references);
    s.mean_leaf = s.leaves > 0 ? double(references) / double(s.leaves) : 0;
    out.push_back(s);
  }
  return out;
}

std::string format_stats(const Scene& scene, const RenderStats& stats, const RayCounts& counts,
                         const PhaseTimes& times) {
  std::string out = "statistics\n";
  char line[256];
  const std::uint64_t total = counts.total();
  const double pixels = double(stats.width) * double(stats.height);
  std::snprintf(line, sizeof line, "  image            %dx%d, %d spp, %d threads\n", stats.width,
                stats.height, stats.spp, stats.threads);
  out += line;
  out += "  rays by kind\n";
  const std::pair<const char*, std::uint64_t> kinds[] = {{"camera", counts.camera},
                                                         {"reflection", counts.reflection},
                                                         {"refraction", counts.refraction},
                                                         {"shadow", counts.shadow}};
  for (const auto& [name, n] : kinds) {
    std::snprintf(line, sizeof line, "    %-12s %s\n", name, count_text(n, total).c_str());
    out += line;
  }
  std::snprintf(line, sizeof line, "    %-12s %12llu  (%.2f per pixel, deepest ray %d)\n", "total",
                static_cast<unsigned long long>(total), pixels > 0 ? double(total) / pixels : 0,
                counts.max_depth);
  out += line;
  out += "  time by phase\n";
  std::snprintf(line, sizeof line,
                "    load+build   %10.3f s  (acceleration build %.3f s)\n    render       "
                "%10.3f s  (%.2f Mrays/s)\n    write        %10.3f s\n",
                times.load, scene.build_ms() * 1e-3, times.render,
                times.render > 0 ? double(total) / times.render * 1e-6 : 0, times.write);
  out += line;
  std::snprintf(line, sizeof line,
                "  scene            %zu objects, %zu lights, top-level structure %zu bytes\n",
                scene.objects.size(), scene.lights.size(), scene.accel_bytes());
  out += line;
  for (const MeshTreeStats& s : mesh_tree_stats(scene)) {
    std::snprintf(line, sizeof line,
                  "  mesh BVH #%d      %zu triangles: %zu inner nodes (8-wide), %zu leaves, "
                  "depth %d, triangles per leaf %.2f mean, %d max\n",
                  scene.objects[std::size_t(s.object)].entry, s.triangles, s.nodes, s.leaves,
                  s.depth, s.mean_leaf, s.max_leaf);
    out += line;
  }
  return out;
}

}  // namespace raycast

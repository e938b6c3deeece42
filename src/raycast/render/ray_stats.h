#pragma once
// The statistics report of `render --stats` (docs/rendering.md "Statistics"): rays by kind, rays
// per pixel, time by phase and the acceleration structures' shape, as pbrt prints after a render.
#include <cstdint>
#include <string>
#include <vector>

#include "render/pixel_record.h"
#include "render/renderer.h"

namespace raycast {

/// The shape of one mesh's BVH: inner nodes, leaves, depth and triangles per leaf.
struct MeshTreeStats {
  std::int32_t object = -1;  // index in Scene::objects
  std::size_t triangles = 0, nodes = 0, leaves = 0;
  int depth = 0;
  int max_leaf = 0;      // most triangles in one leaf
  double mean_leaf = 0;  // triangles per leaf (references, with split references)
};

/// The shape of every mesh BVH of the scene (meshes inside CSG or instances are not listed).
std::vector<MeshTreeStats> mesh_tree_stats(const Scene& scene);

/// Time spent by phase, in seconds.
struct PhaseTimes {
  double load = 0;    // reading the scene and building its acceleration structures
  double render = 0;  // the pixel loop
  double write = 0;   // writing the image files
};

/// The report, several lines of text ending in a newline.
std::string format_stats(const Scene& scene, const RenderStats& stats, const RayCounts& counts,
                         const PhaseTimes& times);

}  // namespace raycast

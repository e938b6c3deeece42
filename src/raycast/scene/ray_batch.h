#pragma once
// Nearest hits of a batch of rays, through the mesh packet kernel where the rays are coherent
// (`raycast bench --packets` measures both paths).
#include <cstdint>
#include <span>

#include "scene/scene.h"

namespace raycast {

/// Whether rays[0..n) (n <= 16) may go as one packet: the same direction octant, origins within
/// `extent` / 32 of each other and unit directions within 1/16 of each other on every axis.
bool coherent_rays(const Ray* rays, int n, double extent);

/// hits[i] and found[i] exactly as `found[i] = scene.intersect(rays[i], hits[i])` from a
/// default SceneHit gives them. In a scene of one mesh without a transform (Scene::sole_mesh: other
/// objects' boxes empty), each run of sixteen (AVX-512: packet_width) or eight coherent rays
/// (coherent_rays) is traced as one packet (mesh/packet_traverse.inl, bit for bit the single-ray
/// answers) after the object's box test on its lanes; every other ray alone. Serial: callers
/// split big batches.
void intersect_batch(const Scene& scene, std::span<const Ray> rays, std::span<SceneHit> hits,
                     std::span<std::uint8_t> found);

}  // namespace raycast

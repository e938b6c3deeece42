#pragma once
// Random float rays for the mesh BVH tests (std::mt19937 streams, as those tests draw them).
#include <random>

#include "mesh/mesh_bvh.h"

namespace raycast::testing {

/// A ray from a point in the cube of half-width 1.5 spread, with a normally distributed
/// direction (not too short), tmin 0 and tmax in [0.5, 10] spread.
inline MeshRay random_mesh_ray(std::mt19937& rng, float spread) {
  std::uniform_real_distribution<float> pos(-1.5f * spread, 1.5f * spread);
  std::normal_distribution<float> dir;
  MeshRay r;
  r.o = {pos(rng), pos(rng), pos(rng)};
  do r.d = {dir(rng), dir(rng), dir(rng)};
  while (!(length_squared(r.d) > 0.01f));
  r.tmin = 0;
  r.tmax = std::uniform_real_distribution<float>(0.5f, 10.0f)(rng) * spread;
  return r;
}

}  // namespace raycast::testing

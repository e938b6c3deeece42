// Casts a batch of rays at a triangle mesh built in code (an octahedron) and prints a summary.
#include <cstdio>
#include <vector>

#include <raycast/raycast.h>

int main() {
  const std::vector<double> vertices = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  const std::vector<std::uint32_t> triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                                2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  raycast::Scene scene;
  scene.add_mesh(vertices, triangles);
  scene.commit();

  // A 100 x 100 grid of parallel rays along +z, interleaved [ox, oy, oz, dx, dy, dz].
  const int n = 100;
  std::vector<double> rays;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      rays.insert(rays.end(),
                  {-1.2 + 2.4 * (x + 0.5) / n, -1.2 + 2.4 * (y + 0.5) / n, -5, 0, 0, 1});
  std::vector<double> t(n * n);
  std::vector<std::int32_t> triangle(n * n);
  raycast::HitColumns out;
  out.t = t.data();
  out.primitive = triangle.data();
  scene.intersect(raycast::RayArray::interleaved(rays.data(), n * n), out);

  int hits = 0;
  double nearest = 1e300;
  for (int i = 0; i < n * n; ++i)
    if (triangle[i] >= 0) {
      ++hits;
      nearest = std::min(nearest, t[i]);
    }
  std::printf("%d of %d rays hit the octahedron; nearest t = %g (raycast %s)\n", hits, n * n,
              nearest, RAYCAST_VERSION_STRING);
  return hits > 0 ? 0 : 1;
}

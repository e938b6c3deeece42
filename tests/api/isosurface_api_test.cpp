// Iso-surfaces built through the public API (Scene::add_isosurface) answer exactly as the same
// data loaded from a scene file does.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "raycast/raycast.h"

namespace {

const std::string kData = std::string(RAYCAST_SOURCE_DIR) + "/tests/volume/data/";

std::vector<raycast::Ray> random_rays(int n) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  std::vector<raycast::Ray> rays(n);
  for (auto& r : rays) {
    raycast::Vec3d o{g(rng), g(rng), g(rng)};
    const double len = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
    for (double& c : o) c *= 4 / len;
    r.origin = o;
    r.direction = {u(rng) - o[0], u(rng) - o[1], u(rng) - o[2]};
  }
  return rays;
}

void expect_same_hits(const raycast::Scene& a, const raycast::Scene& b) {
  int hits = 0;
  for (const raycast::Ray& r : random_rays(300)) {
    const raycast::SurfaceInfo x = a.intersect(r), y = b.intersect(r);
    ASSERT_EQ(x.hit(), y.hit());
    if (!x.hit()) continue;
    ++hits;
    EXPECT_EQ(x.t, y.t);
    EXPECT_EQ(x.normal, y.normal);
    EXPECT_EQ(a.intersect_all(r).size(), b.intersect_all(r).size());
  }
  EXPECT_GT(hits, 30);
}

TEST(PublicIsosurface, GridFromValues_EqualsTheRawFile) {
  std::ifstream in(kData + "sphere_sdf.raw", std::ios::binary);
  std::vector<float> values(13 * 13 * 13);
  in.read(reinterpret_cast<char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
  ASSERT_TRUE(in);
  raycast::Scene built;
  raycast::GridSurface g;
  g.counts = {13, 13, 13};
  g.origin = {-1.5, -1.5, -1.5};
  g.spacing = {0.25, 0.25, 0.25};
  g.iso = 0;
  EXPECT_EQ(built.add_isosurface(values, g), 0);
  built.commit();
  EXPECT_EQ(built.shape_name(0), "isosurface");
  const raycast::Scene loaded = raycast::Scene::from_string(
      "objects: [{isosurface: {grid: sphere_sdf.raw, iso: 0}}]", "iso.yaml", kData);
  expect_same_hits(built, loaded);
}

TEST(PublicIsosurface, ParticlesFromArray_EqualTheParticleFile) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0, 0.2);
  std::vector<double> particles(3 * 300);
  for (double& c : particles) c = g(rng);
  const auto dir = std::filesystem::temp_directory_path() / "raycast_iso_api_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream out(dir / "p.xyz");
    out.precision(17);
    for (std::size_t i = 0; i < particles.size(); i += 3)
      out << particles[i] << ' ' << particles[i + 1] << ' ' << particles[i + 2] << '\n';
  }
  raycast::Scene built;
  raycast::ParticleSurface p;
  p.smoothing_length = 0.1;
  p.iso = 100;
  built.add_isosurface(particles, p);
  built.commit();
  const raycast::Scene loaded = raycast::Scene::from_string(
      "objects: [{isosurface: {particles: p.xyz, smoothing_length: 0.1, iso: 100}}]", "iso.yaml",
      dir.string());
  expect_same_hits(built, loaded);
  std::filesystem::remove_all(dir);
}

TEST(PublicIsosurface, BadParameters_ThrowSceneErrorNamingTheCall) {
  raycast::Scene s;
  raycast::GridSurface g;
  g.counts = {2, 2, 2};
  const std::vector<float> seven(7);
  EXPECT_THROW(s.add_isosurface(seven, g), raycast::SceneError);
  raycast::ParticleSurface p;  // no smoothing length
  const std::vector<double> one(3);
  try {
    s.add_isosurface(one, p);
    FAIL() << "no error";
  } catch (const raycast::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("add_isosurface"), std::string::npos) << e.what();
  }
  p.smoothing_length = 1;
  p.resolution = std::array<int, 3>{2000000, 2000000, 2};
  try {
    s.add_isosurface(one, p);
    FAIL() << "no error";
  } catch (const raycast::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("bytes"), std::string::npos) << e.what();
  }
}

}  // namespace

// Groups, materials of compound objects, library/use instancing, and the loader's errors for them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "csg_oracle.h"
#include "io/scene_error.h"
#include "objects/prototype.h"

namespace raycast {
namespace {

using csg_test::scene_of;

const std::string kMaterials =
    "materials:\n"
    "  red: {color: [1, 0, 0]}\n"
    "  green: {color: [0, 1, 0]}\n"
    "  blue: {color: [0, 0, 1]}\n";

std::string material_at(const Scene& scene, const Ray& ray) {
  SceneHit hit;
  if (!scene.intersect(ray, hit)) return "miss";
  return scene.material_of(hit).name;
}

TEST(Group, Children_KeepTheirOwnHitsAndTheEntryIndex) {
  const Scene scene = scene_of(
      "- sphere: {center: [0, 0, 10], radius: 1}\n"
      "- group:\n"
      "    - sphere: {radius: 1}\n"
      "    - group:\n"
      "        - sphere: {center: [1, 0, 0], radius: 1}\n"
      "      transform: [{translate: [0, 0, 0]}]\n");
  ASSERT_EQ(scene.objects.size(), 3u);
  EXPECT_EQ(scene.entries, 2);
  std::vector<Crossing> all;
  scene.intersect_all(Ray{{-5, 0, 0}, {1, 0, 0}}, all);
  ASSERT_EQ(all.size(), 4u);  // the overlap keeps both spheres' surfaces
  EXPECT_EQ(all[0].t, 4);
  EXPECT_EQ(all[1].t, 5);
  EXPECT_EQ(all[2].t, 6);
  EXPECT_EQ(all[3].t, 7);
  for (const Crossing& c : all) EXPECT_EQ(scene.objects[c.object].entry, 1);
}

TEST(Group, Transforms_ComposeParentAfterChild) {
  const Scene scene = scene_of(
      "- group:\n"
      "    - sphere: {radius: 1}\n"
      "      transform: [{translate: [1, 0, 0]}]\n"
      "  transform: [{scale: 2}, {translate: [0, 0, 5]}]\n");
  SceneHit hit;
  // The child sits at (1, 0, 0) scaled by 2 to (2, 0, 0) with radius 2, then moved to z = 5.
  const Ray r{{2, 0, -5}, {0, 0, 1}};
  ASSERT_TRUE(scene.intersect(r, hit));
  EXPECT_EQ(hit.local.t, 8);
}

TEST(Materials, CsgChildrenShowTheirOwnMaterialOnTheirSurfaces) {
  const Scene scene = load_scene_text(kMaterials +
                                      "objects:\n"
                                      "  - difference:\n"
                                      "      - sphere: {radius: 2}\n"
                                      "        material: red\n"
                                      "      - sphere: {radius: 1}\n"
                                      "        material: blue\n"
                                      "      - union:\n"
                                      "          - sphere: {center: [0, 3, 0], radius: 1.5}\n"
                                      "        material: {color: [0.5, 0.5, 0.5]}\n"
                                      "      - sphere: {center: [0, -3, 0], radius: 1.5}\n"
                                      "    material: green\n");
  EXPECT_EQ(material_at(scene, Ray{{0, 0, -5}, {0, 0, 1}}), "red");
  EXPECT_EQ(material_at(scene, Ray{{0, 0, -1.5}, {0, 0, 1}}), "blue");  // inside, at the cavity
  SceneHit hit;
  ASSERT_TRUE(scene.intersect(Ray{{0, 5, 0.2}, {0, -1, 0}}, hit));
  EXPECT_EQ(scene.material_of(hit).color.x, 0.5);  // inherited from the inner union
  EXPECT_EQ(material_at(scene, Ray{{0, -5, 0.2}, {0, 1, 0}}), "green");  // no material: the CSG's
}

TEST(Materials, GroupChildrenInheritUnlessTheyNameTheirOwn) {
  const Scene scene = load_scene_text(kMaterials +
                                      "objects:\n"
                                      "  - group:\n"
                                      "      - sphere: {center: [-3, 0, 0], radius: 1}\n"
                                      "      - sphere: {center: [3, 0, 0], radius: 1}\n"
                                      "        material: blue\n"
                                      "    material: red\n"
                                      "  - sphere: {center: [0, 3, 0], radius: 1}\n");
  EXPECT_EQ(material_at(scene, Ray{{-3, 0, -5}, {0, 0, 1}}), "red");
  EXPECT_EQ(material_at(scene, Ray{{3, 0, -5}, {0, 0, 1}}), "blue");
  EXPECT_EQ(material_at(scene, Ray{{0, 3, -5}, {0, 0, 1}}), "default");
}

TEST(Instancing, UsesShareOnePrototypeAndTakeTheirMaterial) {
  const Scene scene = load_scene_text(kMaterials +
                                      "library:\n"
                                      "  thing:\n"
                                      "    group:\n"
                                      "      - sphere: {radius: 1}\n"
                                      "      - sphere: {center: [0, 3, 0], radius: 0.5}\n"
                                      "        material: blue\n"
                                      "objects:\n"
                                      "  - use: thing\n"
                                      "    material: red\n"
                                      "  - use: thing\n"
                                      "    transform: [{translate: [10, 0, 0]}]\n");
  ASSERT_EQ(scene.objects.size(), 2u);
  const auto& a = std::get<InstanceShape>(scene.objects[0].shape);
  const auto& b = std::get<InstanceShape>(scene.objects[1].shape);
  EXPECT_EQ(a.proto.get(), b.proto.get());
  EXPECT_EQ(material_at(scene, Ray{{0, 0, -5}, {0, 0, 1}}), "red");
  EXPECT_EQ(material_at(scene, Ray{{0, 3, -5}, {0, 0, 1}}), "blue");
  EXPECT_EQ(material_at(scene, Ray{{10, 0, -5}, {0, 0, 1}}), "default");
  SceneHit hit;
  ASSERT_TRUE(scene.intersect(Ray{{10, 0, -5}, {0, 0, 1}}, hit));
  EXPECT_EQ(hit.local.t, 4);
  EXPECT_EQ(scene.objects[hit.object].entry, 1);
}

// A library entry (CSG with per-leaf materials, in a group with a transform) used at random
// places, against the same scene with every use written out in full.
TEST(Instancing, SameAnswersAsTheFlattenedScene) {
  const std::string def =
      "group:\n"
      "  - difference:\n"
      "      - sphere: {radius: 1}\n"
      "        material: red\n"
      "      - sphere: {center: [0.6, 0, 0], radius: 0.6}\n"
      "        material: blue\n"
      "  - sphere: {center: [0, 1.4, 0], radius: 0.4}\n"
      "    transform: [{scale: [1, 0.5, 1]}]\n";
  auto indented = [](const std::string& text, const std::string& pad) {
    std::string out;
    std::size_t start = 0;
    while (start < text.size()) {
      const std::size_t end = text.find('\n', start);
      out += pad + text.substr(start, end - start + 1);
      start = end + 1;
    }
    return out;
  };
  testing::Rng rng(5);
  std::uniform_real_distribution<double> u(-6, 6), angle(0, 360), s(0.5, 1.5);
  std::string used = kMaterials + "library:\n  thing:\n" + indented(def, "    ") + "objects:\n";
  std::string flat = kMaterials + "objects:\n";
  for (int i = 0; i < 30; ++i) {
    const std::string xf =
        "    transform: [{scale: [" + std::to_string(s(rng)) + ", " + std::to_string(s(rng)) +
        ", 1]}, {rotate: {axis: [1, 1, 0], degrees: " + std::to_string(angle(rng)) +
        "}}, {translate: [" + std::to_string(u(rng)) + ", " + std::to_string(u(rng)) + ", " +
        std::to_string(u(rng)) + "]}]\n";
    const std::string mat = i % 3 ? "    material: green\n" : "";
    used += "  - use: thing\n" + xf + mat;
    flat += "  - group:\n      -\n" + indented(def, "        ") + xf + mat;
  }
  const Scene a = load_scene_text(used), b = load_scene_text(flat);
  ASSERT_EQ(a.objects.size(), 30u);
  ASSERT_EQ(b.objects.size(), 60u);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    SCOPED_TRACE(::testing::Message() << "seed 5, ray " << i);
    const Vec3 target{u(rng), u(rng), u(rng)};
    const Vec3 d = rng.direction();
    const Ray ray{target - 15.0 * d, d};
    SceneHit ha, hb;
    const bool fa = a.intersect(ray, ha), fb = b.intersect(ray, hb);
    ASSERT_EQ(fa, fb);
    EXPECT_EQ(a.occluded(ray), fa);
    if (!fa) continue;
    ++hits;
    EXPECT_NEAR(ha.local.t, hb.local.t, 1e-9 * hb.local.t);
    const SurfaceInfo sa = a.surface(ray, ha), sb = b.surface(ray, hb);
    EXPECT_NEAR(dot(sa.n, sb.n), 1, 1e-9);
    EXPECT_EQ(a.objects[ha.object].entry, b.objects[hb.object].entry);
    EXPECT_EQ(a.material_of(ha).name, b.material_of(hb).name);
    std::vector<Crossing> ca, cb;
    a.intersect_all(ray, ca);
    b.intersect_all(ray, cb);
    ASSERT_EQ(ca.size(), cb.size());
    for (std::size_t k = 0; k < ca.size(); ++k) EXPECT_NEAR(ca[k].t, cb[k].t, 1e-9 * cb[k].t);
  }
  EXPECT_GT(hits, 300);
}

TEST(Instancing, UseInsideCsgAndLibraryIsExpandedInPlace) {
  const Scene scene = load_scene_text(
      "library:\n"
      "  ball: {sphere: {radius: 1}}\n"
      "  pair:\n"
      "    group:\n"
      "      - use: ball\n"
      "        transform: [{translate: [-2, 0, 0]}]\n"
      "      - use: ball\n"
      "        transform: [{translate: [2, 0, 0]}]\n"
      "objects:\n"
      "  - difference:\n"
      "      - sphere: {radius: 4}\n"
      "      - use: pair\n"
      "  - use: pair\n"
      "    transform: [{translate: [0, 10, 0]}]\n");
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_STREQ(shape_name(scene.objects[0]), "csg");
  const auto& inst = std::get<InstanceShape>(scene.objects[1].shape);
  EXPECT_EQ(inst.proto->objects.size(), 2u);  // the nested uses were flattened into spheres
  std::vector<Crossing> all;
  scene.intersect_all(Ray{{-10, 0, 0}, {1, 0, 0}}, all);
  ASSERT_EQ(all.size(), 6u);
  const double expected[] = {6, 7, 9, 11, 13, 14};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(all[i].t, expected[i]);
  EXPECT_EQ(scene.surface(Ray{{-10, 0, 0}, {1, 0, 0}}, SceneHit{all[1].local, all[1].object}).n.x,
            1);
  scene.intersect_all(Ray{{-10, 10, 0}, {1, 0, 0}}, all);
  ASSERT_EQ(all.size(), 4u);
  for (const Crossing& c : all) EXPECT_EQ(scene.objects[c.object].entry, 1);
}

std::string error_of(const std::string& text) {
  try {
    load_scene_text(text, "s.yaml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

TEST(CompoundLoader, Errors_NameThePosition) {
  EXPECT_EQ(error_of("objects:\n  - union:\n      - sphere: {radius: 1, phi_max: 90}\n"),
            "s.yaml:3:9: sphere cannot be a CSG operand: it is an open surface");
  EXPECT_EQ(error_of("objects:\n  - use: nothing\n"),
            "s.yaml:2:10: unknown library entry 'nothing'");
  EXPECT_EQ(error_of("library:\n  a: {use: b}\n  b: {use: a}\nobjects: []\n"),
            "s.yaml:3:12: library entry 'a' uses itself (a -> b -> a)");
  EXPECT_EQ(
      error_of("library:\n  a: {sphere: {radius: 1}}\n  a: {sphere: {radius: 2}}\nobjects: []\n"),
      "s.yaml:3:3: library entry 'a' is defined twice");
  // Library entries are checked in file order, used or not.
  EXPECT_EQ(error_of("library:\n  z: {sphere: {radius: 0}}\n  a: {box: 1}\nobjects: []\n"),
            "s.yaml:2:24: sphere.radius must be > 0, got 0");
  EXPECT_EQ(error_of("objects:\n  - union: []\n"),
            "s.yaml:2:12: union must be a non-empty list of solids, got a list of 0");
  EXPECT_EQ(error_of("objects:\n  - group: {sphere: {radius: 1}}\n"),
            "s.yaml:2:12: group must be a list of objects, got a mapping");
  EXPECT_EQ(error_of("library: [1]\nobjects: []\n"),
            "s.yaml:1:10: library must be a mapping of names to objects, got a list of 1");
  EXPECT_EQ(error_of("objects:\n  - intersection:\n      - sphere: {radius: -1}\n"),
            "s.yaml:3:26: sphere.radius must be > 0, got -1");
  EXPECT_NE(error_of("objects:\n  - unoin: []\n").find("s.yaml:2:5: unknown key 'unoin' in object"),
            std::string::npos);
  // Nesting deeper than kMaxNesting: through a chain of library entries (yaml-cpp itself stops
  // a few hundred levels of indentation earlier, also with a position).
  std::string chain = "library:\n";
  for (int i = 0; i < 200; ++i)
    chain += "  e" + std::to_string(i) + ": {group: [{use: e" + std::to_string(i + 1) + "}]}\n";
  chain += "  e200: {sphere: {radius: 1}}\nobjects: []\n";
  const std::string deep = error_of(chain);
  EXPECT_EQ(deep.rfind("s.yaml:", 0), 0u) << deep;
  EXPECT_NE(deep.find("objects are nested deeper than 256"), std::string::npos) << deep;
  // Entries that each use the next twice: 2^40 spheres are refused, quickly.
  std::string doubling = "library:\n";
  for (int i = 0; i < 40; ++i)
    doubling += "  e" + std::to_string(i) + ": {group: [{use: e" + std::to_string(i + 1) +
                "}, {use: e" + std::to_string(i + 1) + "}]}\n";
  doubling += "  e40: {sphere: {radius: 1}}\nobjects: []\n";
  EXPECT_NE(error_of(doubling).find("library expansion makes more than 65536 objects"),
            std::string::npos);
  for (const char* key : {"group", "union"}) {
    std::string text = "objects:\n";
    std::string indent = "  ";
    for (int i = 0; i <= kMaxNesting + 1; ++i) {
      text += indent + "- " + key + ":\n";
      indent += "  ";
    }
    text += indent + "- sphere: {radius: 1}\n";
    const std::string e = error_of(text);
    EXPECT_EQ(e.rfind("s.yaml:", 0), 0u) << key << ": " << e;
  }
}

}  // namespace
}  // namespace raycast

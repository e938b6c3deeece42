#include <cstdio>
#include <map>
#include <string>

#include "commands.h"
#include "scene/loader.h"

namespace raycast::cli {

namespace {

void print_box(const char* label, const Aabb& b) {
  if (b.is_empty()) {
    std::printf("%s: empty\n", label);
    return;
  }
  std::printf("%s: [%g, %g, %g] - [%g, %g, %g]\n", label, b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z);
}

}  // namespace

Action add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Print what a scene holds: objects, bounds, acceleration");
  auto scene_path = std::make_shared<std::string>();
  cmd->add_option("SCENE", *scene_path, "Scene file (YAML or JSON)")->required();
  return [scene_path] {
    const Scene scene = load_scene_file(*scene_path);
    std::map<std::string, int> by_type;
    for (const Object& o : scene.objects) ++by_type[shape_name(o)];
    std::printf("scene: %s\n", scene.source.c_str());
    std::printf("entries: %d\nobjects: %zu\n", scene.entries, scene.objects.size());
    for (const auto& [type, count] : by_type) std::printf("  %s: %d\n", type.c_str(), count);
    std::printf("materials: %zu\nlights: %zu\n", scene.materials.size() - 1, scene.lights.size());
    print_box("bounds", scene.bounds());
    print_box("finite bounds", scene.finite_bounds());
    std::printf("acceleration: top-level BVH, %zu bytes, built in %.3f ms\n", scene.accel_bytes(),
                scene.build_ms());
    return 0;
  };
}

}  // namespace raycast::cli

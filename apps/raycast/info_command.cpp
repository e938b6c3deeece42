#include <cstdio>
#include <map>
#include <string>

#include <thread>

#include "commands.h"
#include "load/loader.h"
#include "math/isa.h"

namespace raycast::cli {

namespace {

void print_box(const char* label, const Aabb& b) {
  if (b.is_empty()) {
    std::printf("%s: empty\n", label);
    return;
  }
  std::printf("%s: [%g, %g, %g] - [%g, %g, %g]\n", label, b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y,
              b.hi.z);
}

// Triangle counts, dropped degenerate triangles and the mesh BVHs.
void print_meshes(const Scene& scene) {
  std::size_t meshes = 0, triangles = 0, dropped = 0, closed = 0, bvh = 0, total = 0;
  double build_ms = 0;
  for (const Object& o : scene.objects)
    if (const auto* m = std::get_if<MeshShape>(&o.shape)) {
      ++meshes;
      triangles += m->mesh->triangle_count();
      dropped += m->mesh->dropped;
      closed += m->mesh->closed();
      bvh += m->mesh->bvh_bytes();
      total += m->mesh->memory_bytes();
      build_ms += m->mesh->build_ms;
    }
  if (meshes == 0) return;
  std::printf("triangles: %zu in %zu meshes (%zu closed); %zu degenerate triangles dropped\n",
              triangles, meshes, closed, dropped);
  std::printf("mesh BVHs: %zu bytes (%.1f per triangle), built in %.3f ms; mesh memory %zu bytes\n",
              bvh, triangles ? double(bvh) / triangles : 0.0, build_ms, total);
}

// The machine as the engine sees it: the SIMD path of the kernels and why, and the threads.
void print_system() {
  std::printf("isa: %s (%s)\n", isa_name(active_isa()), active_isa_reason());
  std::printf("isa supported:");
  for (Isa isa : kAllIsas)
    if (isa_supported(isa)) std::printf(" %s", isa_name(isa));
  std::printf("\nhardware threads: %u\n", std::thread::hardware_concurrency());
}

}  // namespace

Action add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Print what a scene holds: objects, bounds, acceleration");
  auto scene_path = std::make_shared<std::string>();
  auto system = std::make_shared<bool>(false);
  cmd->add_option("SCENE", *scene_path, "Scene file (YAML or JSON)");
  cmd->add_flag("--system", *system,
                "Print the SIMD path in use (RAYCAST_ISA=scalar|sse4|avx2|avx512 forces one) and "
                "the hardware threads");
  return [scene_path, system] {
    if (*system) print_system();
    if (scene_path->empty()) {
      if (*system) return 0;
      std::fprintf(stderr, "raycast info: give a SCENE, or --system\n");
      return 2;
    }
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
    print_meshes(scene);
    return 0;
  };
}

}  // namespace raycast::cli

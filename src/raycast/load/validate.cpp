#include "load/validate.h"

#include <cstdio>
#include <string>

#include "io/scene_error.h"
#include "load/loader.h"

namespace raycast {
namespace {

std::string format_point(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p.x, p.y, p.z);
  return buf;
}

// "the sphere of objects entry 3 (line 12)": how a finding names an object.
std::string describe_object(const Scene& scene, const Object& o) {
  std::string s =
      std::string("the ") + shape_name(o) + " of objects entry " + std::to_string(o.entry + 1);
  if (o.entry >= 0 && o.entry < static_cast<int>(scene.marks.entries.size()) &&
      scene.marks.entries[o.entry].line > 0)
    s += " (line " + std::to_string(scene.marks.entries[o.entry].line) + ")";
  return s;
}

// The first closed object whose solid holds p, or nullptr. `opaque_only` skips objects whose
// material lets light through.
const Object* solid_around(const Scene& scene, const Vec3& p, bool opaque_only) {
  for (const Object& o : scene.objects) {
    if (!is_closed(o) || !bounds(o).contains(p) || !contains(o, p)) continue;
    if (opaque_only && o.material >= 0 && o.material < static_cast<int>(scene.materials.size()) &&
        scene.materials[o.material].transmission > 0)
      continue;
    return &o;
  }
  return nullptr;
}

}  // namespace

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::kNote:
      return "note";
    case Severity::kWarning:
      return "warning";
    case Severity::kError:
      return "error";
  }
  return "?";
}

std::string no_lights_warning(const Scene& scene, RenderMode mode) {
  if (!scene.lights.empty() || mode != RenderMode::kWhitted) return "";
  return "the scene has no lights: the whitted integrator shows only ambient light and the "
         "background";
}

std::vector<Finding> check_scene(const Scene& scene) {
  std::vector<Finding> found;
  auto add = [&](Severity severity, SourceMark at, std::string message) {
    found.push_back({severity, scene.source, at.line, at.column, std::move(message)});
  };
  auto entry_mark = [&](const Object& o) {
    return o.entry >= 0 && o.entry < static_cast<int>(scene.marks.entries.size())
               ? scene.marks.entries[o.entry]
               : SourceMark{};
  };

  if (std::string warning = no_lights_warning(scene, scene.render.integrator); !warning.empty())
    add(Severity::kWarning, {}, std::move(warning));

  const CameraDesc camera = camera_or_default(scene);
  if (const Object* o = solid_around(scene, camera.position, false))
    add(Severity::kWarning, scene.marks.camera,
        "the camera at " + format_point(camera.position) + " is inside " +
            describe_object(scene, *o) + ": the image shows that solid from within");

  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    if (light.type == LightType::kDirectional) continue;
    if (const Object* o = solid_around(scene, light.position, true))
      add(Severity::kWarning, i < scene.marks.lights.size() ? scene.marks.lights[i] : SourceMark{},
          "light " + std::to_string(i + 1) + " at " + format_point(light.position) + " is inside " +
              describe_object(scene, *o) + ", which is opaque: it lights nothing outside it");
  }

  for (const Object& o : scene.objects) {
    if (const auto* m = std::get_if<MeshShape>(&o.shape); m && m->mesh->dropped > 0)
      add(Severity::kWarning, entry_mark(o),
          std::to_string(m->mesh->dropped) +
              " degenerate triangles (zero area or a repeated vertex) were dropped from this mesh");
    if (!bounds(o).is_bounded())
      add(Severity::kNote, entry_mark(o),
          std::string("the ") + shape_name(o) +
              " is unbounded: every ray tests it (fine for a floor or a backdrop)");
  }
  return found;
}

std::vector<Finding> validate_scene_file(const std::string& path) {
  try {
    const Scene scene = load_scene_file(path);
    return check_scene(scene);
  } catch (const SceneError& e) {
    return {{Severity::kError, e.file(), e.line(), e.column(), e.message()}};
  }
}

}  // namespace raycast

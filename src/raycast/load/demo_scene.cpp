#include "load/demo_scene.h"

#include "load/loader.h"

namespace raycast {

const char* demo_scene_text() {
  // The text starts right after the delimiter, so line numbers in messages count from 1.
  return R"yaml(# The built-in demo (`raycast render` with no scene): Whitted's 1980 picture, a mirror sphere and a
# glass sphere over a checkerboard, lit by one point light under a sky-blue background.
# The checkerboard is evaluated in object space with cells of size 1, so the floor sits at
# y = -0.5, in the middle of a cell: a floor on a cell boundary (y = 0) would flicker.
camera: {type: perspective, position: [0, 1.8, -7], look_at: [0, 0.4, 0], up: [0, 1, 0], fov: 40}
image: {width: 800, height: 600, samples: 4}
render: {integrator: whitted, max_depth: 8, background: [0.45, 0.65, 1.0], ambient: [0.12, 0.12, 0.14], seed: 1}
materials:
  floor:  {texture: {checker: {colors: [[0.95, 0.8, 0.15], [0.75, 0.08, 0.06]], scale: 1.0}}, diffuse: 0.85}
  mirror: {color: [0.9, 0.9, 0.9], ambient: 0.2, diffuse: 0.15, specular: 0.6, shininess: 120, reflection: 0.8}
  glass:  {color: [0.95, 0.97, 1.0], ambient: 0, diffuse: 0, specular: 0.8, shininess: 200, transmission: 0.95, ior: 1.5, fresnel: true}
lights:
  - {type: point, position: [-4, 8, -6], color: [1, 1, 1], intensity: 1.0}
objects:
  - name: floor
    plane: {normal: [0, 1, 0], point: [0, -0.5, 0]}
    material: floor
  - name: mirror ball
    sphere: {center: [1.1, 0.6, 1.2], radius: 1.1}
    material: mirror
  - name: glass ball
    sphere: {center: [-0.9, 0.35, -1.0], radius: 0.85}
    material: glass
)yaml";
}

Scene load_demo_scene() { return load_scene_text(demo_scene_text(), "<demo>"); }

}  // namespace raycast

#pragma once
// The built-in demo scene (`raycast render` with no SCENE): Whitted's mirror and glass spheres
// over a checkerboard. The same text is in scenes/demo.yaml (a test keeps the two identical).
#include "scene/scene.h"

namespace raycast {

/// The demo scene's YAML text.
const char* demo_scene_text();

/// The demo scene, loaded by the ordinary loader under the name "<demo>".
Scene load_demo_scene();

}  // namespace raycast

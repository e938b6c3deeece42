// POV-Ray 3.7 twin of bench/scenes/mesh.yaml (benchmark suite, docs/performance.md).
// bumpy.inc (bench/povray/make_mesh.py) holds the same vertices and triangles as bumpy.obj.
// Conventions as in analytic.pov.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 ambient_light rgb <0.1, 0.1, 0.1> }
#default { finish { ambient 1 diffuse 0.8 } }
#include "bumpy.inc"
camera {
  perspective
  location <0, 2.5, -7>
  right -x * image_width / image_height
  up y
  sky y
  angle 2 * degrees(atan(tan(radians(20)) * image_width / image_height))
  look_at <0, 0.8, 0>
}
background { rgb <0.5, 0.62, 0.85> }
light_source { <-6, 10, -8> color rgb <0.9, 0.9, 0.9> }
light_source { <8, 6, -4> color rgb <0.4, 0.4, 0.4> }
plane { y, -0.5 texture { pigment { checker rgb <0.9, 0.9, 0.88>, rgb <0.3, 0.32, 0.35> } } }
object {
  Bumpy
  scale 1.5
  translate <0, 1.2, 0>
  texture { pigment { rgb <0.8, 0.45, 0.3> } finish { phong 0.4 phong_size 50 } }
}

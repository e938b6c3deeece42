// POV-Ray 3.7 twin of bench/scenes/whitted.yaml (benchmark suite, docs/performance.md).
// Conventions as in analytic.pov: coordinates copied, right -x*aspect makes the frame right-handed,
// angle is the horizontal fov for raycast's vertical 40 degrees, #default is raycast's default
// material, max_trace_level = max_depth + 1 (POV-Ray counts the primary ray).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 11 ambient_light rgb <0.12, 0.12, 0.14> }
#default { finish { ambient 1 diffuse 0.8 } }
camera {
  perspective
  location <0, 1.8, -7>
  right -x * image_width / image_height
  up y
  sky y
  angle 2 * degrees(atan(tan(radians(20)) * image_width / image_height))
  look_at <0, 0.4, 0>
}
background { rgb <0.45, 0.65, 1.0> }
light_source { <-4, 8, -6> color rgb 1 }
plane {
  y, -0.5
  texture { pigment { checker rgb <0.95, 0.8, 0.15>, rgb <0.75, 0.08, 0.06> } finish { diffuse 0.85 } }
}
sphere {
  <1.1, 0.6, 1.2>, 1.1
  texture {
    pigment { rgb <0.9, 0.9, 0.9> }
    finish { ambient 0.2 diffuse 0.15 phong 0.6 phong_size 120 reflection 0.8 }
  }
}
sphere {
  <-0.9, 0.35, -1.0>, 0.85
  material {
    texture {
      pigment { rgbt <0.95, 0.97, 1.0, 0.95> }
      finish { ambient 0 diffuse 0 phong 0.8 phong_size 200 reflection { 0, 1 fresnel on } conserve_energy }
    }
    interior { ior 1.5 }
  }
}

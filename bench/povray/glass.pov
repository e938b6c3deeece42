// POV-Ray 3.7 twin of bench/scenes/glass.yaml (benchmark suite, docs/performance.md).
// Glass as in analytic.pov: raycast's transmission t, colour C, ior and Fresnel are rgbt <C, t>,
// reflection { 0, 1 fresnel on } with conserve_energy and interior ior. POV-Ray's shadows through
// transmit pigments are filtered like raycast's (transmission * C per object, unrefracted).
// Conventions otherwise as in analytic.pov; max_trace_level 9 is max_depth 8.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 9 ambient_light rgb <0.1, 0.1, 0.1> }
#default { finish { ambient 1 diffuse 0.8 } }
camera {
  perspective
  location <0, 2.6, -8>
  right -x * image_width / image_height
  up y
  sky y
  angle 2 * degrees(atan(tan(radians(20)) * image_width / image_height))
  look_at <0, 0.5, 0>
}
background { rgb <0.45, 0.6, 0.9> }
light_source { <-5, 9, -6> color rgb <0.9, 0.9, 0.9> }
light_source { <6, 7, -3> color rgb <0.5, 0.5, 0.5> }
plane { y, -0.5 texture { pigment { checker rgb <0.95, 0.95, 0.9>, rgb <0.2, 0.45, 0.3> } } }
#declare Glass = material {
  texture {
    pigment { rgbt <0.95, 0.97, 1.0, 0.95> }
    finish { ambient 0 diffuse 0 phong 0.8 phong_size 200 reflection { 0, 1 fresnel on } conserve_energy }
  }
  interior { ior 1.5 }
}
#declare Tinted = material {
  texture {
    pigment { rgbt <1.0, 0.75, 0.6, 0.9> }
    finish { ambient 0 diffuse 0 phong 0.8 phong_size 200 reflection { 0, 1 fresnel on } conserve_energy }
  }
  interior { ior 1.5 }
}
sphere { <-2.4, 0.4, 0.5>, 0.9 material { Glass } }
sphere { <0, 0.6, 1.6>, 1.1 material { Tinted } }
sphere { <2.3, 0.2, 0.2>, 0.7 material { Glass } }
sphere { <0.6, -0.05, -1.6>, 0.45 material { Glass } }
box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> material { Glass } rotate 30 * y translate <-1.1, 0.0, -1.8> }
sphere { <1.4, 0.1, 3.2>, 0.6 texture { pigment { rgb <0.8, 0.18, 0.15> } finish { phong 0.4 phong_size 60 } } }

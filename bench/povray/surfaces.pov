// POV-Ray 3.7 twin of bench/scenes/surfaces.yaml (benchmark suite, docs/performance.md).
// Conventions as in analytic.pov. The heart is a sturm polynomial inside its box, the implicit
// surfaces isosurfaces with contained_by boxes and max_gradient bounds checked by hand
// (sin/cos: |grad| <= 6.9 in its box; gyroid: each partial derivative is at most 2 in size, so
// |grad| <= 2 sqrt(3) < 3.5).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 ambient_light rgb <0.1, 0.1, 0.1> }
#default { finish { ambient 1 diffuse 0.8 } }
camera {
  perspective
  location <0, 3.2, -11.5>
  right -x * image_width / image_height
  up y
  sky y
  angle 2 * degrees(atan(tan(radians(20)) * image_width / image_height))
  look_at <0, 0.6, 0>
}
background { rgb <0.5, 0.62, 0.85> }
light_source { <-6, 10, -8> color rgb <0.8, 0.8, 0.8> }
light_source { <8, 6, -4> color rgb <0.5, 0.5, 0.5> }
plane { y, -0.5 texture { pigment { checker rgb <0.9, 0.9, 0.88>, rgb <0.3, 0.32, 0.35> } } }
torus {  // POV-Ray's torus is about y: raycast's (about z) is POV-Ray's turned by -90 about x
  1.0, 0.35
  rotate -90 * x
  rotate -60 * x
  translate <-4.2, 0.7, 0>
  texture { pigment { rgb <0.2, 0.35, 0.8> } finish { phong 0.4 phong_size 40 } }
}
intersection {  // (x^2 + 9/4 y^2 + z^2 - 1)^3 - x^2 z^3 - 9/80 y^2 z^3, expanded
  polynomial {
    6,
    xyz(6, 0, 0): 1, xyz(4, 2, 0): 6.75, xyz(4, 0, 2): 3, xyz(4, 0, 0): -3,
    xyz(2, 4, 0): 15.1875, xyz(2, 2, 2): 13.5, xyz(2, 2, 0): -13.5, xyz(2, 0, 4): 3,
    xyz(2, 0, 3): -1, xyz(2, 0, 2): -6, xyz(2, 0, 0): 3, xyz(0, 6, 0): 11.390625,
    xyz(0, 4, 2): 15.1875, xyz(0, 4, 0): -15.1875, xyz(0, 2, 4): 6.75, xyz(0, 2, 3): -0.1125,
    xyz(0, 2, 2): -13.5, xyz(0, 2, 0): 6.75, xyz(0, 0, 6): 1, xyz(0, 0, 4): -3,
    xyz(0, 0, 2): 3, xyz(0, 0, 0): -1
    sturm
  }
  box { <-1.5, -1, -1.5>, <1.5, 1, 1.5> }
  rotate -90 * x
  scale 1.1
  translate <-1.4, 0.8, 0>
  texture { pigment { rgb <0.8, 0.18, 0.15> } finish { phong 0.4 phong_size 60 } }
}
isosurface {
  function { (2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z) }
  contained_by { box { -4, 4 } }
  open
  max_gradient 7
  scale 0.2
  translate <1.4, 0.4, 0>
  texture { pigment { rgb <0.2, 0.65, 0.6> } finish { phong 0.4 phong_size 40 } }
}
isosurface {
  function { sin(x) * cos(y) + sin(y) * cos(z) + sin(z) * cos(x) }
  contained_by { box { -3, 3 } }
  max_gradient 3.5
  rotate 30 * y
  scale 0.3
  translate <4.2, 0.5, 0.5>
  texture { pigment { rgb <0.85, 0.65, 0.2> } finish { phong 0.5 phong_size 80 } }
}

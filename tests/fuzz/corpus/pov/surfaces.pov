// Higher-degree and meshed shapes: a quartic torus in a box, an isosurface, a lathe, a sor and
// a mesh2 pyramid (from an #include file), with POV-Ray's default handedness.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "pyramid.inc"
camera { location <0, 2.5, -7> look_at <0, 0.7, 0> angle 50 }
light_source { <-5, 7, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 scale 1 } finish { ambient 0.15 diffuse 0.7 } }
#declare R = 0.6; #declare r = 0.2;
intersection {  // (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2): a torus about y
  quartic {
    < 1, 0, 0, 0, 2, 0, 0, 2, 0, -2 * (R * R + r * r),
      0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
      1, 0, 0, 2, 0, 2 * (R * R - r * r), 0, 0, 0, 0,
      1, 0, -2 * (R * R + r * r), 0, pow(R * R - r * r, 2) >
  }
  box { <-1, -0.3, -1>, <1, 0.3, 1> }
  pigment { rgb <0.2, 0.4, 0.9> } finish { phong 0.5 }
  rotate -35 * x
  translate <-2, 0.8, 0>
}
isosurface {
  function { x * x + y * y * 2 + z * z - 0.36 }
  contained_by { box { -1, 1 } }
  max_gradient 4
  pigment { rgb <0.9, 0.4, 0.2> }
  translate <-0.4, 0.5, -1.2>
}
lathe {
  linear_spline 5,
  <0, 0>, <0.5, 0>, <0.3, 0.6>, <0.45, 1.2>, <0, 1.2>
  pigment { rgb <0.3, 0.8, 0.5> }
  translate <0.7, 0, 0.8>
}
sor {
  6,
  <0, -0.1>, <0.4, 0>, <0.25, 0.5>, <0.35, 0.9>, <0.2, 1.2>, <0, 1.3>
  pigment { rgb <0.8, 0.7, 0.3> }
  translate <2.1, 0, -0.4>
}
object { Pyramid pigment { rgb <0.7, 0.3, 0.7> } translate <1.8, 0, 2.2> }

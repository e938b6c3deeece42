// POV-Ray twin of scenes/csg.yaml (same geometry, camera, light and materials), for
// bench/compare_povray.sh. `right -x*...` makes POV-Ray's frame right-handed like raycast's, so
// coordinates are copied unchanged. Planes are written with unit normals and their distances.
// POV-Ray's torus lies in the xz plane (axis y): raycast's (axis z) is turned 90 degrees about x.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 5 }

camera {
  perspective
  location <0, 3.5, -10>
  look_at <0, 0.9, 0>
  sky y
  up y
  right -x*image_width/image_height
  // raycast's fov is vertical (40 degrees); POV-Ray's angle is horizontal.
  angle 2*degrees(atan(tan(radians(20))*image_width/image_height))
}
background { rgb <0.6, 0.7, 1.0> }
light_source { <5, 8, -6> color rgb 1 }

#declare F_Plain = finish { ambient 0.1 diffuse 0.8 }
#declare M_Red = texture { pigment { rgb <0.8, 0.2, 0.2> } finish { F_Plain phong 0.5 phong_size 60 } }
#declare M_Blue = texture { pigment { rgb <0.2, 0.3, 0.8> } finish { F_Plain phong 0.5 phong_size 60 } }
#declare M_Gold = texture { pigment { rgb <0.9, 0.7, 0.2> } finish { F_Plain phong 0.3 phong_size 30 } }
#declare M_Green = texture { pigment { rgb <0.2, 0.7, 0.3> } finish { F_Plain phong 0.3 phong_size 30 } }
#declare M_White = texture { pigment { rgb <0.9, 0.9, 0.9> } finish { F_Plain phong 0.2 phong_size 20 } }
#declare M_Default = texture { pigment { rgb <0.8, 0.8, 0.8> } finish { F_Plain } }

plane { <0, 1, 0>, -0.001
  texture { pigment { checker rgb 0.9 rgb 0.3 } finish { ambient 0.1 diffuse 0.8 } }
}

// Seed 000: the cube minus the sphere, turned 30 degrees about y (right-hand rule) and moved.
difference {
  box { <-1, -1, -1>, <1, 1, 1> }
  sphere { <0, 0, 0>, 1.3 }
  matrix <0.8660254037844387, 0, -0.5, 0, 1, 0, 0.5, 0, 0.8660254037844387, 0, 0, 0>
  translate <-2.6, 1, 1>
  texture { M_Red }
}

// Three orthogonal capped cylinders intersected, minus a sphere with its own material.
difference {
  intersection {
    cylinder { <-1, 0, 0>, <1, 0, 0>, 1 }
    cylinder { <0, -1, 0>, <0, 1, 0>, 1 }
    cylinder { <0, 0, -1>, <0, 0, 1>, 1 }
    texture { M_Blue }
  }
  sphere { <0, 0, -1>, 0.8 texture { M_Gold } }
  translate <2.6, 1, 1>
}

// A torus with a notch, and a drilled cone.
difference {
  torus { 0.9, 0.3 }
  box { <-0.5, -0.5, -1.5>, <0.5, 0.5, -0.5> }
  translate <1.6, 0.3, 4.8>
  texture { M_Gold }
}
difference {
  cone { <0, 0, 0>, 0.9, <0, 2.2, 0>, 0 }
  cylinder { <0, 0.8, -1>, <0, 0.8, 1>, 0.25 }
  translate <-1.5, 0, 5>
  texture { M_White }
}

// The lens.
intersection {
  sphere { <0, 0, -1.2>, 1.5 }
  sphere { <0, 0, 1.2>, 1.5 }
  translate <0, 1, 2.5>
  texture { M_White }
}

// The clipped sphere and the union of three spheres.
union {
  intersection {
    sphere { <0, 0, 0>, 0.8 }
    plane { <1, 1, -1>, 0.34641016151377546 }  // through (0.2, 0.2, -0.2), unit normal (1,1,-1)/sqrt(3)
    translate <-1, 0.8, -1.5>
  }
  union {
    sphere { <1.2, 0.5, -1.5>, 0.5 }
    sphere { <1.2, 1.1, -1.5>, 0.35 }
    sphere { <1.2, 1.5, -1.5>, 0.25 }
  }
  texture { M_Green }
}

// The library's nut, declared once and used five times.
#macro Nut(Body)
  difference {
    sphere { <0, 0, 0>, 0.45 texture { Body } }
    box { <-0.2, -1, -0.2>, <0.2, 1, 0.2> texture { M_Gold } }
  }
#end
object { Nut(M_Red) translate <-2, 0.45, -3.5> }
object { Nut(M_Blue) translate <-1, 0.45, -3.5> }
object { Nut(M_Green) translate <0, 0.45, -3.5> }
object { Nut(M_White) translate <1, 0.45, -3.5> }
object { Nut(M_Default) scale 1.3 translate <2, 0.585, -3.5> }

// CSG and declared objects and textures, a torus, a disc and a quadric, under a camera with
// POV-Ray's default handedness.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Red = texture { pigment { rgb <0.85, 0.25, 0.2> } finish { ambient 0.15 diffuse 0.7 phong 0.4 } }
#declare Gold = texture { pigment { rgb <0.9, 0.7, 0.2> } finish { ambient 0.15 diffuse 0.7 } }
#declare Nut = difference {
  sphere { 0, 0.6 }
  box { <-0.25, -1, -0.25>, <0.25, 1, 0.25> texture { Gold } }
}
camera { location <1, 3, -7> look_at <0, 0.5, 0> angle 45 }
light_source { <5, 8, -6> color rgb <1, 1, 1> }
light_source { <-6, 4, -2> color rgb 0.4 }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.2 diffuse 0.6 } }
object { Nut texture { Red } translate <-1.8, 0.6, 0> }
intersection {
  sphere { <0, 0, -0.5>, 1 }
  sphere { <0, 0, 0.5>, 1 }
  texture { Gold }
  rotate <0, 40, 20>
  translate <0, 0.8, 1.5>
}
merge {
  cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.3 }
  cylinder { <0, -0.8, 0>, <0, 0.8, 0>, 0.3 }
  pigment { rgb <0.3, 0.5, 0.9> }
  translate <1.8, 0.9, 0>
}
torus { 0.7, 0.2 rotate -30 * x translate <0, 0.5, -1.5> texture { Red } }
disc { <-2.5, 0.02, -2>, y, 0.6, 0.3 pigment { rgb <0.2, 0.7, 0.3> } }
intersection {  // a hyperboloid of one sheet cut by a box
  quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.1 }
  box { <-0.7, -0.8, -0.7>, <0.7, 0.8, 0.7> }
  pigment { rgb <0.7, 0.4, 0.8> }
  translate <2.8, 0.8, 2.2>
}

// A spherical lens (360 by 120 degrees) with a skewed right vector, inside a ring of objects: the
// lens, its angles and POV-Ray's frame convert to YAML and render the same.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { spherical angle 360, 120 location <0, 1, 0> right <1.5, 0, 0.2> look_at <1, 1, 4> }
background { rgb <0.4, 0.5, 0.7> }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9>, rgb <0.2, 0.3, 0.2> } }
sphere { <0, 1, 4>, 1 pigment { rgb <0.8, 0.2, 0.2> } }
box { <-1, 0, -1>, <1, 2, 1> translate <4, 0, 0> pigment { rgb <0.2, 0.4, 0.9> } }
cylinder { <-4, 0, 0>, <-4, 2, 0>, 0.7 pigment { rgb <0.9, 0.8, 0.2> } }
cone { <0, 0, -4>, 1, <0, 2, -4>, 0 pigment { rgb <0.3, 0.8, 0.4> } }

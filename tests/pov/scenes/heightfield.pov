// Height fields: a PGM terrain (its top rows at the back), smooth and cut by a water level, and
// a function's field, with POV-Ray's default handedness.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -4.5> look_at <0, 0.2, 0> angle 50 }
light_source { <-5, 7, -6> color rgb 1 }
plane { y, -0.01 pigment { rgb <0.2, 0.3, 0.6> } }
height_field { pgm "hills.pgm" smooth water_level 0.3
  translate <-0.5, 0, -0.5> scale <3, 0.8, 2> translate <-1.2, 0, 0.5>
  pigment { rgb <0.4, 0.7, 0.3> } }
height_field { function 20, 12 { 0.5 + 0.4 * sin(6 * x) * y }
  translate <-0.5, 0, -0.5> scale <1.6, 0.6, 1.6> translate <1.6, 0, -0.3>
  pigment { rgb <0.8, 0.5, 0.3> } }

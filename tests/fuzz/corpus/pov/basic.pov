// POV-Ray's own left-handed camera (right +x): the import negates z. A checkered floor, a
// shiny sphere, a turned box, a cylinder and a cone, one point light.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0, 2, -6> look_at <0, 0.6, 0> angle 50 right x * 4 / 3 }
background { rgb <0.4, 0.5, 0.7> }
light_source { <-4, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9>, rgb <0.2, 0.3, 0.2> } finish { ambient 0.2 diffuse 0.7 } }
sphere { <-1.3, 0.8, 0.5>, 0.8 pigment { rgb <0.8, 0.2, 0.2> } finish { ambient 0.1 diffuse 0.7 phong 0.6 phong_size 40 } }
box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> rotate 35 * y translate <1.2, 0, 0.3>
      pigment { rgb <0.2, 0.4, 0.9> } finish { diffuse 0.8 } }
cylinder { <0.2, 0, -1.6>, <0.6, 1.1, -1.2>, 0.25 pigment { rgb <0.9, 0.8, 0.2> } }
cone { <2.4, 0, 2>, 0.6, <2.4, 1.4, 2>, 0 pigment { rgb <0.3, 0.8, 0.4> } }

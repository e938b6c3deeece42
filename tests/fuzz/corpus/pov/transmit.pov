// A half-transparent red sphere (rgbt) over a green background: POV-Ray weighs the surface's own
// ambient and diffuse light by its opacity (1 - transmit), which the import carries over.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -4> look_at 0 angle 40 }
background { rgb <0.2, 0.6, 0.2> }
light_source { <-3, 4, -5> color rgb 1 }
sphere { 0, 1 pigment { rgbt <1, 0.2, 0.2, 0.5> } finish { ambient 0.1 diffuse 0.6 } }

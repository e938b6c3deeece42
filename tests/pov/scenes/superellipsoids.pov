// Superellipsoids: rounded boxes, the octahedron <2, 2>, a star-shaped <3, 0.5> and a rounded
// box with a sphere taken out, with POV-Ray's default handedness.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 7, -6> color rgb 1 }
plane { y, 0 pigment { rgb 0.6 } finish { ambient 0.15 diffuse 0.7 } }
superellipsoid { <0.2, 0.2> scale 0.6 rotate <-15, 30, 0> translate <-2, 0.8, 0>
  pigment { rgb <0.2, 0.4, 0.9> } finish { phong 0.5 } }
superellipsoid { <2, 2> scale 0.8 translate <0, 0.8, 0> pigment { rgb <0.9, 0.4, 0.2> } }
superellipsoid { <3, 0.5> scale 0.7 rotate 90 * x translate <2, 0.7, 0>
  pigment { rgb <0.3, 0.8, 0.5> } }
difference {
  superellipsoid { <0.3, 1> }
  sphere { <0, 0, -1>, 0.7 }
  scale 0.6 rotate -20 * y translate <-0.8, 0.6, 2>
  pigment { rgb <0.8, 0.7, 0.3> }
}

// A blob of spheres and cylinders, with a negative component (in the old syntax) and component
// transformations, with POV-Ray's default handedness.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 7, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.35 } }
blob {
  threshold 0.6
  sphere { <-1, 0.8, 0>, 1, 1 }
  sphere { <0, 0.8, 0>, 0.6, 1 scale <2, 1, 1> rotate 30 * z }
  cylinder { <0, 0.4, -0.5>, <1.5, 1.2, 0.5>, 0.5, strength 1.2 }
  component -0.8, 0.5, <-1.2, 1.2, -0.6>
  pigment { rgb <0.8, 0.3, 0.2> }
  finish { phong 0.5 }
  rotate 20 * y
}

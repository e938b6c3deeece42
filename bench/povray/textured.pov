// POV-Ray 3.7 twin of bench/scenes/textured.yaml (benchmark suite, docs/performance.md).
// globe.png is bench/scenes/globe.png (bench/povray/make_texture.py). raycast's sphere has its
// pole on z and u = atan2(y, x) / 2 pi; turned by -90 about x its pole is +y and its u runs from
// +x towards -z. POV-Ray's spherical map (map_type 1) has its pole on y and u = atan2(x, z) / 2 pi,
// from +z towards +x: the POV-Ray sphere is mirrored in x (u runs the other way) and turned 90
// degrees about y (seams together). The two renders agree to an RMSE of 1e-5 at 320x240.
// Conventions otherwise as in analytic.pov.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 ambient_light rgb <0.1, 0.1, 0.1> }
#default { finish { ambient 1 diffuse 0.8 } }
camera {
  perspective
  location <0, 2.5, -9>
  right -x * image_width / image_height
  up y
  sky y
  angle 2 * degrees(atan(tan(radians(20)) * image_width / image_height))
  look_at <0, 0.7, 0>
}
background { rgb <0.5, 0.62, 0.85> }
light_source { <-6, 10, -8> color rgb <0.9, 0.9, 0.9> }
light_source { <8, 6, -4> color rgb <0.4, 0.4, 0.4> }
plane { y, -0.5 texture { pigment { checker rgb <0.9, 0.9, 0.88>, rgb <0.3, 0.32, 0.35> } } }
#declare Globe = texture {
  pigment { image_map { png "globe.png" gamma srgb map_type 1 interpolate 2 } }
  finish { phong 0.3 phong_size 40 }
}
sphere { 0, 1 texture { Globe } scale <-1, 1, 1> rotate 90 * y translate <-2.6, 0.5, 0.5> }
sphere { 0, 1 texture { Globe } scale <-1, 1, 1> rotate 90 * y scale 1.3 rotate 60 * y translate <0.2, 0.8, 1.5> }
sphere { 0, 1 texture { Globe } scale <-1, 1, 1> rotate 90 * y scale 0.8 rotate 140 * y translate <2.7, 0.3, -0.5> }
box {
  <-0.6, -0.5, -0.6>, <0.6, 0.7, 0.6>
  texture {
    pigment { checker rgb <0.85, 0.2, 0.2>, rgb <0.95, 0.95, 0.9> scale 0.25 }
    finish { phong 0.2 phong_size 20 }
  }
  rotate 35 * y
  translate <-1.0, 0.0, -2.2>
}

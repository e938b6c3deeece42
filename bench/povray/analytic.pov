// POV-Ray 3.7 twin of scenes/analytic.yaml (the same coordinates, objects and materials), timed
// against raycast by bench/compare_povray.sh analytic. Render alone with:
//   povray +Ibench/povray/analytic.pov +Oanalytic-pov.png +W1280 +H720 -A -D +FN
// Matching raycast's conventions (docs/rendering.md):
// - raycast's frame is right-handed; POV-Ray's is left-handed. Every coordinate is copied as is
//   and the camera's right vector is negated (right -x*aspect), which mirrors the image back.
//   Rotation matrices are the same in both (POV-Ray's rotate <a,0,0> is raycast's rotate about x
//   by a degrees).
// - raycast's fov is the vertical angle; POV-Ray's angle is the horizontal one.
// - whitted shading: ambient * ambient_light * C + sum_lights (diffuse * C * n.l + phong highlight).
//   #default gives raycast's default material (ambient 1, diffuse 0.8); ambient_light is the
//   scene's render.ambient; phong/phong_size are raycast's specular/shininess (untinted highlights).
// - raycast max_depth counts secondary rays, POV-Ray's max_trace_level counts levels including
//   the primary ray: max_depth 5 -> max_trace_level 6.
// - No radiosity, no antialiasing (-A), against raycast --spp 1.
#version 3.7;

global_settings {
  assumed_gamma 1.0
  max_trace_level 6
  ambient_light rgb <0.1, 0.1, 0.1>
}

#default { finish { ambient 1 diffuse 0.8 } }

#declare Aspect = image_width / image_height;
camera {
  perspective
  location <0, 4, -13>
  right -x * Aspect
  up y
  sky y
  angle 2 * degrees(atan(tan(radians(40 / 2)) * Aspect))
  look_at <0, 0.6, 2>
}

background { rgb <0.5, 0.62, 0.85> }

light_source { <-6, 10, -8> color rgb <0.8, 0.8, 0.8> }
light_source { <8, 6, -4> color rgb <0.5, 0.5, 0.5> }

#declare Red = texture { pigment { rgb <0.8, 0.18, 0.15> } finish { phong 0.4 phong_size 60 } }
#declare Gold = texture { pigment { rgb <0.85, 0.65, 0.2> } finish { phong 0.5 phong_size 80 } }
#declare Blue = texture { pigment { rgb <0.2, 0.35, 0.8> } finish { phong 0.4 phong_size 40 } }
#declare Green = texture { pigment { rgb <0.25, 0.7, 0.3> } finish { phong 0.3 phong_size 30 } }
#declare Teal = texture { pigment { rgb <0.2, 0.65, 0.6> } finish { phong 0.4 phong_size 40 } }
#declare Mirror = texture {
  pigment { rgb <0.9, 0.9, 0.9> }
  finish { ambient 0.2 diffuse 0.15 phong 0.6 phong_size 120 reflection 0.8 }
}
// raycast: transmission 0.95, ior 1.5, fresnel (w_reflect = 0.95 F, w_refract = 0.95 (1 - F)),
// no local diffuse or ambient, untinted refraction: transmit (not filter) with Fresnel reflection.
#declare Glass = material {
  texture {
    pigment { rgbt <0.95, 0.97, 1.0, 0.95> }
    finish { ambient 0 diffuse 0 phong 0.8 phong_size 200 reflection { 0, 1 fresnel on } conserve_energy }
  }
  interior { ior 1.5 }
}

// The floor: the half-space y < -0.5 with a checker of cell 1 in world space.
plane {
  y, -0.5
  texture { pigment { checker rgb <0.9, 0.9, 0.88>, rgb <0.3, 0.32, 0.35> } }
}

// Back row (z = 5).
sphere { 0, 1 scale <1.2, 1, 0.8> translate <-7, 0.6, 5> texture { Red } }  // ellipsoid

intersection {  // hyperboloid of one sheet, a = 0.5, c = 1, closed by its box
  quadric { <4, 4, -1>, <0, 0, 0>, <0, 0, 0>, -1 }
  box { <-1.2, -1.2, -1>, <1.2, 1.2, 1> }
  rotate -90 * x
  translate <-4.3, 0.55, 5>
  texture { Gold }
}

torus {  // POV-Ray's torus is about y: raycast's about z turned by -90 about x
  0.9, 0.3
  rotate 25 * z
  translate <-1.6, 0.5, 5>
  texture { Blue }
}

intersection {  // the heart, (x^2 + 9/4 y^2 + z^2 - 1)^3 - x^2 z^3 - 9/80 y^2 z^3, expanded
  polynomial {
    6,
    xyz(6, 0, 0): 1, xyz(4, 2, 0): 6.75, xyz(4, 0, 2): 3, xyz(4, 0, 0): -3,
    xyz(2, 4, 0): 15.1875, xyz(2, 2, 2): 13.5, xyz(2, 2, 0): -13.5, xyz(2, 0, 4): 3,
    xyz(2, 0, 3): -1, xyz(2, 0, 2): -6, xyz(2, 0, 0): 3, xyz(0, 6, 0): 11.390625,
    xyz(0, 4, 2): 15.1875, xyz(0, 4, 0): -15.1875, xyz(0, 2, 4): 6.75, xyz(0, 2, 3): -0.1125,
    xyz(0, 2, 2): -13.5, xyz(0, 2, 0): 6.75, xyz(0, 0, 6): 1, xyz(0, 0, 4): -3,
    xyz(0, 0, 2): 3, xyz(0, 0, 0): -1
    sturm  // without Sturm sequences POV-Ray's solver leaves holes at the heart's cusps
  }
  box { <-1.5, -1, -1.5>, <1.5, 1, 1.5> }
  rotate -90 * x
  scale 0.9
  translate <1.2, 0.6, 5>
  texture { Red }
}

quadric {  // open paraboloid x^2/a^2 + y^2/a^2 - z/c = 0, a = 0.6, c = 1, clipped (not closed)
  <2.77777777777778, 2.77777777777778, 0>, <0, 0, 0>, <0, 0, -1>, 0
  clipped_by { box { <-2, -2, 0>, <2, 2, 1.5> } }
  rotate -90 * x
  translate <3.8, -0.3, 5>
  texture { Green }
}

isosurface {  // the seed's implicit surface; |grad f| <= 6.9 inside the box (checked by hand)
  function { (2 - cos(x)) * cos(z) + (y + sin(x)) * sin(z) + cos(x + z) }
  contained_by { box { -4, 4 } }
  max_gradient 7
  scale 0.17
  translate <6.6, 0.3, 5>
  texture { Teal }
}

// Middle row (z = 1.5).
sphere { <-4.5, 0.7, 1.5>, 1.2 texture { Mirror } }
sphere { <-1.4, 0.35, 0.2>, 0.85 material { Glass } }

sphere {  // partial sphere: z in [-0.6, 0.8], phi in [0, 270] degrees (x > 0, y < 0 cut away)
  0, 0.9
  clipped_by {
    intersection {
      union { plane { x, 0 } plane { -y, 0 } }
      plane { z, 0.8 }
      plane { -z, 0.6 }
    }
  }
  rotate -90 * x
  rotate 200 * y
  translate <1.3, 0.45, 1.5>
  texture { Gold }
}

#declare S = 1 / sqrt(3);
intersection {  // the octahedron |x| + |y| + |z| <= 0.9 as eight half-spaces
  plane { <1, 1, 1> * S, 0.9 * S }
  plane { <1, 1, -1> * S, 0.9 * S }
  plane { <1, -1, 1> * S, 0.9 * S }
  plane { <1, -1, -1> * S, 0.9 * S }
  plane { <-1, 1, 1> * S, 0.9 * S }
  plane { <-1, 1, -1> * S, 0.9 * S }
  plane { <-1, -1, 1> * S, 0.9 * S }
  plane { <-1, -1, -1> * S, 0.9 * S }
  rotate 20 * y
  translate <3.8, 0.5, 1.5>
  texture { Red }
}

box { <-0.6, -0.5, -0.6>, <0.6, 0.5, 0.6> rotate 30 * y translate <6.4, 0.05, 1.5> texture { Blue } }

// Front row (z = -2).
cylinder { <-5.6, -0.2, -2.2>, <-4.4, 0.9, -1.6>, 0.45 texture { Green } }
cone { <-2.5, -0.4, -2>, 0.7, <-2.5, 1.2, -2>, 0.2 texture { Gold } }
disc { <0.3, 0.5, -2>, <0.3, 0.4, -1>, 0.75, 0.3 texture { Teal } }
polygon {
  6,
  <2.3, -0.4, -2>, <3.7, -0.4, -2>, <3.7, 1.2, -2>, <3, 0.5, -2>, <2.3, 1.2, -2>, <2.3, -0.4, -2>
  texture { Green }
}

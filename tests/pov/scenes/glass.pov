// A mirror sphere and a glass sphere over a checkered floor: reflection, refraction with Fresnel,
// a spotlight. The camera's right vector is -x (right-handed, as in the benchmark suite): the
// import then copies coordinates unchanged.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 ambient_light rgb 0.3 }
camera { location <0, 1.8, -6> look_at <0, 0.7, 0> right -x * image_width / image_height angle 48 }
background { rgb <0.5, 0.6, 0.8> }
light_source { <3, 7, -5> color rgb 1 spotlight point_at <0, 0, 0> radius 20 falloff 30 }
light_source { <-5, 5, -4> color rgb 0.5 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.85>, rgb <0.25, 0.3, 0.5> } finish { ambient 0.3 diffuse 0.7 } }
sphere { <-1.1, 0.9, 0.6>, 0.9 pigment { rgb 0.85 } finish { ambient 0.05 diffuse 0.1 reflection 0.8 phong 0.8 phong_size 120 } }
sphere { <1.0, 0.8, -0.4>, 0.8
  material {
    texture { pigment { rgbt <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 phong 0.8 phong_size 200 reflection { 0, 1 fresnel on } conserve_energy } }
    interior { ior 1.5 }
  }
}

#pragma once
// A finish (docs/textures.md "Finishes"): how a surface takes light, POV-Ray's terms.
namespace raycast::texture {

struct Finish {
  double ambient = 0.1;   // times the scene's ambient light and the pigment
  double diffuse = 0.6;   // Lambert's term, raised to `brilliance`
  double brilliance = 1;  // diffuse falls off as (N.L)^brilliance
  double phong = 0;       // Phong highlight: phong * (R.V)^phong_size
  double phong_size = 40;
  double specular = 0;  // Blinn highlight: specular * (N.H)^(1/roughness)
  double roughness = 0.05;
  double metallic = 0;  // highlights take the pigment's colour by this fraction
  double reflection_min = 0, reflection_max = 0;  // mirror weight, facing and grazing
  bool reflection_fresnel = false;                // between min and max by the Fresnel reflectance
  double reflection_falloff = 1;                  // else by (1 - cos)^falloff
  bool reflection_metallic = false;               // the reflection is tinted by the pigment
  double crand = 0;  // graininess: the lit colour is darkened by up to crand at random
};

}  // namespace raycast::texture

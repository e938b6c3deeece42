#pragma once
#include "scene/material.h"

namespace raycast {

enum class LightType { kPoint, kDirectional, kSpot, kSphere };
enum class Attenuation { kNone, kInverseSquare };

/// A light; which fields matter depends on `type` (docs/scene-format.md "Lights").
struct Light {
  LightType type = LightType::kPoint;
  Color color{1, 1, 1};
  double intensity = 1;
  Vec3 position;             // point, spot, sphere (centre)
  Vec3 direction{0, -1, 0};  // directional, spot: where the light travels (unit)
  double angle = 30;         // spot: half-angle of the cone, degrees
  double falloff = 5;        // spot: degrees of the soft edge inside `angle`
  double radius = 0;         // sphere light
  int samples = 16;          // sphere light: shadow rays per shading point
  Attenuation attenuation = Attenuation::kNone;

  Color emitted() const { return intensity * color; }
};

}  // namespace raycast

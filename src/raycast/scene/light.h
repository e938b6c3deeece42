#pragma once
#include "scene/material.h"

namespace raycast {

enum class LightType { kPoint, kDirectional, kSpot, kSphere, kCylinder, kArea };
/// kFade: POV-Ray's 2 / (1 + (d / fade_distance)^fade_power), full light at fade_distance.
enum class Attenuation { kNone, kInverseSquare, kFade };
/// A spot's soft edge: smoothstep over the angle (kAngle) or over its cosine (kCosine, as
/// POV-Ray's spotlight).
enum class SpotEdge { kAngle, kCosine };

/// A light; which fields matter depends on `type` (docs/scene-format.md "Lights").
struct Light {
  LightType type = LightType::kPoint;
  Color color{1, 1, 1};
  double intensity = 1;
  Vec3 position;             // point, spot, sphere (centre), cylinder, area (centre)
  Vec3 direction{0, -1, 0};  // directional, spot, cylinder: where the light travels (unit)
  double angle = 30;         // spot: half-angle of the cone, degrees; cylinder: its radius
  double falloff = 5;        // spot: degrees of the soft edge inside `angle` (cylinder: units)
  double tightness = 0;      // spot, cylinder: the light times cos(angle off the axis)^tightness
  SpotEdge edge = SpotEdge::kAngle;
  double radius = 0;  // sphere light
  int samples = 16;   // sphere light: shadow rays per shading point
  Attenuation attenuation = Attenuation::kNone;
  double fade_distance = 1, fade_power = 2;  // Attenuation::kFade
  bool shadows = true;                       // false: nothing blocks it (POV-Ray's shadowless)
  bool bounded = false;  // directional: only objects below the plane through `position`
                         // (perpendicular to `direction`) cast shadows (POV-Ray's parallel)
  // Area light: a grid of size1 x size2 points over the parallelogram axis1 x axis2 centred at
  // `position` (corners included), each with 1/(size1 size2) of the light; `jitter` moves each
  // point at random within its cell, `circular` squeezes the grid into the inscribed ellipse,
  // `orient` turns it to face the lit point. With `spot`, a spot cone (direction, angle,
  // falloff, tightness, edge) shapes it. `adaptive` >= 0 (POV-Ray's adaptive N): the corners
  // of the grid's (2^N + 1)^2 coarse cells are sampled first, and a cell is split where its
  // corners differ; -1: every point sampled.
  Vec3 axis1{1, 0, 0}, axis2{0, 0, 1};
  int size1 = 2, size2 = 2;
  int adaptive = -1;
  bool jitter = false, circular = false, orient = false, spot = false;

  Color emitted() const { return intensity * color; }
};

}  // namespace raycast

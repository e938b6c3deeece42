#pragma once
// raycast's public C++ API (docs/library.md): include this header and link raycast::raycast.
#include "raycast/api/scene.h"
#include "raycast/api/types.h"
#include "raycast/version.h"

namespace raycast {
using api::Camera;
using api::Crossing;
using api::CsgOp;
using api::GridSurface;
using api::HitColumns;
using api::Image;
using api::kNoObject;
using api::Light;
using api::Material;
using api::MaterialId;
using api::NotImplementedError;
using api::ObjectId;
using api::ParticleSurface;
using api::Ray;
using api::RayArray;
using api::RenderOptions;
using api::Scene;
using api::SceneError;
using api::SurfaceInfo;
using api::Transform;
using api::Vec3d;
}  // namespace raycast

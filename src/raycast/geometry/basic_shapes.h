#pragma once
// The first shapes beyond sphere and plane, in one include for the scene's variant.
#include "geometry/box.h"
#include "geometry/disk.h"
#include "geometry/parallelogram.h"
#include "geometry/triangle.h"

#pragma once
// The shared geometry of a library entry: its objects (placed in the entry's space) and a BVH.
#include <cstdint>
#include <memory>
#include <vector>

#include "objects/object.h"
#include "objects/object_set.h"

namespace raycast {

/// Objects' material -1 means the instance's. Objects are never instances themselves (nested
/// `use` is expanded when the prototype is built), so a hit needs one LocalHit::inner level.
struct Prototype {
  std::vector<Object> objects;
  ObjectSet set;  // their BVH and the walks over it (the same as the scene's top level)

  /// Bytes held by this prototype (objects, BVH, index arrays), shared by all its instances.
  std::size_t memory_bytes() const;
};

/// Builds the BVH and freezes the prototype. Throws std::invalid_argument if an object is an
/// instance.
std::shared_ptr<const Prototype> make_prototype(std::vector<Object> objects);

/// The material of the prototype object that made `hit` (-1: the instance's own).
int instance_material(const InstanceShape& s, const LocalHit& hit);

}  // namespace raycast

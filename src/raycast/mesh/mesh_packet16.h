#pragma once
// Packets of sixteen rays: one 16-lane packet where the kernels have 512-bit registers
// (AVX-512: mesh/packet_lanes16.inl), two 8-ray packets elsewhere. The answers are those of
// intersect8 / intersect_closest8 on each half, bit for bit (and so those of single rays).
#include "geometry/hit.h"
#include "geometry/ray.h"
#include "math/isa.h"
#include "mesh/mesh.h"
#include "mesh/mesh_bvh.h"

namespace raycast {

/// The most rays `isa`'s kernels trace as one packet: 16 with AVX-512, else 8.
int packet_width(Isa isa);

/// intersect_closest8 (mesh/mesh_bvh.h, the double-ray overload) on up to sixteen rays (rays[l]
/// for each bit l of mask) with `isa`'s kernels (supported by the CPU): the same hits and scales.
/// Returns the mask of the rays that hit, or -1, with nothing traced, when a ray's direction
/// needs to_mesh_ray's slow path.
int intersect_closest16(const MeshBvh& bvh, Isa isa, const Ray* rays, int mask, MeshBvhHit* hits,
                        double* scale);

/// intersect8 (mesh/mesh.h) on up to sixteen rays with the active ISA's kernels: the same hits.
int intersect16(const MeshShape& s, const Ray* rays, int mask, LocalHit* hits);

}  // namespace raycast

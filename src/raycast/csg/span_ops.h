#pragma once
// Boolean operations on span lists: the heart of CSG on ray intervals (Roth 1982). A linear merge
// of two sorted lists; knows no concrete shape.
#include <cstdint>

#include "geometry/span_list.h"

namespace raycast {

enum class CsgOp : std::uint8_t { kUnion, kIntersection, kDifference };

/// Whether a point inside `a` (or not) and inside `b` (or not) is inside `a op b`.
constexpr bool csg_inside(CsgOp op, bool a, bool b) {
  switch (op) {
    case CsgOp::kUnion:
      return a || b;
    case CsgOp::kIntersection:
      return a && b;
    case CsgOp::kDifference:
      return a && !b;
  }
  return false;
}

/// out = a op b, for a and b sorted by t and disjoint (touching allowed), as shapes produce them.
/// The operation is regularised (the coincident-boundary rule): the result is the closure of the
/// open gaps between consecutive distinct end values where `op` holds. Hence no zero-length span
/// ever results, touching result spans are merged into one, and boundaries of a and b at exactly
/// the same t cancel or merge as the solids do (a box minus an equal box is empty). Equality of t
/// is exact, so the answer is deterministic. Each result end is the crossing of the operand that
/// makes the result change there (the first operand when both do); ends taken from b in a
/// difference have `flip` toggled. out must not alias a or b; no allocation unless out outgrows
/// its inline capacity.
void combine_spans(CsgOp op, const SpanList& a, const SpanList& b, SpanList& out);

/// The complement of a solid's spans over the whole line (POV-Ray's `inverse`), in place: the
/// gaps between the spans, with ends at -inf or +inf (part kNoSurface) where the spans leave the
/// line open. Each end keeps the crossing it had (the caller flips the normals). `spans` must
/// be sorted and disjoint, as shapes produce them.
void complement_spans(SpanList& spans);

}  // namespace raycast

#include "csg/span_ops.h"

namespace raycast {

namespace {

// Walks one operand's ends in order: in0, out0, in1, out1, ...
struct Cursor {
  const SpanList& list;
  std::size_t k = 0;

  bool done() const { return k >= 2 * list.size(); }
  const LocalHit& end() const { return k % 2 ? list[k / 2].out : list[k / 2].in; }
  bool is_entry() const { return k % 2 == 0; }
};

// What one operand does at one value of t: its state in the gap after t, and its last entry and
// exit there.
struct Step {
  bool before = false;
  bool after = false;
  const LocalHit* entry = nullptr;
  const LocalHit* exit = nullptr;
  bool changed() const { return before != after; }
  const LocalHit* crossing() const { return after ? entry : exit; }
};

// Consumes every end of c at exactly t (at least one when `force`, so that a NaN cannot stall the
// merge).
Step advance(Cursor& c, double t, bool state, bool force) {
  Step s;
  s.before = s.after = state;
  while (!c.done() && (force || c.end().t == t)) {
    if (c.is_entry()) {
      s.entry = &c.end();
      s.after = true;
    } else {
      s.exit = &c.end();
      s.after = false;
    }
    ++c.k;
    force = false;
  }
  return s;
}

// Out of line on purpose: inlined right after clear(), GCC 12 reports a false -Warray-bounds in
// SpanList::grow().
[[gnu::noinline]] void append(SpanList& out, const LocalHit& in, const LocalHit& exit) {
  out.add(in, exit);
}

// Two convex pieces of positive length (the common case), exactly as the merge below would
// combine them: ties go to x, subtracted ends are flipped.
void combine_single(CsgOp op, const Span& x, const Span& y, SpanList& out) {
  out.clear();
  switch (op) {
    case CsgOp::kIntersection: {
      const LocalHit& in = y.in.t > x.in.t ? y.in : x.in;
      const LocalHit& exit = y.out.t < x.out.t ? y.out : x.out;
      if (in.t < exit.t) append(out, in, exit);
      return;
    }
    case CsgOp::kUnion:
      if (y.in.t > x.out.t) {
        append(out, x.in, x.out);
        out.push_back(y);
      } else if (x.in.t > y.out.t) {
        append(out, y.in, y.out);
        out.push_back(x);
      } else {  // overlapping or touching: one piece
        append(out, y.in.t < x.in.t ? y.in : x.in, y.out.t > x.out.t ? y.out : x.out);
      }
      return;
    case CsgOp::kDifference: {
      LocalHit y_in = y.in, y_out = y.out;
      y_in.flip = !y_in.flip;
      y_out.flip = !y_out.flip;
      if (y.out.t <= x.in.t || y.in.t >= x.out.t) {
        append(out, x.in, x.out);  // apart or touching: x whole
      } else if (y.in.t <= x.in.t) {
        if (y.out.t < x.out.t) append(out, y_out, x.out);  // else x is covered: nothing
      } else {
        append(out, x.in, y_in);
        if (y.out.t < x.out.t) out.add(y_out, x.out);
      }
      return;
    }
  }
}

}  // namespace

void combine_spans(CsgOp op, const SpanList& a, const SpanList& b, SpanList& out) {
  if (a.size() == 1 && b.size() == 1 && a[0].in.t < a[0].out.t && b[0].in.t < b[0].out.t) {
    combine_single(op, a[0], b[0], out);
    return;
  }
  out.clear();
  Cursor ca{a}, cb{b};
  bool in_a = false, in_b = false, in_r = false;
  LocalHit entry;
  while (!ca.done() || !cb.done()) {
    const bool take_a = cb.done() || (!ca.done() && !(cb.end().t < ca.end().t));
    const double t = take_a ? ca.end().t : cb.end().t;
    const Step sa = advance(ca, t, in_a, take_a);
    const Step sb = advance(cb, t, in_b, !take_a);
    const bool r = csg_inside(op, sa.after, sb.after);
    if (r != in_r) {
      // The responsible operand: one whose change alone turns the result; else any that changed.
      bool from_a;
      if (sa.changed() && csg_inside(op, sa.after, sb.before) == r)
        from_a = true;
      else if (sb.changed() && csg_inside(op, sa.before, sb.after) == r)
        from_a = false;
      else
        from_a = sa.changed();
      LocalHit h = from_a ? *sa.crossing() : *sb.crossing();
      if (!from_a && op == CsgOp::kDifference) h.flip = !h.flip;
      if (r)
        entry = h;
      else
        out.add(entry, h);
      in_r = r;
    }
    in_a = sa.after;
    in_b = sb.after;
  }
}

void complement_spans(SpanList& spans) {
  const LocalHit lo{.t = -kInfinity, .part = kNoSurface}, hi{.t = kInfinity, .part = kNoSurface};
  SpanList gaps;
  LocalHit from = lo;
  for (const Span& s : spans) {
    if (from.t < s.in.t) gaps.add(from, s.in);
    from = s.out;
  }
  if (from.t < kInfinity) gaps.add(from, hi);
  spans.clear();
  for (const Span& s : gaps) spans.push_back(s);
}

}  // namespace raycast

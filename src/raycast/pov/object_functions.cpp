// POV-Ray's functions of objects (trace, inside, min_extent, max_extent): arguments checked
// here, answers from Options::object_queries, which builds the object as the scene would.
#include "pov/interpreter.h"

namespace raycast::pov {

namespace {

Value vector_value(const Vec3& p) { return Value::vector({p.x, p.y, p.z}); }

}  // namespace

Value Interpreter::object_query(const Token& t, const std::vector<Value>& a,
                                const std::vector<Pos>& at,
                                const std::optional<Token>& normal_name) {
  const std::string& w = t.text;
  const std::size_t want = w == "trace" ? 3 : w == "inside" ? 2 : 1;
  if (a.size() != want && !(w == "trace" && a.size() == 4))
    fail_at(t.pos, w + " takes " + std::to_string(want) + " argument(s)" +
                       (w == "trace" ? " or 4" : "") + ", got " + std::to_string(a.size()));
  if (a[0].kind != Value::Object)
    fail_at(at[0], w + ": expected an object, got " + kind_name(a[0]));
  auto vv = [&](std::size_t i) { return vector_argument(w, a[i], at[i]); };
  // An object raycast does not build (a shape it warned about) is asked as if absent.
  ObjectQueries* q = a[0].object ? options_.object_queries.get() : nullptr;
  const std::string what =
      "the " + w + " function" + (a[0].object ? "" : " of an object raycast does not build");
  if (w == "inside") {
    const Vec3 p = vv(1);
    if (!q) unsupported_warning(t.pos, what, "its answer is 0");
    return Value::number(q && q->inside(scene_, a[0].object, p) ? 1 : 0);
  }
  if (w == "trace") {
    const Vec3 origin = vv(1), direction = vv(2);
    if (!q) unsupported_warning(t.pos, what, "its answer is <0, 0, 0>");
    const auto hit = q ? q->trace(scene_, a[0].object, origin, direction) : std::nullopt;
    if (normal_name)
      assign(normal_name->text, vector_value(hit ? hit->normal : Vec3{0, 0, 0}), false,
             normal_name->pos);
    return vector_value(hit ? hit->point : Vec3{0, 0, 0});
  }
  if (!q) {
    unsupported_warning(t.pos, what, "its answer is <0, 0, 0>");
    return vector_value({0, 0, 0});
  }
  const auto [lo, hi] = q->extent(scene_, a[0].object);
  return vector_value(w == "min_extent" ? lo : hi);
}

}  // namespace raycast::pov

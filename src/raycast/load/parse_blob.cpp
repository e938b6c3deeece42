// The blob's parser: a threshold and a list of sphere and cylinder components.
#include <stdexcept>
#include <string>
#include <vector>

#include "load/shape_parsers.h"

namespace raycast {

namespace {

// One component: `center` (a sphere) or `from` and `to` (a cylinder), `radius`, `strength` (1),
// `transform` (placing the component's field in the blob).
BlobComponent read_component(const SourceContext& ctx, const YamlNode& node,
                             const std::string& what) {
  if (!node.IsMap())
    fail_at(ctx, node, what + " must be a mapping with center or from/to, radius, strength");
  Fields c(ctx, node, what);
  BlobComponent b;
  if (c.has("from") || c.has("to")) {
    if (c.has("center")) c.fail("center", what + " has center and from/to: give one");
    b.cylinder = true;
    b.a = c.vec3("from");
    b.b = c.vec3("to");
  } else {
    b.a = c.vec3("center");
  }
  b.radius = c.positive("radius");
  b.strength = c.number("strength", 1);
  if (const YamlNode t = c.optional("transform")) b.xf = read_transform(ctx, t);
  c.finish();
  return b;
}

}  // namespace

ShapeVariant parse_shape(std::type_identity<Blob>, Fields& f) {
  const double threshold = f.positive("threshold", 1);
  const YamlNode list = f.required("components");
  if (!list.IsSequence() || list.size() == 0)
    fail_at(f.ctx(), list,
            f.name("components") + " must be a non-empty list, got " + describe(list));
  if (list.size() > kMaxBlobComponents)
    fail_at(
        f.ctx(), list,
        f.name("components") + " has more than " + std::to_string(kMaxBlobComponents) + " entries");
  std::vector<BlobComponent> components;
  components.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i)
    components.push_back(
        read_component(f.ctx(), list[i], f.name("components") + "[" + std::to_string(i) + "]"));
  try {
    return make_blob(threshold, std::move(components));
  } catch (const std::invalid_argument& e) {
    fail_at(f.ctx(), list, f.name("components") + ": " + e.what());
  }
}

}  // namespace raycast

#include "load/loader.h"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <vector>

#include "geometry/shape_error.h"
#include "io/huge_pages.h"
#include "io/scene_file.h"
#include "load/formula_noise_registration.h"
#include "load/pov_loader.h"
#include "load/read_materials.h"
#include "load/read_settings.h"
#include "load/shape_parsers.h"
#include "load/yaml_prescan.h"
#include "load/yaml_reader.h"
#include "objects/csg_tree.h"
#include "objects/prototype.h"

namespace raycast {

namespace {

constexpr const char* kObjectKeys = "name, material, transform, shadows, image, reflections";
// A `use` inside a library entry or a CSG operation is copied in place; a scene whose copies make
// more shapes than this (summed over all copies) is refused rather than exhausting memory.
constexpr std::size_t kMaxExpandedObjects = std::size_t{1} << 16;
constexpr const char* kCompoundKeys = "group, union, intersection, difference, use";

class Loader {
 public:
  Loader(SourceContext ctx, Scene& scene) : ctx_(std::move(ctx)), scene_(scene) {
    ctx_.files = &scene_.marks.files;
  }

  void load(const YamlNode& root) {
    if (root.IsNull())
      throw SceneError(ctx_.file, 0, 0, "the scene is empty (expected a mapping with `objects`)");
    Fields top(ctx_, root, "scene");
    scene_.materials.emplace_back();
    scene_.materials.back().name = "default";
    if (top.has("camera")) {
      scene_.camera = read_camera(ctx_, top.required("camera"));
      scene_.marks.camera = mark_of(top.required("camera"));
    }
    if (top.has("image")) scene_.image = read_image(ctx_, top.required("image"));
    if (top.has("render")) scene_.render = read_render(ctx_, top.required("render"));
    if (top.has("materials")) read_materials(top.required("materials"));
    if (top.has("lights")) read_lights(top.required("lights"));
    if (top.has("library")) read_library(top.required("library"));
    const YamlNode objects = top.required("objects");
    top.finish();
    if (!objects.IsSequence())
      fail_at(ctx_, objects, "objects must be a list, got " + describe(objects));
    // One object per entry in most scenes: the vector grows once, not by copies of its objects
    // (up to a bound, so that a long list of anything but objects reserves no gigabytes).
    constexpr std::size_t kMaxReserved = std::size_t{1} << 20;
    scene_.objects.reserve(scene_.objects.size() + std::min(objects.size(), kMaxReserved));
    advise_huge_pages(scene_.objects.data(), scene_.objects.capacity() * sizeof(Object));
    scene_.marks.entries.reserve(std::min(objects.size(), kMaxReserved));
    for (const YamlNode& entry : objects) {
      scene_.marks.entries.push_back(mark_of(entry));
      read_object(entry, 0, scene_.entries, Placement{}, scene_.objects);
      if (entry.IsMap() && entry["name"]) {
        scene_.marks.entry_names.resize(std::size_t(scene_.entries) + 1);
        scene_.marks.entry_names.back() = std::string(entry["name"].Scalar());
      }
      ++scene_.entries;
    }
  }

 private:
  static SourceMark mark_of(const YamlNode& node) {
    return {node.Mark().line + 1, node.Mark().column + 1};
  }

  void read_materials(const YamlNode& node) {
    if (!node.IsMap()) fail_at(ctx_, node, "materials must be a mapping of names to materials");
    for (const YamlPair& kv : pairs_of(node)) {
      const std::string name = key_text(ctx_, kv.key());
      if (named_materials_.count(name))
        fail_at(ctx_, kv.key(), "material '" + name + "' is defined twice");
      named_materials_[name] = static_cast<int>(scene_.materials.size());
      scene_.materials.push_back(read_material(ctx_, kv.value(), name));
    }
  }

  void read_lights(const YamlNode& node) {
    if (!node.IsSequence()) fail_at(ctx_, node, "lights must be a list");
    for (const YamlNode& l : node) {
      scene_.lights.push_back(read_light(ctx_, l));
      scene_.marks.lights.push_back(mark_of(l));
    }
  }

  int read_material_ref(const YamlNode& node) {
    if (node.IsScalar()) {
      const auto it = named_materials_.find(node.Scalar());
      if (it == named_materials_.end())
        fail_at(ctx_, node, "unknown material '" + std::string(node.Scalar()) + "'");
      return it->second;
    }
    scene_.materials.push_back(read_material(ctx_, node, ""));
    return static_cast<int>(scene_.materials.size() - 1);
  }

  // Where an object sits and what it inherits: the transform composed from its ancestors (to the
  // space of what it goes into) and the material it gets when it names none (-1: its container's).
  struct Placement {
    std::optional<Transform> xf;
    int material = 0;
  };

  Placement place(const YamlNode& node, const Placement& parent) {
    Placement p;
    p.material = node["material"] ? read_material_ref(node["material"]) : parent.material;
    p.xf = parent.xf;
    if (node["transform"]) {
      const Transform own = read_transform(ctx_, node["transform"]);
      if (!own.is_identity()) p.xf = parent.xf ? *parent.xf * own : own;
    }
    if (node["name"] && !node["name"].IsScalar()) fail_at(ctx_, node["name"], "name must be text");
    return p;
  }

  static bool is_csg_key(const std::string& key) {
    return key == "union" || key == "intersection" || key == "difference";
  }
  static bool is_compound_key(const std::string& key) {
    return is_csg_key(key) || key == "group" || key == "use";
  }

  // The one shape or compound key of an object mapping, and its node (for positions).
  std::pair<std::string, YamlNode> object_key(const YamlNode& node, int depth) {
    if (depth > kMaxNesting)
      fail_at(ctx_, node, "objects are nested deeper than " + std::to_string(kMaxNesting));
    if (!node.IsMap())
      fail_at(ctx_, node, "an object must be a mapping with one shape key, got " + describe(node));
    std::string shape_key;
    YamlNode key_node;
    for (const YamlPair& kv : pairs_of(node)) {
      const std::string key(kv.key().Scalar());
      if (key == "name" || key == "material" || key == "transform" || key == "shadows" ||
          key == "image" || key == "reflections")
        continue;
      if (!shape_parsers().count(key) && !is_compound_key(key))
        fail_at(ctx_, kv.key(),
                "unknown key '" + describe(kv.key()) + "' in object (expected a shape, " +
                    kCompoundKeys + " or " + kObjectKeys + ")");
      if (!shape_key.empty())
        fail_at(ctx_, kv.key(),
                "an object has exactly one shape key; found " + shape_key + " and " + key);
      shape_key = key;
      key_node = kv.key();
    }
    if (shape_key.empty()) fail_at(ctx_, node, "object has no shape key");
    return {shape_key, key_node};
  }

  // One primitive shape, placed.
  Object read_shape(const YamlNode& node, const std::string& key, const Placement& here,
                    int entry) {
    // Library entries using each other twice at every level would grow exponentially: bound it.
    if (copying_ > 0 && ++expanded_ > kMaxExpandedObjects)
      fail_at(ctx_, node,
              "library expansion makes more than " + std::to_string(kMaxExpandedObjects) +
                  " objects (entries using each other repeatedly?)");
    Object obj;
    obj.entry = entry;
    obj.material = here.material;
    obj.xf = here.xf;
    Fields f(ctx_, node[key], key);
    try {
      obj.shape = shape_parsers().at(key)(f);
    } catch (const ShapeParameterError& e) {
      // At the parameter when the mapping spells it, else at the shape.
      if (f.has(e.parameter()))
        f.fail(e.parameter(), f.name(e.parameter()) + " " + e.requirement());
      fail_at(ctx_, node[key], f.name(e.parameter()) + " " + e.requirement());
    } catch (const std::invalid_argument& e) {
      fail_at(ctx_, node[key], key + ": " + e.what());
    }
    f.finish();
    return obj;
  }

  // While alive, `name` is on the stack of library entries being read (cycle detection) and, when
  // `copying`, objects are counted against kMaxExpandedObjects; undone on every exit, throws too.
  class Expansion {
   public:
    Expansion(Loader& loader, const std::string& name, bool copying)
        : loader_(loader), counts_(copying) {
      loader_.expanding_.push_back(name);
      if (counts_) ++loader_.copying_;
    }
    ~Expansion() {
      if (counts_) --loader_.copying_;
      loader_.expanding_.pop_back();
    }
    Expansion(const Expansion&) = delete;
    Expansion& operator=(const Expansion&) = delete;

   private:
    Loader& loader_;
    bool counts_;
  };

  const YamlNode& library_entry(const YamlNode& use) {
    if (!use.IsScalar()) fail_at(ctx_, use, "use must name a library entry, got " + describe(use));
    const auto it = library_.find(use.Scalar());
    const std::string name(use.Scalar());
    if (it == library_.end()) fail_at(ctx_, use, "unknown library entry '" + name + "'");
    const auto cycle = std::find(expanding_.begin(), expanding_.end(), name);
    if (cycle != expanding_.end()) {
      std::string path;
      for (auto k = cycle; k != expanding_.end(); ++k) path += *k + " -> ";
      fail_at(ctx_, use, "library entry '" + name + "' uses itself (" + path + name + ")");
    }
    return it->second;
  }

  // Reads one entry of `objects` (or a child of a group, or a library entry) and appends what it
  // makes to `out`: groups are flattened, each child keeping `entry`. `shadows: false` makes every
  // object it gives cast no shadow.
  void read_object(const YamlNode& node, int depth, int entry, const Placement& parent,
                   std::vector<Object>& out) {
    const std::size_t first = out.size();
    read_object_parts(node, depth, entry, parent, out);
    const bool shadows = flag(node, "shadows"), image = flag(node, "image"),
               reflections = flag(node, "reflections");
    for (std::size_t i = first; i < out.size(); ++i) {
      out[i].casts_shadow = out[i].casts_shadow && shadows;
      out[i].seen_by_camera = out[i].seen_by_camera && image;
      out[i].seen_in_reflections = out[i].seen_in_reflections && reflections;
    }
  }

  // An object's `shadows`, `image` or `reflections`: true (also when absent) or false.
  bool flag(const YamlNode& node, const char* key) const {
    const YamlNode s = node[key];
    if (!s) return true;
    const std::string v(s.IsScalar() ? s.Scalar() : std::string_view());
    if (v == "true" || v == "false") return v == "true";
    fail_at(ctx_, s, std::string(key) + " must be true or false, got " + describe(s));
  }

  void read_object_parts(const YamlNode& node, int depth, int entry, const Placement& parent,
                         std::vector<Object>& out) {
    const auto [key, key_node] = object_key(node, depth);
    const Placement here = place(node, parent);
    const YamlNode body = node[key];
    if (key == "group") {
      if (!body.IsSequence())
        fail_at(ctx_, body, "group must be a list of objects, got " + describe(body));
      for (const YamlNode& child : body) read_object(child, depth + 1, entry, here, out);
    } else if (is_csg_key(key)) {
      CsgTree tree;
      read_csg_operation(body, key, depth, tree, Placement{std::nullopt, -1});
      Object obj;
      obj.shape = CsgShape{finish_csg_tree(std::move(tree))};
      obj.xf = here.xf;
      obj.material = here.material;
      obj.entry = entry;
      out.push_back(std::move(obj));
    } else if (key == "use") {
      const YamlNode& def = library_entry(body);
      if (!expanding_.empty()) {
        // Inside a library entry: expanded in place, so that prototypes never hold instances.
        const Expansion guard(*this, std::string(body.Scalar()), true);
        read_object(def, depth + 1, entry, here, out);
        return;
      }
      Object obj;
      obj.shape = InstanceShape{prototypes_.find(body.Scalar())->second};
      obj.xf = here.xf;
      obj.material = here.material;
      obj.entry = entry;
      out.push_back(std::move(obj));
    } else {
      out.push_back(read_shape(node, key, here, entry));
    }
  }

  // Adds the operation `key` over the list `body` to the tree and returns its node code.
  std::int32_t read_csg_operation(const YamlNode& body, const std::string& key, int depth,
                                  CsgTree& tree, const Placement& here) {
    if (!body.IsSequence() || body.size() == 0)
      fail_at(ctx_, body, key + " must be a non-empty list of solids, got " + describe(body));
    const std::size_t index = tree.nodes.size();
    tree.nodes.emplace_back();
    tree.nodes[index].op = key == "intersection" ? CsgOp::kIntersection
                           : key == "difference" ? CsgOp::kDifference
                                                 : CsgOp::kUnion;  // union, or a group inside CSG
    for (const YamlNode& child : body) {
      const std::int32_t code = read_csg_operand(child, depth + 1, tree, here);
      tree.nodes[index].operands.push_back(code);
    }
    return static_cast<std::int32_t>(index);
  }

  // One operand of a CSG operation: a closed solid, a nested operation, a group (its union) or a
  // `use` (expanded in place). Transforms are relative to the CSG object.
  std::int32_t read_csg_operand(const YamlNode& node, int depth, CsgTree& tree,
                                const Placement& parent) {
    const auto [key, key_node] = object_key(node, depth);
    for (const char* whole : {"shadows", "image", "reflections"})
      if (node[whole])
        fail_at(ctx_, node[whole],
                std::string(whole) + " applies to whole objects, not to CSG operands");
    const Placement here = place(node, parent);
    if (is_csg_key(key) || key == "group")
      return read_csg_operation(node[key], key, depth, tree, here);
    if (key == "use") {
      const YamlNode& def = library_entry(node[key]);
      const Expansion guard(*this, std::string(node[key].Scalar()), true);
      return read_csg_operand(def, depth + 1, tree, here);
    }
    Object leaf = read_shape(node, key, here, -1);
    if (!is_closed(leaf))
      fail_at(ctx_, key_node, key + " cannot be a CSG operand: it is an open surface");
    tree.leaves.push_back(std::move(leaf));
    return csg_leaf_code(tree.leaves.size() - 1);
  }

  // The top-level `library:` map: every entry is read (so its errors show even when unused) and
  // built once into a shared prototype.
  void read_library(const YamlNode& node) {
    if (!node.IsMap())
      fail_at(ctx_, node, "library must be a mapping of names to objects, got " + describe(node));
    std::vector<std::string> order;  // file order, so that the first mistake is reported first
    for (const YamlPair& kv : pairs_of(node)) {
      if (!kv.key().IsScalar()) fail_at(ctx_, kv.key(), "a library name must be text");
      const std::string name(kv.key().Scalar());
      if (library_.count(name))
        fail_at(ctx_, kv.key(), "library entry '" + name + "' is defined twice");
      library_[name] = kv.value();
      order.push_back(name);
    }
    for (const std::string& name : order) {
      const YamlNode def = library_.at(name);
      std::vector<Object> objects;
      {
        const Expansion guard(*this, name, false);
        read_object(def, 1, -1, Placement{std::nullopt, -1}, objects);
      }
      prototypes_[name] = make_prototype(std::move(objects));
    }
  }

  SourceContext ctx_;
  Scene& scene_;
  std::map<std::string, int, std::less<>> named_materials_;
  std::map<std::string, YamlNode, std::less<>> library_;
  std::map<std::string, std::shared_ptr<const Prototype>, std::less<>> prototypes_;
  std::vector<std::string> expanding_;  // library entries being read, innermost last
  int copying_ = 0;                     // > 0 while a `use` is being copied in place
  std::size_t expanded_ = 0;            // shapes read while copying
};

// load_scene_text with the text handed over: the parsed document keeps it (its scalars are views
// of it), without a copy of a large file.
Scene load_owned_text(std::string text, const std::string& name, const std::string& dir,
                      int frame) {
  register_formula_noise();  // the formulas' noise1, noise2, noise3
  Scene scene;
  scene.source = name;
  SourceContext ctx{name, dir, frame};
  {
    // The nodes are freed before the acceleration structure is built: they are the larger.
    const YamlDocument doc = parse_yaml(std::move(text), name, kMaxNesting);
    Loader(ctx, scene).load(doc.root());
  }
  scene.build();
  return scene;
}

}  // namespace

Scene load_scene_text(const std::string& text, const std::string& name, const std::string& dir,
                      int frame) {
  return load_owned_text(text, name, dir, frame);
}

Scene load_scene_file(const std::string& path, int frame) {
  if (path == "-") {  // the CLI's convention for standard input (docs/cli.md)
    std::stringstream ss;
    ss << std::cin.rdbuf();
    if (std::cin.bad()) throw SceneError("<stdin>", 0, 0, "cannot read the scene");
    return load_owned_text(std::move(ss).str(), "<stdin>", ".", frame);
  }
  if (is_pov_path(path))
    return load_pov_scene_file(path, frame, default_pov_options());  // docs/pov-import.md
  SceneFileText file = read_scene_file(path);
  return load_owned_text(std::move(file.text), path, file.dir, frame);
}

}  // namespace raycast

#include <algorithm>
#include <cmath>
#include <functional>

#include "pov/interpreter.h"

namespace raycast::pov {

const char* kind_name(const Value& v) {
  switch (v.kind) {
    case Value::Float:
      return "a float";
    case Value::Vector:
      return v.colour ? "a colour" : "a vector";
    case Value::String:
      return "a string";
    case Value::Array:
      return "an array";
    case Value::Object:
      return "an object";
    case Value::Texture:
      return "a texture";
    case Value::Pigment:
      return "a pigment";
    case Value::Finish:
      return "a finish";
    case Value::Normal:
      return "a normal";
    case Value::Interior:
      return "an interior";
    case Value::Material:
      return "a material";
    case Value::Camera:
      return "a camera";
    case Value::Light:
      return "a light";
    case Value::Transform:
      return "a transform";
    case Value::Function:
      return "a function";
    case Value::Spline:
      return "a spline";
    case Value::Macro:
      return "a macro";
    case Value::ColourMap:
      return "a colour map";
    case Value::SkySphere:
      return "a sky_sphere";
    case Value::Fog:
      return "a fog";
    case Value::Opaque:
      return "a block";
  }
  return "a value";
}

Symbol* Interpreter::find_symbol(const std::string& name) {
  for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s) {
    const auto it = s->find(name);
    if (it == s->end()) continue;
    Symbol* sym = &it->second;
    for (int hops = 0; sym->ref && hops < 1000; ++hops) sym = sym->ref;
    return sym;
  }
  return nullptr;
}

const Value* Interpreter::lookup(const std::string& name) {
  const Symbol* s = find_symbol(name);
  return s ? &s->value : nullptr;
}

void Interpreter::assign(const std::string& name, Value v, bool local, const Pos& at,
                         std::size_t local_scope) {
  if (v.kind == Value::String && v.text.size() > options_.limits.string_bytes)
    fail_at(at, "a string longer than " + std::to_string(options_.limits.string_bytes) + " bytes");
  Symbol* target = nullptr;
  if (local) {
    auto& scope = scopes_[std::min(local_scope, scopes_.size() - 1)];
    const auto it = scope.find(name);
    if (it != scope.end()) {
      target = &it->second;
      while (target->ref) target = target->ref;
    } else {
      target = &scope[name];
    }
  } else {
    // #declare changes the innermost existing identifier of that name (a macro's local too),
    // else creates a global one (POV-Ray's rule).
    target = find_symbol(name);
    if (!target) target = &scopes_.front()[name];
  }
  target->value = std::move(v);
}

void Interpreter::declare(const Token& d, bool local) {
  if (is_word("deprecated")) {  // #declare deprecated [once] "message" Name = ...
    next();
    if (is_word("once")) next();
    string_value("the deprecation message");
  }
  // The name is read raw: a macro's name may be declared over.
  const Token nt = raw_name();
  if (nt.kind != Token::Word)
    fail_at(nt.pos, std::string("expected a name after #") + (local ? "local" : "declare") +
                        ", got " + describe(nt));
  const std::string name = nt.text;
  const Pos at = nt.pos;
  if (is_symbol("[")) {  // an array element
    Symbol* s = find_symbol(name);
    if (!s || s->value.kind != Value::Array) fail_at(at, "'" + name + "' is not an array");
    ArrayValue& a = *s->value.array;
    std::size_t index = 0;
    for (std::size_t k = 0; k < a.sizes.size(); ++k) {
      expect_symbol("[", "for the array's next index");
      const Pos ip = tok().pos;
      const double i = number("an array index");
      expect_symbol("]", "after the index");
      if (!(i >= 0 && i < a.sizes[k]))
        fail_at(ip, "index " + std::to_string(static_cast<long long>(std::floor(i))) +
                        " out of range [0, " + std::to_string(a.sizes[k] - 1) + "] of " + name);
      index = index * static_cast<std::size_t>(a.sizes[k]) + static_cast<std::size_t>(i);
    }
    expect_symbol("=", ("after " + name + "[...]").c_str());
    const std::shared_ptr<ArrayValue> keep = s->value.array;
    Value v = rvalue();
    keep->elements[index] = std::move(v);
  } else {
    expect_symbol("=", ("after #declare " + name).c_str());
    // #local names the scope where the directive starts: a macro whose body is the value may
    // end after it (`Add(1, 2);`) or its body may hold the `;` (`#if (C) Q; #else ... #end`).
    const std::size_t scope = scopes_.size() - 1;
    Value v = rvalue();
    // The token after the value first: a macro whose body is the value ends there.
    const bool semicolon = pov::is_symbol(peek_operator(), ";");
    assign(name, std::move(v), local, at, scope);
    if (semicolon) next();
    return;
  }
  (void)d;
  if (pov::is_symbol(peek_operator(), ";")) next();
}

void Interpreter::undef() {
  const Token nt = raw_name();
  if (nt.kind != Token::Word) fail_at(nt.pos, "expected a name after #undef, got " + describe(nt));
  const std::string name = nt.text;
  for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s)
    if (s->erase(name)) return;
}

void Interpreter::default_block() {
  expect_symbol("{", "after #default");
  while (!accept_symbol("}")) {
    if (is_word("texture")) {
      next();
      default_texture_ = texture_block(default_texture_, 0);
    } else if (is_word("pigment")) {
      next();
      default_texture_.pigment = pigment_block(default_texture_.pigment);
    } else if (is_word("finish")) {
      next();
      default_texture_.finish = finish_block(default_texture_.finish);
    } else if (is_word("normal")) {
      next();
      default_texture_.normal = normal_block(default_texture_.normal);
    } else {
      unexpected("texture, pigment, finish or normal in #default");
    }
  }
  default_texture_.name.clear();
}

void Interpreter::apply_declares() {
  for (const auto& [name, text] : options_.declares) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end && *end == '\0' && !text.empty())
      scopes_.front()[name].value = Value::number(v);
    else
      scopes_.front()[name].value = Value::string(text);
  }
}

namespace {
bool is_skipped_block(std::string_view w) {
  static constexpr std::string_view kinds[] = {
      "pigment_map",  "normal_map",       "texture_map", "slope_map",     "density_map",
      "material_map", "density",          "media",       "rainbow",       "photons",
      "radiosity",    "interior_texture", "bump_map",    "image_pattern", "image_map"};
  for (const std::string_view k : kinds)
    if (k == w) return true;
  return false;
}
}  // namespace

Value Interpreter::rvalue() {
  const Token t = tok();
  Value v;
  if (t.kind != Token::Word) return expression();
  const std::string& w = t.text;
  const std::string_view word = w;  // compared with literals inline
  if (is_object_keyword()) {
    v.kind = Value::Object;
    if (std::optional<Node> n = object(0)) v.object = std::make_shared<const Node>(std::move(*n));
  } else if (word == "light_source") {
    v.kind = Value::Object;
    v.object = std::make_shared<const Node>(light_block());
  } else if (word == "texture") {
    next();
    v.kind = Value::Texture;
    Texture tx = texture_block(default_texture_, 0);
    while (peek_operator().kind == Token::Word && peek_operator().text == "texture" &&
           !pending_) {  // layered: each further texture goes on top
      next();
      tx = layer_on_top(std::move(tx), texture_block(default_texture_, 0));
    }
    v.texture = std::make_shared<const Texture>(std::move(tx));
  } else if (word == "pigment") {
    next();
    v.kind = Value::Pigment;
    v.pigment = std::make_shared<const Pigment>(pigment_block(default_texture_.pigment));
  } else if (word == "normal") {
    next();
    v.kind = Value::Normal;
    v.normal = std::make_shared<const texture::Normal>(normal_block(std::nullopt));
  } else if (word == "finish") {
    next();
    v.kind = Value::Finish;
    v.finish = std::make_shared<const Finish>(finish_block(default_texture_.finish));
  } else if (word == "interior") {
    next();
    v.kind = Value::Interior;
    v.interior = interior_block();
  } else if (word == "material") {
    next();
    v.kind = Value::Material;
    v.texture = std::make_shared<const Texture>(material_block(default_texture_, 0));
  } else if (word == "camera") {
    next();
    v.kind = Value::Camera;
    v.camera = std::make_shared<const Camera>(camera_block(Camera{}));
  } else if (word == "transform") {
    next();
    v.kind = Value::Transform;
    v.transform = std::make_shared<const std::vector<XformOp>>(transform_block());
  } else if (word == "function") {
    next();
    v = function_block(t.pos);
  } else if (word == "spline") {
    next();
    v = spline_block(t.pos);
  } else if (word == "color_map" || word == "colour_map") {
    next();
    v.kind = Value::ColourMap;
    v.colour_map = std::make_shared<const std::vector<MapEntry>>(colour_map_block());
  } else if (word == "sky_sphere") {
    next();
    v.kind = Value::SkySphere;
    v.sky_sphere = std::make_shared<const SkySphere>(sky_sphere_block());
  } else if (word == "fog") {
    next();
    v.kind = Value::Fog;
    v.fog = std::make_shared<const Fog>(fog_block());
  } else if (is_skipped_block(w)) {
    next();
    skip_block(w);
    v.kind = Value::Opaque;
    v.text = w;
  } else if (word == "array") {
    next();
    v.kind = Value::Array;
    v.array = std::make_shared<ArrayValue>();
    std::size_t total = 1;
    while (pov::is_symbol(peek_operator(), "[") && !pending_) {
      next();
      const Pos at = tok().pos;
      const double n = number("an array size");
      expect_symbol("]", "after the array's size");
      if (!(n >= 1) || n != std::floor(n) || v.array->sizes.size() >= 5)
        fail_at(at, "an array has 1 to 5 dimensions, each of a whole size >= 1");
      // Compared as a double before the conversion, which is undefined for sizes past size_t.
      if (n > static_cast<double>(options_.limits.array_elements) / static_cast<double>(total))
        fail_at(at, "an array of more than " + std::to_string(options_.limits.array_elements) +
                        " elements (raise the bound with --pov-max-array N)");
      total *= static_cast<std::size_t>(n);
      if (total > options_.limits.array_elements)
        fail_at(at, "an array of more than " + std::to_string(options_.limits.array_elements) +
                        " elements (raise the bound with --pov-max-array N)");
      v.array->sizes.push_back(static_cast<int>(n));
    }
    if (v.array->sizes.empty()) unexpected("'[' and the array's size");
    v.array->elements.resize(total);
    if (pov::is_symbol(peek_operator(), "{") && !pending_) {
      // Initialisers: nested braces per dimension, elements in row-major order.
      std::size_t at = 0;
      std::function<void(std::size_t)> fill = [&](std::size_t dim) {
        expect_symbol("{", "to open the array's initialiser");
        for (int i = 0; i < v.array->sizes[dim]; ++i) {
          if (i) accept_symbol(",");  // commas between elements may be left out
          if (dim + 1 < v.array->sizes.size())
            fill(dim + 1);
          else
            v.array->elements[at++] = rvalue();
        }
        accept_symbol(",");
        expect_symbol("}", "to close the array's initialiser (more elements than its size?)");
      };
      fill(0);
    }
  } else {
    return expression();
  }
  return v;
}

}  // namespace raycast::pov

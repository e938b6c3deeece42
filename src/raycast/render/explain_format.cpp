#include "render/explain_format.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace raycast {

namespace {

// Appended piece by piece: GCC 12's -Wrestrict misfires on `"[" + std::string + ...`.
std::string vec_json(const Vec3& v) {
  std::string text = "[";
  text += json_double(v.x);
  text += ", ";
  text += json_double(v.y);
  text += ", ";
  text += json_double(v.z);
  text += "]";
  return text;
}

/// A JSON string: quotes, backslashes and control characters escaped (names are the scene's).
std::string json_string(const std::string& s) {
  std::string text = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      text += '\\';
      text += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", static_cast<unsigned>(c));
      text += code;
    } else {
      text += c;
    }
  }
  text += '"';
  return text;
}

/// Short numbers for people: 4 significant digits.
std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

std::string vec_text(const Vec3& v) {
  std::string text = "(";
  text += num(v.x);
  text += ", ";
  text += num(v.y);
  text += ", ";
  text += num(v.z);
  text += ")";
  return text;
}

/// "sphere #2 'mirror' (line 14)": the shape, the top-level entry, its name and where the scene
/// wrote it.
std::string object_text(const Scene& scene, std::int32_t index) {
  const Object& o = scene.objects[std::size_t(index)];
  std::string text = std::string(shape_name(o)) + " #" + std::to_string(o.entry);
  if (const std::string& name = scene.marks.entry_name(o.entry); !name.empty())
    text += " '" + name + "'";
  if (o.entry >= 0 && std::size_t(o.entry) < scene.marks.entries.size() &&
      scene.marks.entries[std::size_t(o.entry)].line > 0)
    text += " (line " + std::to_string(scene.marks.entries[std::size_t(o.entry)].line) + ")";
  return text;
}

/// The material's name, or its index for one without a name.
std::string material_text(const Scene& scene, std::size_t index) {
  const std::string& name = scene.materials[index].name;
  return name.empty() ? (index == 0 ? std::string("default") : std::to_string(index)) : name;
}

const char* light_type_name(LightType type) {
  switch (type) {
    case LightType::kPoint:
      return "point";
    case LightType::kDirectional:
      return "directional";
    case LightType::kSpot:
      return "spot";
    case LightType::kSphere:
      return "sphere";
    case LightType::kCylinder:
      return "cylinder";
    case LightType::kArea:
      return "area";
  }
  return "point";
}

class TextWriter {
 public:
  explicit TextWriter(const Scene& scene) : scene_(scene) {}
  std::string out;

  void line(int indent, const std::string& text) {
    out.append(std::size_t(2 * indent), ' ');
    out += text;
    out += '\n';
  }

  void ray(const ExplainedRay& r, int indent) {
    std::string head =
        std::string(ray_kind_name(r.kind)) + " ray, depth " + std::to_string(r.depth);
    if (r.kind != RayKind::kCamera) head += ", weight " + num(r.weight);
    if (r.tint != Color{1, 1, 1}) head += ", tint " + vec_text(r.tint);
    line(indent, head + ": o " + vec_text(r.ray.o) + " d " + vec_text(r.ray.d) + " t in [" +
                     num(r.ray.tmin) + ", " + num(r.ray.tmax) + "]");
    if (!r.hit) {
      line(indent + 1, "miss: background " + vec_text(r.radiance));
      return;
    }
    hit(r, indent + 1);
  }

  void hit(const ExplainedRay& r, int indent) {
    const ExplainedHit& h = *r.hit;
    line(indent, "hit " + object_text(scene_, h.hit.object) + " at t " + num(h.hit.local.t) + ", " +
                     (h.outside ? "entering" : "leaving") + ", material " +
                     material_text(scene_, h.material));
    line(indent + 1, "point " + vec_text(h.si.p) + " normal " + vec_text(h.si.n) +
                         " shading normal " + vec_text(h.si.shading_n) + " uv (" + num(h.si.u) +
                         ", " + num(h.si.v) + ")");
    line(indent + 1, "ambient " + vec_text(h.ambient));
    for (const ExplainedLight& l : h.lights) light(l, indent + 1);
    if (r.stop == RayStop::kMaxDepth)
      line(indent + 1, "stop: max_depth " + std::to_string(scene_.render.max_depth) +
                           " reached, no secondary rays");
    if (r.split) split(r, indent + 1);
    line(indent + 1, "= ambient " + vec_text(h.ambient) + " + diffuse " + vec_text(r.diffuse()) +
                         " + specular " + vec_text(r.specular()) + " + reflection " +
                         vec_text(r.reflection()) + " + refraction " + vec_text(r.refraction()) +
                         " = " + vec_text(r.radiance));
  }

  void light(const ExplainedLight& l, int indent) {
    const LightSample& s = l.sample;
    const Light& light = scene_.lights[s.light];
    std::string head = "light " + std::to_string(s.light) + " (" + light_type_name(light.type) +
                       "): L " + vec_text(s.l) + " N.L " + num(s.n_dot_l);
    if (!(s.n_dot_l > 0)) {
      line(indent, head + ": faces away, no term");
      return;
    }
    line(indent, head + ", diffuse " + vec_text(s.diffuse) + " specular " + vec_text(s.specular));
    if (!s.shadow_ray) {
      line(indent + 1, "no shadow ray: the term is 0");
      return;
    }
    std::string verdict;
    if (max_component(s.visibility) > 0) {
      verdict = "reaches the light";
      if (!l.filters.empty()) {
        verdict += ", filtered by";
        for (std::int32_t f : l.filters) verdict += " " + object_text(scene_, f);
        verdict += ": " + vec_text(s.visibility);
      }
    } else if (l.blocker >= 0) {
      verdict = "blocked by " + object_text(scene_, l.blocker) + " at t " + num(l.blocker_t);
    } else {
      verdict = "blocked";
    }
    line(indent + 1, "shadow ray: o " + vec_text(s.shadow.o) + " d " + vec_text(s.shadow.d) +
                         " t in [0, " + num(s.shadow.tmax) + "]: " + verdict);
  }

  void split(const ExplainedRay& r, int indent) {
    if (!(r.w_reflect > 0) && !(r.w_refract > 0)) return;  // an opaque surface: nothing to split
    std::string text =
        "split: reflection weight " + num(r.w_reflect) + ", refraction weight " + num(r.w_refract);
    if (r.fresnel >= 0) text += " (Fresnel F " + num(r.fresnel) + ")";
    if (r.tir) text += ", total internal reflection";
    line(indent, text);
    const double limit = r.bailout;
    if (r.w_reflect > 0 && r.w_reflect < limit)
      line(indent, "reflection not traced: its weight in the pixel is below the bailout");
    if (r.w_refract > 0 && r.w_refract < limit)
      line(indent, "refraction not traced: its weight in the pixel is below the bailout");
    for (const ExplainedRay& child : r.children) ray(child, indent);
  }

 private:
  const Scene& scene_;
};

class JsonWriter {
 public:
  explicit JsonWriter(const Scene& scene) : scene_(scene) {}
  std::string out;

  void ray(const ExplainedRay& r) {
    out += "{\"kind\": \"" + std::string(ray_kind_name(r.kind)) +
           "\", \"origin\": " + vec_json(r.ray.o) + ", \"direction\": " + vec_json(r.ray.d) +
           ", \"tmin\": " + json_double(r.ray.tmin) + ", \"tmax\": " + json_double(r.ray.tmax) +
           ", \"depth\": " + std::to_string(r.depth) + ", \"weight\": " + json_double(r.weight) +
           ", \"tint\": " + vec_json(r.tint) + ", \"radiance\": " + vec_json(r.radiance) +
           ", \"stop\": ";
    out += r.stop == RayStop::kMaxDepth ? "\"max_depth\""
           : r.stop == RayStop::kMiss   ? "\"miss\""
                                        : "null";
    if (!r.hit) {
      out += ", \"background\": " + vec_json(r.radiance) + ", \"hit\": null, \"children\": []}";
      return;
    }
    out += ", \"hit\": ";
    hit(r);
    out += ", \"children\": [";
    bool first = true;
    for (const ExplainedLight& l : r.hit->lights) {
      if (!l.sample.shadow_ray) continue;
      if (!first) out += ", ";
      first = false;
      shadow(l, r.depth);
    }
    for (const ExplainedRay& child : r.children) {
      if (!first) out += ", ";
      first = false;
      ray(child);
    }
    out += "]}";
  }

 private:
  void object(std::int32_t index) {
    const Object& o = scene_.objects[std::size_t(index)];
    out += "\"object\": " + std::to_string(o.entry) +
           ", \"scene_object\": " + std::to_string(index) + ", \"shape\": \"" + shape_name(o) +
           "\"";
    if (const std::string& name = scene_.marks.entry_name(o.entry); !name.empty())
      out += ", \"name\": " + json_string(name);
  }

  void hit(const ExplainedRay& r) {
    const ExplainedHit& h = *r.hit;
    out += "{";
    object(h.hit.object);
    out += ", \"t\": " + json_double(h.hit.local.t) + ", \"point\": " + vec_json(h.si.p) +
           ", \"normal\": " + vec_json(h.si.n) +
           ", \"shading_normal\": " + vec_json(h.si.shading_n) + ", \"uv\": [" +
           json_double(h.si.u) + ", " + json_double(h.si.v) +
           "], \"entering\": " + (h.outside ? "true" : "false") +
           ", \"material\": " + std::to_string(h.material) +
           ", \"shading\": {\"ambient\": " + vec_json(h.ambient) +
           ", \"diffuse\": " + vec_json(r.diffuse()) + ", \"specular\": " + vec_json(r.specular()) +
           ", \"reflection\": " + vec_json(r.reflection()) +
           ", \"refraction\": " + vec_json(r.refraction()) + "}, \"lights\": [";
    for (std::size_t k = 0; k < h.lights.size(); ++k) {
      const LightSample& s = h.lights[k].sample;
      if (k > 0) out += ", ";
      out += "{\"light\": " + std::to_string(s.light) + ", \"l\": " + vec_json(s.l) +
             ", \"n_dot_l\": " + json_double(s.n_dot_l) + ", \"diffuse\": " + vec_json(s.diffuse) +
             ", \"specular\": " + vec_json(s.specular) +
             ", \"shadow_ray\": " + (s.shadow_ray ? "true" : "false") +
             ", \"visibility\": " + vec_json(s.shadow_ray ? s.visibility : Color{}) + "}";
    }
    out += "], \"split\": ";
    if (!r.split) {
      out += "null}";
      return;
    }
    out += "{\"reflection\": " + json_double(r.w_reflect) +
           ", \"refraction\": " + json_double(r.w_refract) +
           ", \"fresnel\": " + (r.fresnel >= 0 ? json_double(r.fresnel) : std::string("null")) +
           ", \"total_internal_reflection\": " + (r.tir ? "true" : "false") + "}}";
  }

  void shadow(const ExplainedLight& l, int depth) {
    const LightSample& s = l.sample;
    out +=
        "{\"kind\": \"shadow\", \"origin\": " + vec_json(s.shadow.o) +
        ", \"direction\": " + vec_json(s.shadow.d) + ", \"tmin\": " + json_double(s.shadow.tmin) +
        ", \"tmax\": " + json_double(s.shadow.tmax) + ", \"depth\": " + std::to_string(depth) +
        ", \"light\": " + std::to_string(s.light) + ", \"visibility\": " + vec_json(s.visibility) +
        ", \"blocked\": " + (max_component(s.visibility) > 0 ? "false" : "true") +
        ", \"filtered_by\": [";
    for (std::size_t k = 0; k < l.filters.size(); ++k)
      out += (k > 0 ? ", " : "") + std::to_string(scene_.objects[std::size_t(l.filters[k])].entry);
    out += "], \"hit\": ";
    if (l.blocker < 0 || max_component(s.visibility) > 0) {
      out += "null, \"children\": []}";
      return;
    }
    out += "{";
    object(l.blocker);
    out += ", \"t\": " + json_double(l.blocker_t) +
           ", \"point\": " + vec_json(s.shadow.at(l.blocker_t)) +
           ", \"normal\": " + vec_json(l.blocker_n) + ", \"shading\": {}}, \"children\": []}";
  }

  const Scene& scene_;
};

}  // namespace

std::string json_double(double value) {
  if (!std::isfinite(value)) return "null";
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

std::string explain_text(const Scene& scene, const Explanation& e) {
  TextWriter w(scene);
  w.line(0, "pixel (" + std::to_string(e.x) + ", " + std::to_string(e.y) + ") of " +
                std::to_string(e.width) + "x" + std::to_string(e.height) + ", sample " +
                std::to_string(e.sample) + " of " + std::to_string(e.spp) + ": color " +
                vec_text(e.color) + ", " + std::to_string(e.rays) + " rays, traced in " +
                num(e.seconds * 1e3) + " ms");
  w.ray(e.root, 1);
  return w.out;
}

std::string explain_json(const Scene& scene, const Explanation& e) {
  JsonWriter w(scene);
  w.out = "{\"pixel\": [" + std::to_string(e.x) + ", " + std::to_string(e.y) +
          "], \"sample\": " + std::to_string(e.sample) + ", \"samples\": " + std::to_string(e.spp) +
          ", \"color\": " + vec_json(e.color) + ", \"rays\": " + std::to_string(e.rays) +
          ", \"seconds\": " + json_double(e.seconds) + ", \"ray\": ";
  w.ray(e.root);
  w.out += "}\n";
  return w.out;
}

}  // namespace raycast

// image_map and image_pattern blocks: the file (found on the library path, as POV-Ray finds
// images) or a function's picture, the projection, once, interpolate, gamma, and the filter and
// transmit of palette entries or of every pixel, read into the texture system's ImageMap.
#include <algorithm>
#include <cmath>

#include "io/image.h"
#include "pov/interpreter.h"

namespace raycast::pov {

namespace {

constexpr int kMaxFunctionImageSide = 4096;

// A channel as stored (sRGB-encoded, or as the scene's `gamma` says) in linear light. Scenes of
// POV-Ray before 3.7 without assumed_gamma take image values as they are (`decode` false).
float decode_channel(float v, bool decode, double gamma) {
  if (!decode) return v;
  if (gamma > 0) return static_cast<float>(std::pow(v, gamma));
  return srgb_to_linear(v);
}

}  // namespace

bool Interpreter::image_map_modifier(ImageMapRead& r) {
  if (is_word("map_type")) {
    const Pos at = tok().pos;
    next();
    const int t = static_cast<int>(number("map_type"));
    if (t < 0 || t > 2) {
      unsupported_warning(at, "map_type " + std::to_string(t), "mapped as map_type 0");
    } else {
      r.image.projection = static_cast<texture::ImageProjection>(t);
    }
  } else if (is_word("bump_size")) {
    next();
    r.bump_size = number("bump_size");
  } else if (is_word("once")) {
    next();
    r.image.once = true;
  } else if (is_word("interpolate")) {
    next();
    r.image.interpolate = number("interpolate") > 0;
  } else if (is_word("gamma")) {
    next();
    if (is_word("srgb")) {
      next();
      r.gamma = 0;
    } else {
      r.gamma = number("gamma");
    }
  } else if (is_word("filter") || is_word("transmit")) {
    const bool filter = is_word("filter");
    next();
    int index = -1;  // all
    if (is_word("all")) {
      next();
    } else {
      index = static_cast<int>(number("a palette index"));
    }
    skip_comma();
    const double amount = number(filter ? "filter" : "transmit");
    (filter ? r.filter : r.transmit).push_back({index, amount});
  } else if (is_word("use_color") || is_word("use_colour") || is_word("use_index") ||
             is_word("use_alpha") || is_word("premultiplied")) {
    const std::string w = tok().text;
    next();
    if (w == "use_index") r.use_index = true;
    if (w == "use_alpha") r.use_alpha = true;
    if (w == "premultiplied" && numeric_ahead()) number("premultiplied");
  } else {
    return false;
  }
  return true;
}

void Interpreter::image_from_file(ImageMapRead& r, const std::string& name, const Pos& at) {
  const std::optional<std::string> path = find_on_library_path(name);
  if (!path) fail_at(at, "cannot open the image '" + name + "' (looked on the library path)");
  PngPixels png;
  try {
    png = load_png_pixels(*path);
  } catch (const ImageError& e) {
    fail_at(at, e.what());
  }
  r.image.width = png.width;
  r.image.height = png.height;
  r.alpha.resize(std::size_t(png.width) * std::size_t(png.height));
  r.image.pixels.resize(r.alpha.size());
  r.index = std::move(png.index);
  r.palette_size = png.palette_size;
  for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
    const float* c = &png.rgba[4 * i];
    r.image.pixels[i] = {c[0], c[1], c[2], 0, 0};  // decoded once the gamma is known
    r.alpha[i] = c[3];
  }
}

void Interpreter::image_from_function(ImageMapRead& r, const Pos& at) {
  // function W, H { ... }: the picture of f(x, y, 0) over the unit square, a grey image.
  const double w = number("the image's width");
  skip_comma();
  const double h = number("the image's height");
  if (!(w >= 1 && h >= 1 && w <= kMaxFunctionImageSide && h <= kMaxFunctionImageSide))
    fail_at(at, "a function image is 1 to 4096 pixels wide and high");
  const Value f = function_block(at);
  r.image.width = static_cast<int>(w);
  r.image.height = static_cast<int>(h);
  r.image.pixels.resize(std::size_t(r.image.width) * std::size_t(r.image.height));
  r.alpha.assign(r.image.pixels.size(), 1.f);
  r.from_function = true;
  std::vector<double> args(std::max<std::size_t>(3, f.function->params.size()), 0.0);
  for (int y = 0; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x) {
      args[0] = (x + 0.5) / r.image.width;
      args[1] = 1 - (y + 0.5) / r.image.height;  // the top row is y = 1
      const double v = evaluate(*f.function, args);
      const auto g = static_cast<float>(std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0);
      r.image.pixels[std::size_t(y) * std::size_t(r.image.width) + std::size_t(x)] = {g, g, g, 0,
                                                                                      0};
    }
}

std::shared_ptr<const texture::ImageMap> Interpreter::image_map_block(const std::string& what,
                                                                      double* bump_size) {
  const Pos at = tok().pos;
  expect_symbol("{", ("after " + what).c_str());
  ImageMapRead r;
  static const char* const kFormats[] = {"png", "gif",  "tga",  "iff", "ppm", "pgm",
                                         "sys", "jpeg", "tiff", "exr", "hdr", "bmp"};
  std::string format;
  for (const char* f : kFormats)
    if (is_word(f)) format = f;
  bool supported = true;
  if (!format.empty()) {
    const Pos fat = tok().pos;
    next();
    const std::string name = string_value("the image's file name");
    if (format == "png") {
      image_from_file(r, name, fat);
    } else {
      unsupported_warning(fat, format + " images", "the image_map is drawn grey");
      supported = false;
    }
  } else if (is_word("function")) {
    next();
    image_from_function(r, at);
  } else if (tok().kind == Token::String || tok().kind == Token::Word) {
    const Pos fat = tok().pos;
    const std::string name = string_value("the image's file name");
    const std::string ext = name.size() >= 4 ? name.substr(name.size() - 4) : "";
    if (ext == ".png" || ext == ".PNG") {
      image_from_file(r, name, fat);
    } else {
      unsupported_warning(fat, "images of this format ('" + name + "')",
                          "the image_map is drawn grey");
      supported = false;
    }
  }
  for (int guard = 0; !accept_symbol("}"); ++guard) {
    if (tok().kind == Token::End || guard > 100000) fail_at(at, what + " { is never closed");
    if (!image_map_modifier(r)) unexpected("an image_map item (map_type, once, interpolate ...)");
  }
  if (bump_size) *bump_size = r.bump_size;
  if (!supported) return nullptr;
  finish_image(r);
  return std::make_shared<const texture::ImageMap>(std::move(r.image));
}

void Interpreter::finish_image(ImageMapRead& r) {
  const bool decode = !r.from_function && (scene_.settings.gamma_given ||
                                           scene_.settings.version >= 3.7 || r.gamma >= 0);
  for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
    texture::ImagePixel& p = r.image.pixels[i];
    p.r = decode_channel(p.r, decode, r.gamma);
    p.g = decode_channel(p.g, decode, r.gamma);
    p.b = decode_channel(p.b, decode, r.gamma);
    // An alpha channel is transmit (POV-Ray's reading of an image's alpha).
    p.transmit = 1 - r.alpha[i];
    const int k = r.index.empty() ? -1 : r.index[i];
    for (const auto& [index, amount] : r.filter)
      if (index < 0 || index == k) p.filter = static_cast<float>(amount);
    for (const auto& [index, amount] : r.transmit)
      if (index < 0 || index == k) p.transmit = static_cast<float>(amount);
    if (p.filter > 0 || p.transmit > 0) r.image.transmits = true;
    if (r.use_index && k >= 0 && r.palette_size > 1) {
      // A bump map's height from the palette index instead of the colour's grey.
      const auto h = static_cast<float>(k) / static_cast<float>(r.palette_size - 1);
      p.r = p.g = p.b = h;
    }
  }
}

}  // namespace raycast::pov

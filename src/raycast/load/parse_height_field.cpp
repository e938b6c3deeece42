// The `height_field` shape: an image's values as heights over the unit square, built as a mesh.
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "io/image.h"
#include "load/shape_parsers.h"
#include "mesh/height_field.h"

namespace raycast {

ShapeVariant parse_height_field(Fields& f) {
  const SourceContext& ctx = f.ctx();
  const std::string name = f.string("image");
  const std::string format = f.string("format", "");
  HeightFieldOptions options;
  options.smooth = f.boolean("smooth", false);
  options.water_level = f.number("water_level", 0);
  if (!std::isfinite(options.water_level))
    f.fail("water_level", "height_field.water_level must be finite");
  const std::filesystem::path p(name);
  const std::string path = p.is_absolute() ? name : (std::filesystem::path(ctx.dir) / p).string();
  if (ctx.files) ctx.files->push_back(path);
  HeightImage image;
  try {
    image = read_height_image(path, height_image_format(format, path));
  } catch (const ImageError& e) {
    f.fail(f.has("format") ? "format" : "image", std::string("height_field.image: ") + e.what());
  }
  try {
    return MeshShape{make_height_field(height_grid_of(image), options)};
  } catch (const std::invalid_argument& e) {
    f.fail("image", std::string("height_field.image: ") + e.what());
  }
}

}  // namespace raycast

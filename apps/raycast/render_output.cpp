#include "render_output.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "output_file.h"

namespace raycast::cli {

void normalize_depth(Image& image) {
  std::vector<float> finite;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3)
    if (std::isfinite(image.rgb[i])) finite.push_back(image.rgb[i]);
  float scale = 0;
  if (!finite.empty()) {
    auto middle = finite.begin() + std::ptrdiff_t(finite.size() / 2);
    std::nth_element(finite.begin(), middle, finite.end());
    scale = 2 * *middle;
  }
  for (float& d : image.rgb)
    d = std::isfinite(d) ? (scale > 0 ? std::min(1.f, d / scale) : 0.f) : 1.f;
}

std::string aov_path(const std::string& output, const std::string& aov) {
  std::filesystem::path p(output);
  p.replace_extension();
  return p.string() + "." + aov + ".pfm";
}

void save_render(Image image, const std::string& path, bool depth) {
  if (depth && (is_stdout(path) || image_format_for(path) == ImageFormat::kPng))
    normalize_depth(image);
  write_output_image(image, path);
}

}  // namespace raycast::cli

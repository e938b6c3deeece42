// The OpenEXR plugin (io/exr_plugin_abi.h): the only code that links OpenEXR, loaded by
// io/exr.cpp the first time an image is written as .exr. It throws the core's own header-only
// ImageError, which the core catches by type across the module boundary.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <exception>

#include "io/exr_plugin_abi.h"

namespace raycast {
namespace {

void save(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0)
    throw ImageError(path + ": cannot write an empty image");
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    const char* names[3] = {"R", "G", "B"};
    for (const char* name : names) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    Imf::FrameBuffer frame;
    const std::size_t x_stride = 3 * sizeof(float);
    const std::size_t y_stride = x_stride * std::size_t(image.width);
    // The slices point into our buffer; OpenEXR only reads through them.
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.rgb.data()));
    for (int c = 0; c < 3; ++c)
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), x_stride, y_stride));
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    throw ImageError(path + ": cannot write EXR: " + e.what());
  }
}

const ExrPlugin kPlugin{kExrPluginAbiVersion, save};

}  // namespace
}  // namespace raycast

extern "C" __attribute__((visibility("default"))) const raycast::ExrPlugin*
raycast_openexr_plugin() {
  return &raycast::kPlugin;
}

#include "io/image.h"

#if RAYCAST_HAVE_OPENEXR
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include <exception>
#endif

namespace raycast {

#if RAYCAST_HAVE_OPENEXR

bool have_exr() { return true; }

void save_exr(const Image& image, const std::string& path) {
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

#else

bool have_exr() { return false; }

void save_exr(const Image&, const std::string& path) {
  throw ImageError(path + ": this build has no OpenEXR support; write .png or .pfm");
}

#endif

}  // namespace raycast

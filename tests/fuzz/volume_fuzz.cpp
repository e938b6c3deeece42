// libFuzzer target for the volume readers: particle files (PLY, CSV, .xyz) and raw density grids
// with their JSON sidecar. The first byte picks the input: 'P' PLY, 'C' CSV, 'X' .xyz particles;
// 'G' a grid, whose sidecar is the text up to the first NUL byte and whose raw floats are the
// rest. Anything else is skipped. Every input must read or throw VolumeFileError.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>

#include "volume/grid_file.h"
#include "volume/particle_file.h"

namespace {

void write_file(const std::string& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::string stem = "/tmp/raycast_volume_fuzz_" + std::to_string(getpid());
  const char kind = static_cast<char>(data[0]);
  try {
    if (kind == 'G') {
      const std::size_t nul = bytes.find('\0');
      const std::string_view json = bytes.substr(0, nul);
      const std::string_view raw =
          nul == std::string_view::npos ? std::string_view() : bytes.substr(nul + 1);
      write_file(stem + ".json", json);
      write_file(stem + ".raw", raw);
      (void)raycast::read_raw_grid(stem + ".raw");
    } else {
      const char* ext = kind == 'P'   ? ".ply"
                        : kind == 'C' ? ".csv"
                        : kind == 'X' ? ".xyz"
                                      : nullptr;
      if (!ext) return 0;
      write_file(stem + ext, bytes);
      (void)raycast::read_particles(stem + ext);
      std::remove((stem + ext).c_str());
    }
  } catch (const raycast::VolumeFileError&) {
  }
  std::remove((stem + ".json").c_str());
  std::remove((stem + ".raw").c_str());
  return 0;
}

#include "output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace raycast::cli {

std::string output_problem(const std::string& path) {
  if (is_stdout(path)) return {};
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return path + ": is a directory";
  const bool existed = std::filesystem::exists(path, ec);
  std::FILE* file = std::fopen(path.c_str(), "ab");
  if (!file) return path + ": cannot create the file: " + std::strerror(errno);
  std::fclose(file);
  if (!existed) std::remove(path.c_str());
  return {};
}

void write_output_image(const Image& image, const std::string& path) {
  if (!is_stdout(path)) return save_image(image, path);
  write_png(image, stdout, "<stdout>");
  if (std::fflush(stdout) != 0) throw ImageError("<stdout>: cannot write the image");
}

}  // namespace raycast::cli

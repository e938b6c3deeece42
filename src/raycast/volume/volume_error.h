#pragma once
// The error of the volume readers: a data file that cannot be used, with the position in it.
#include <stdexcept>
#include <string>

namespace raycast {

/// A malformed, truncated or oversized particle or grid file. `line` and `column` are 1-based
/// (for binary data: the line after the header and column 1, with the byte offset in the
/// message). The scene loader turns it into a SceneError naming the data file.
class VolumeFileError : public std::runtime_error {
 public:
  VolumeFileError(std::string file, int line, int column, const std::string& message)
      : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                           message),
        file_(std::move(file)),
        line_(line),
        column_(column),
        message_(message) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_, column_;
  std::string message_;
};

}  // namespace raycast

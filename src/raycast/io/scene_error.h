#pragma once
// The one error type for bad user input: file, 1-based line and column, and what was expected.
#include <sstream>
#include <stdexcept>
#include <string>

namespace raycast {

class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, int line, int column, const std::string& message)
      : std::runtime_error(format(file, line, column, message)),
        file_(std::move(file)),
        line_(line),
        column_(column),
        message_(message) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }      // 1-based; 0 when unknown
  int column() const { return column_; }  // 1-based; 0 when unknown
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& file, int line, int column, const std::string& m) {
    std::ostringstream s;
    s << file;
    if (line > 0) s << ':' << line << ':' << column;
    s << ": " << m;
    return s.str();
  }
  std::string file_;
  int line_, column_;
  std::string message_;
};

}  // namespace raycast

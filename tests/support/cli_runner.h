#pragma once
// Runs the raycast binary (RAYCAST_BINARY) for end-to-end tests, on files written to a temporary
// folder of this process that is removed once every test has run.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace raycast::test {

namespace fs = std::filesystem;

/// Exit code (-1: killed by a signal), captured output and wall time of one run.
struct Outcome {
  int code = -1;
  std::string out, err;
  double seconds = 0;
};

inline fs::path temp_dir() {
  const fs::path dir = fs::temp_directory_path() / ("raycast_cli_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

class RemoveTempDir : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(temp_dir(), ec);
  }
};
inline const auto* const kRemoveTempDir = ::testing::AddGlobalTestEnvironment(new RemoveTempDir);

/// Writes `content` to `name` in the temporary folder and returns its path.
inline std::string write(const std::string& name, const std::string& content) {
  const fs::path p = temp_dir() / name;
  std::ofstream(p, std::ios::binary) << content;
  return p.string();
}

inline std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Runs the binary with `args` (already shell-quoted where needed).
inline Outcome run(const std::string& args) {
  const fs::path dir = temp_dir();
  const std::string out = (dir / "stdout").string(), err = (dir / "stderr").string();
  const std::string cmd =
      std::string("'") + RAYCAST_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const auto start = std::chrono::steady_clock::now();
  const int status = std::system(cmd.c_str());
  Outcome r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read(out);
  r.err = read(err);
  return r;
}

}  // namespace raycast::test

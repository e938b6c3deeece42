// Every include file of POV-Ray 3.7's standard library (Debian's povray-includes, found where
// POV-Ray finds it; never copied into the project) parses, each after the prelude scenes use:
// colors.inc, shapes.inc and stdcam.inc. Skipped when the folder is absent (the test command
// installs the package: scripts/packages/test-pov.txt).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "pov/interpreter.h"

namespace raycast::pov {
namespace {

constexpr const char* kIncludes = "/usr/share/povray-3.7/include";

TEST(PovIncludes, EveryStandardIncludeParses) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(kIncludes)) GTEST_SKIP() << kIncludes << " is absent (povray-includes)";
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kIncludes)) {
    if (entry.path().extension() != ".inc") continue;
    ++files;
    const std::string name = entry.path().filename().string();
    Options o;
    o.system_library_path = false;
    o.library_paths = {kIncludes};
    std::ostringstream debug;
    o.debug = &debug;
    const std::string text =
        "#include \"colors.inc\"\n#include \"shapes.inc\"\n"
        "#include \"stdcam.inc\"\n#include \"" +
        name + "\"\n";
    try {
      interpret_pov(text, "t.pov", ".", o);
    } catch (const SceneError& e) {
      ADD_FAILURE() << name << ": " << e.what();
    }
  }
  EXPECT_GT(files, 30);
}

}  // namespace
}  // namespace raycast::pov

// The README's examples work: every `raycast cast SCENE <<< "RAY"` line in it is run and must hit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/cli_runner.h"

namespace {

TEST(Readme, CastExamples_Hit) {
  std::ifstream in(std::string(RAYCAST_SOURCE_DIR) + "/README.md");
  ASSERT_TRUE(in) << "README.md not found";
  const std::string marker = "raycast cast ";
  int examples = 0;
  for (std::string line; std::getline(in, line);) {
    // `raycast cast SCENE <<< "RAY"` (std::regex is avoided: GCC 12 warns inside <regex>).
    const std::size_t at = line.find(marker), here = line.find(" <<< \"");
    if (at == std::string::npos || here == std::string::npos || here < at + marker.size()) continue;
    const std::size_t ray_end = line.find('"', here + 6);
    if (ray_end == std::string::npos) continue;
    const std::string scene = line.substr(at + marker.size(), here - at - marker.size());
    const std::string ray = line.substr(here + 6, ray_end - here - 6);
    if (scene.find(' ') != std::string::npos) continue;  // options: not this simple form
    ++examples;
    const std::string rays = raycast::test::write("readme_ray.txt", ray + "\n");
    const raycast::test::Outcome r = raycast::test::run("cast '" + std::string(RAYCAST_SOURCE_DIR) +
                                                        "/" + scene + "' --rays '" + rays + "'");
    EXPECT_EQ(r.code, 0) << line << "\n" << r.err;
    const double t = std::strtod(r.out.c_str(), nullptr);
    EXPECT_TRUE(std::isfinite(t)) << line << " answered: " << r.out;
  }
  EXPECT_GE(examples, 1) << "no `raycast cast SCENE <<< \"RAY\"` example in README.md";
}

}  // namespace

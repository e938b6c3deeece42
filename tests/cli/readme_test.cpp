// The README's examples work: every `raycast cast SCENE <<< "RAY"` line in it is run and must hit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "../support/cli_runner.h"

namespace {

TEST(Readme, CastExamples_Hit) {
  std::ifstream in(std::string(RAYCAST_SOURCE_DIR) + "/README.md");
  ASSERT_TRUE(in) << "README.md not found";
  const std::regex example(R"(raycast cast (\S+) <<< "([^"]+)\")");
  int examples = 0;
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, example)) continue;
    ++examples;
    const std::string rays = raycast::test::write("readme_ray.txt", m[2].str() + "\n");
    const raycast::test::Outcome r = raycast::test::run(
        "cast '" + std::string(RAYCAST_SOURCE_DIR) + "/" + m[1].str() + "' --rays '" + rays + "'");
    EXPECT_EQ(r.code, 0) << line << "\n" << r.err;
    const double t = std::strtod(r.out.c_str(), nullptr);
    EXPECT_TRUE(std::isfinite(t)) << line << " answered: " << r.out;
  }
  EXPECT_GE(examples, 1) << "no `raycast cast SCENE <<< \"RAY\"` example in README.md";
}

}  // namespace

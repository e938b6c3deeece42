// `raycast info --system` and RAYCAST_ISA end to end: the forced path is the one reported, and an
// unknown or unsupported request falls back with a warning (docs/architecture.md "ISA dispatch").
#include <gtest/gtest.h>

#include <cstdlib>

#include "../support/cli_runner.h"
#include "math/isa.h"

namespace raycast {
namespace {

// Runs `raycast info --system` with RAYCAST_ISA set to `value` (unset when null).
test::Outcome info_system(const char* value) {
  if (value)
    setenv("RAYCAST_ISA", value, 1);
  else
    unsetenv("RAYCAST_ISA");
  test::Outcome o = test::run("info --system");
  unsetenv("RAYCAST_ISA");
  return o;
}

TEST(IsaCli, InfoSystem_ReportsTheCpusBestPathByDefault) {
  const test::Outcome o = info_system(nullptr);
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find(std::string("isa: ") + isa_name(best_isa()) + " (cpu)"), std::string::npos)
      << o.out;
  EXPECT_EQ(o.err, "");
}

TEST(IsaCli, RaycastIsa_ForcesEverySupportedPath) {
  for (Isa isa : kAllIsas) {
    if (!isa_supported(isa)) continue;
    const test::Outcome o = info_system(isa_name(isa));
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.out.find(std::string("isa: ") + isa_name(isa) + " (RAYCAST_ISA)"),
              std::string::npos)
        << o.out;
    EXPECT_EQ(o.err, "");
  }
}

TEST(IsaCli, UnknownIsa_WarnsAndFallsBackToTheBest) {
  const test::Outcome o = info_system("avx9");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find(std::string("isa: ") + isa_name(best_isa())), std::string::npos) << o.out;
  EXPECT_NE(o.err.find("warning: RAYCAST_ISA=avx9 is not one of"), std::string::npos) << o.err;
}

TEST(IsaCli, InfoWithoutSceneOrSystem_IsAUsageError) {
  const test::Outcome o = test::run("info");
  EXPECT_EQ(o.code, 2);
}

}  // namespace
}  // namespace raycast

// trace, inside, min_extent and max_extent answer from the object as the engine builds it, in
// the scene's own (left-handed) coordinates; the scene checks each answer with #error, so a
// wrong one is a SceneError naming the line.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/scene_error.h"
#include "load/pov_loader.h"

namespace raycast {
namespace {

// Loads the scene text (plus a camera and a light); returns the error message, or "".
std::string error_of(const std::string& body, std::vector<std::string>* warnings = nullptr) {
  const std::string text = "camera { location <0, 0, -10> look_at 0 }\n" + body +
                           "\nsphere { 0, 1 pigment { rgb 1 } }\n";
  try {
    std::vector<std::string> w;
    load_pov_scene_text(text, "t.pov", ".", -1, {}, warnings ? warnings : &w);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// `#error` unless the vectors A and B are within 1e-9.
std::string expect_near(const std::string& a, const std::string& b) {
  return "#if (vlength((" + a + ") - (" + b + ")) > 1e-9) #error concat(\"" + a +
         " = \", vstr(3, " + a + ", \", \", 0, 12)) #end\n";
}

TEST(PovObjectFunctions, Trace_HitsTheNearestSurfaceWithItsOutwardNormal) {
  const std::string s =
      "#declare S = sphere { <1, 2, 3>, 2 }\n"
      "#declare N = <9, 9, 9>;\n"
      "#declare P = trace(S, <1, 2, -10>, <0, 0, 5>, N);\n" +
      expect_near("P", "<1, 2, 1>") + expect_near("N", "<0, 0, -1>") +
      // From inside, the far side; the normal still points out of the solid.
      "#declare P = trace(S, <1, 2, 3>, <1, 0, 0>, N);\n" + expect_near("P", "<3, 2, 3>") +
      expect_near("N", "<1, 0, 0>");
  EXPECT_EQ(error_of(s), "");
}

TEST(PovObjectFunctions, Trace_FollowsTransformsAndUnions) {
  const std::string s =
      "#declare U = union { box { -1, 1 } sphere { <0, 5, 0>, 1 } scale 2 translate <0, 0, 1> }\n"
      "#declare N = 0;\n"
      "#declare P = trace(U, <0, 100, 1>, -y, N);\n" +
      expect_near("P", "<0, 12, 1>") + "#declare P = trace(U, <0.5, 0, -20>, z, N);\n" +
      expect_near("P", "<0.5, 0, -1>") + expect_near("N", "<0, 0, -1>");
  EXPECT_EQ(error_of(s), "");
}

TEST(PovObjectFunctions, Trace_MissAnswersZeroAndZeroNormal) {
  const std::string s =
      "#declare S = sphere { 0, 1 }\n"
      "#declare N = <1, 1, 1>;\n"
      "#declare P = trace(S, <0, 5, 0>, y, N);\n" +
      expect_near("P", "<0, 0, 0>") + expect_near("N", "<0, 0, 0>") +
      "#declare P = trace(S, <0, 5, 0>, 0);\n" + expect_near("P", "<0, 0, 0>");
  EXPECT_EQ(error_of(s), "");
}

TEST(PovObjectFunctions, Inside_FollowsCsg) {
  const std::string s =
      "#declare D = difference { sphere { 0, 2 } sphere { 0, 1 } }\n"
      "#if (inside(D, <1.5, 0, 0>) != 1) #error \"shell\" #end\n"
      "#if (inside(D, <0.5, 0, 0>) != 0) #error \"hole\" #end\n"
      "#if (inside(D, <3, 0, 0>) != 0) #error \"outside\" #end\n";
  EXPECT_EQ(error_of(s), "");
}

TEST(PovObjectFunctions, Extents_AreTheBoundingBoxAndPovRaysHugeBoundWhenUnbounded) {
  const std::string s = "#declare B = box { <-1, -2, -3>, <1, 2, 3> translate <10, 0, 0> }\n" +
                        expect_near("min_extent(B)", "<9, -2, -3>") +
                        expect_near("max_extent(B)", "<11, 2, 3>") +
                        "#declare P = plane { y, 0 }\n"
                        "#declare Hi = max_extent(P); #declare Lo = min_extent(P);\n"
                        "#if (Hi.x < 1e10 | Lo.x > -1e10) #error \"plane\" #end\n";
  EXPECT_EQ(error_of(s), "");
}

TEST(PovObjectFunctions, ObjectNotBuilt_AnswersZeroWithAWarning) {
  std::vector<std::string> warnings;
  EXPECT_EQ(error_of("#declare T = ovus { 1, 0.5 }\n"
                     "#declare M = max_extent(T);\n" +
                         expect_near("M", "<0, 0, 0>"),
                     &warnings),
            "");
  bool warned = false;
  for (const std::string& w : warnings)
    warned = warned ||
             w.find("max_extent function of an object raycast does not build") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(PovObjectFunctions, NonObjectArgument_IsAPositionedError) {
  const std::string e = error_of("#declare P = trace(3, <0, 0, 0>, z);");
  EXPECT_NE(e.find("t.pov:2:20: trace: expected an object"), std::string::npos) << e;
  const std::string n = error_of("#declare S = sphere { 0, 1 }\n#declare P = inside(S);");
  EXPECT_NE(n.find("inside takes 2 argument(s)"), std::string::npos) << n;
}

}  // namespace
}  // namespace raycast

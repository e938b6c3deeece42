// The POV-Ray parser's positioned errors: constructs outside the subset, malformed input,
// non-finite values, deep nesting and huge counts. Each must be a SceneError naming the file,
// line and column, never a crash or a silent skip.
#include <gtest/gtest.h>

#include <string>

#include "pov/import.h"
#include "pov/parser.h"

namespace raycast::pov {
namespace {

std::string error_of(const std::string& text) {
  try {
    import_pov_text(text, "t.pov", RAYCAST_SOURCE_DIR "/tests/pov/scenes");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

bool starts(const std::string& text, const std::string& prefix) {
  if (text.rfind(prefix, 0) == 0) return true;
  ADD_FAILURE() << "'" << text << "' does not start with '" << prefix << "'";
  return false;
}

TEST(PovParser, UnsupportedObjectIsNamedAtItsPosition) {
  EXPECT_EQ(error_of("sphere { 0, 1 }\n  blob { }"),
            "t.pov:2:3: 'blob' is not supported by the POV-Ray import (expected a scene item "
            "(camera, light_source, an object, global_settings, background or a directive))");
}

TEST(PovParser, UnsupportedPatternsModifiersAndDirectives) {
  EXPECT_TRUE(starts(error_of("sphere { 0, 1 pigment { bozo } }"),
                     "t.pov:1:25: 'bozo' is not supported by the POV-Ray import"));
  EXPECT_TRUE(
      starts(error_of("#if (1) #end"), "t.pov:1:1: '#if' is not supported by the POV-Ray i"));
  EXPECT_TRUE(starts(error_of("sphere { 0, 1 no_shadow }"),
                     "t.pov:1:15: 'no_shadow' is not supported by the POV-Ray "));
  EXPECT_TRUE(starts(error_of("camera { fisheye }"),
                     "t.pov:1:10: 'fisheye' is not supported by the POV-Ra"));
  EXPECT_TRUE(starts(error_of("sphere { 0, 1 finish { metallic } }"),
                     "t.pov:1:24: 'metallic' is not supported by the POV-Ray"));
  EXPECT_TRUE(starts(error_of("global_settings { radiosity { } }"),
                     "t.pov:1:19: 'radiosity' is not supported by the POV-Ray"));
}

TEST(PovParser, StandardIncludesAreNotRead) {
  EXPECT_NE(error_of("#include \"colors.inc\"")
                .find("t.pov:1:10: cannot open #include file "
                      "'colors.inc'"),
            std::string::npos);
}

TEST(PovParser, ErrorsInsideAnIncludedFileNameThatFile) {
  const std::string e = error_of("#include \"bad.inc\"");
  EXPECT_NE(e.find("bad.inc:2:3: 'superellipsoid' is not supported"), std::string::npos) << e;
}

TEST(PovParser, MalformedInput) {
  EXPECT_EQ(error_of("sphere { 0 }"), "t.pov:1:12: expected a number, a vector or a name, got '}'");
  EXPECT_EQ(error_of("sphere { <1, 2, 3 0.5 }"),
            "t.pov:1:19: expected '>' to close the vector '<', got the number 0.5");
  EXPECT_EQ(error_of("sphere { 0, 1"),
            "t.pov:1:14: expected an object modifier in sphere, got the end of the file");
  EXPECT_EQ(error_of("sphere { 0, Radius }"),
            "t.pov:1:13: unknown name 'Radius' (not #declared, and not a function the import "
            "knows)");
}

TEST(PovParser, NonFiniteValuesAreRejected) {
  EXPECT_EQ(error_of("sphere { 0, sqrt(-1) }"), "t.pov:1:13: sqrt(...) is not a finite number");
  EXPECT_EQ(error_of("sphere { 0, 1 / 0 }"), "t.pov:1:15: division by zero");
  EXPECT_EQ(error_of("sphere { 0, exp(1000) }"), "t.pov:1:13: exp(...) is not a finite number");
  EXPECT_EQ(error_of("sphere { 0, 1e300 * 1e300 }"),
            "t.pov:1:13: the expression is not a finite number (overflow)");
}

TEST(PovParser, DeepNestingIsAnErrorNotACrash) {
  std::string objects, close;
  for (int i = 0; i < 300; ++i) objects += "union {\n", close += "}";
  EXPECT_NE(
      error_of(objects + "sphere { 0, 1 }" + close).find("objects are nested deeper than 256"),
      std::string::npos);
  EXPECT_TRUE(starts(error_of(objects + "sphere { 0, 1 }" + close), "t.pov:258:1:"));
  std::string parens(400, '(');
  EXPECT_NE(error_of("sphere { 0, " + parens + "1" + std::string(400, ')') + " }")
                .find("expressions are nested deeper than 256"),
            std::string::npos);
  std::string minus(100000, '-');
  EXPECT_NE(error_of("sphere { 0, " + minus + "1 }").find("nested deeper than 256"),
            std::string::npos);
}

TEST(PovParser, HugeCountsAreRefusedBeforeAnyWork) {
  EXPECT_NE(error_of("mesh2 { vertex_vectors { 1e12, <0,0,0> } face_indices { 0 } }")
                .find("t.pov:1:26: the number of vertex_vectors must be a whole number in [0, "
                      "16777216]"),
            std::string::npos);
  EXPECT_NE(error_of("mesh2 { vertex_vectors { 2.5, <0,0,0> } face_indices { 0 } }")
                .find("must be a whole number"),
            std::string::npos);
  EXPECT_NE(error_of("poly { 40, <1> }")
                .find("t.pov:1:8: poly's order must be a whole number "
                      "in [2, 16]"),
            std::string::npos);
  EXPECT_NE(error_of("light_source { 0, rgb 1 area_light x, z, 100000, 100000 }")
                .find("at most 4096 samples"),
            std::string::npos);
  EXPECT_NE(error_of("lathe { 1e9, <0, 0> }").find("t.pov:1:9: the number of points must be"),
            std::string::npos);
}

TEST(PovParser, DeclaredObjectsCopiedIntoEachOtherAreBounded) {
  // Each declaration doubles the one before: 2^40 spheres if nothing stopped it.
  std::string text = "#declare A0 = sphere { 0, 1 }\n";
  for (int i = 1; i <= 40; ++i)
    text += "#declare A" + std::to_string(i) + " = union { object { A" + std::to_string(i - 1) +
            " } object { A" + std::to_string(i - 1) + " } }\n";
  const std::string e = error_of(text);
  EXPECT_NE(e.find("the scene is too large"), std::string::npos) << e;
}

TEST(PovParser, MacrosReplayTheirBodyWithTheArguments) {
  const PovScene s = parse_pov(
      "#macro Ball(C, R) sphere { C, R * 2 } #end\n"
      "#macro Two(T) union { Ball(<1, 2, 3>, 0.5) Ball(-x, 1 + 1) texture { T } } #end\n"
      "#declare Red = texture { pigment { rgb <1, 0, 0> } }\n"
      "object { Two(Red) }",
      "t.pov", ".");
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(s.objects[0].children.size(), 2u);
  EXPECT_EQ(s.objects[0].children[0].points[0].z, 3);
  EXPECT_EQ(s.objects[0].children[0].values[0], 1);
  EXPECT_EQ(s.objects[0].children[1].points[0].x, -1);
  EXPECT_EQ(s.objects[0].children[1].values[0], 4);  // (1 + 1) * 2, not 1 + 1 * 2
  EXPECT_EQ(s.objects[0].texture->pigment.c0.r, 1);
}

TEST(PovParser, MacroErrors) {
  EXPECT_NE(error_of("#macro M() sphere { 0, 1 }").find("t.pov:1:1: #macro M is never closed"),
            std::string::npos);
  EXPECT_NE(error_of("#macro M(A) sphere { 0, A } #end\nM(1, 2)")
                .find("t.pov:2:1: M takes 1 "
                      "argument(s), got 2"),
            std::string::npos);
  EXPECT_NE(error_of("#macro M() M() #end\nM()").find("macros are nested deeper than 64"),
            std::string::npos);
  // An error inside a macro's body points at the body.
  EXPECT_NE(error_of("#macro M()\n  blob { } #end\nM()")
                .find("t.pov:2:3: 'blob' is not "
                      "supported"),
            std::string::npos);
}

TEST(PovParser, CountsMustMatchTheItems) {
  EXPECT_NE(error_of("mesh2 { vertex_vectors { 1, <0,0,0>, <1,0,0> } face_indices { 0 } }")
                .find("vertex_vectors announced 1 items, got more"),
            std::string::npos);
  EXPECT_NE(error_of("mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, "
                     "<0, 1, 7> } }")
                .find("vertex index 7 out of range (3 vertices)"),
            std::string::npos);
  EXPECT_NE(error_of("quartic { <1, 2, 3> }")
                .find("a polynomial of order 4 has 35 coefficients, "
                      "got 3"),
            std::string::npos);
}

TEST(PovParser, PolynomialsNeedABox) {
  EXPECT_NE(error_of("poly { 2, <1,0,0,0,1,0,0,1,0,-1> }")
                .find("t.pov:1:1: raycast needs a bounded polynomial"),
            std::string::npos);
  EXPECT_EQ(error_of("intersection { poly { 2, <1,0,0,0,1,0,0,1,0,-1> } box { -2, 2 } }"), "");
  EXPECT_EQ(error_of("poly { 2, <1,0,0,0,1,0,0,1,0,-1> bounded_by { box { -2, 2 } } }"), "");
}

TEST(PovParser, ValuesOfTheWrongKind) {
  EXPECT_EQ(error_of("#declare T = texture { pigment { rgb 1 } }\nsphere { T, 1 }"),
            "t.pov:2:10: 'T' is not a number or a vector here");
  EXPECT_EQ(error_of("sphere { <1, 2>, 1 }"),
            "t.pov:1:10: expected a 3-vector for sphere's centre, got a 2-vector");
  EXPECT_EQ(error_of("camera { angle 200 }"), "t.pov:1:10: angle must be in (0, 180) degrees");
  EXPECT_EQ(error_of("sphere { 0, 1 scale <1, 0, 1> }"),
            "t.pov:1:15: scale must not be 0 on any axis");
}

TEST(PovParser, DeclaredValuesEvaluate) {
  const PovScene s = parse_pov(
      "#declare A = 2; #local V = <1, 2, 3> * A + x;\n"
      "#declare C = color rgbt <0.1, 0.2, 0.3, 0.4>;\n"
      "sphere { V, min(A, 5) / 4 + vlength(<3, 4, 0>) pigment { C } }",
      "t.pov", ".");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].points[0].x, 3);
  EXPECT_EQ(s.objects[0].points[0].z, 6);
  EXPECT_EQ(s.objects[0].values[0], 5.5);
  EXPECT_EQ(s.objects[0].texture->pigment.c0.transmit, 0.4);
  EXPECT_EQ(s.objects[0].texture->pigment.c0.b, 0.3);
}

TEST(PovParser, PolyCoefficientsFollowPovRaysTermOrder) {
  // The cubic's 20 terms: x^3, x^2 y, x^2 z, x^2, x y^2, x y z, x y, x z^2, x z, x, y^3, ...
  const PovScene s = parse_pov(
      "cubic { <1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20> "
      "bounded_by { box { -1, 1 } } }",
      "t.pov", ".");
  const auto& t = s.objects[0].terms;
  EXPECT_EQ(t.at({3, 0, 0}), 1);
  EXPECT_EQ(t.at({2, 0, 1}), 3);
  EXPECT_EQ(t.at({1, 1, 1}), 6);
  EXPECT_EQ(t.at({1, 0, 2}), 8);
  EXPECT_EQ(t.at({0, 3, 0}), 11);
  EXPECT_EQ(t.at({0, 1, 2}), 14);
  EXPECT_EQ(t.at({0, 0, 3}), 17);
  EXPECT_EQ(t.at({0, 0, 0}), 20);
}

}  // namespace
}  // namespace raycast::pov

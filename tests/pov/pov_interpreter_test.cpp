// The POV-Ray interpreter against the reference documentation's rules and POV-Ray 3.7's own
// #debug output for the same text (captured once with `povray +I t.pov -D`; POV-Ray is not needed
// to run these tests): directives, scoping, macros, expressions, strings, arrays, functions,
// splines, positioned errors and the bounds on loops and recursion.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "pov/interpreter.h"

namespace raycast::pov {
namespace {

// What the scene's #debug statements print.
std::string debug_of(const std::string& text, Options o = {}) {
  std::ostringstream out;
  o.debug = &out;
  o.system_library_path = false;
  interpret_pov(text, "t.pov", RAYCAST_SOURCE_DIR "/tests/pov/scenes", o);
  return out.str();
}

std::string error_of(const std::string& text, Options o = {}) {
  try {
    debug_of(text, o);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(PovInterpreter, DeclareInMacroChangesTheLocalAndCreatesGlobals) {
  // POV-Ray 3.7 prints "in M A=3" and "after A=1 Q=7 NewG=5".
  EXPECT_EQ(debug_of(R"(#declare A = 1;
#macro M(P)
  #local A = 2;
  #declare A = 3;
  #debug concat("in M A=", str(A,0,0), "\n")
  #declare P = 7;
  #declare NewG = 5;
#end
#declare Q = 1;
M(Q)
#debug concat("after A=", str(A,0,0), " Q=", str(Q,0,0), " NewG=", str(NewG,0,0), "\n"))"),
            "in M A=3\nafter A=1 Q=7 NewG=5\n");
}

TEST(PovInterpreter, SwitchFallsThroughUntilBreak) {
  // POV-Ray 3.7: c2 c3, then r13 else.
  EXPECT_EQ(debug_of(R"(#switch (2)
#case (1) #debug "c1 "
#case (2) #debug "c2 "
#case (3) #debug "c3 "
#break
#case (4) #debug "c4 "
#end
#switch (2)
#range (1,3) #debug "r13 "
#else #debug "else"
#end)"),
            "c2 c3 r13 else");
}

TEST(PovInterpreter, MacroResultJoinsTheCallersExpression) {
  // POV-Ray 3.7 prints X=7: the body's tokens 1+2 continue as 1+2*3.
  EXPECT_EQ(debug_of("#macro Add(A,B) A+B #end\n#declare X = Add(1,2)*3;\n"
                     "#debug concat(\"X=\", str(X,0,0))"),
            "X=7");
}

TEST(PovInterpreter, StrAndVstrFormatAsPovRay) {
  // POV-Ray 3.7: 5.000|5.0|-2.50|0.333333|1.0,2.0,3.0
  EXPECT_EQ(debug_of(R"(#debug concat(str(5,0,3), "|", str(5,-3,1), "|", str(-2.5,5,2), "|",
str(1/3,0,-1), "|", vstr(3,<1,2,3>,",",0,1)))"),
            "5.000|5.0|-2.50|0.333333|1.0,2.0,3.0");
}

TEST(PovInterpreter, VectorsColoursAndPromotion) {
  // POV-Ray 3.7: 2.0,4.0,6.0 / 1.0,1.0,1.0,0.0,0.0 / 2.0,3.0,1.0 / 5
  EXPECT_EQ(debug_of(R"(#declare V = <1,2,3>*<2,2,2>; #debug vstr(3,V,",",0,1) #debug "/"
#declare C = rgb 1; #debug vstr(5,C,",",0,1) #debug "/"
#declare C2 = <1,2>; #declare C3 = C2 + <1,1,1>; #debug vstr(3,C3,",",0,1) #debug "/"
#declare T = 1 ? 5 : 6; #debug str(T,0,0))"),
            "2.0,4.0,6.0/1.0,1.0,1.0,0.0,0.0/2.0,3.0,1.0/5");
}

TEST(PovInterpreter, LoopsWithoutSemicolons) {
  EXPECT_EQ(debug_of("#declare I=0; #while (I<3) #declare I=I+1 #end #debug str(I,0,0)\n"
                     "#for (J, 1, 7, 3) #debug str(J,0,0) #end"),
            "3147");
}

TEST(PovInterpreter, LongLoopDoesNotGrowTheStack) {
  EXPECT_EQ(debug_of("#declare I=0; #while (I<200000) #declare I=I+1 #end #debug str(I,0,0)"),
            "200000");
}

TEST(PovInterpreter, LoopTokensReadAgain_KeepTheirValuesAndPositions) {
  // The third iteration reads its tokens from the cache of the first two; its error must be the
  // one the same text gives when it fails on a first reading.
  const std::string body =
      "#while (I < 5)\n  #debug str(A[I], 0, 0)\n  #declare I = I + 1;\n#end\n";
  const std::string head = "#declare A = array[2] {7, 8}\n";
  const std::string again = error_of(head + "#declare I = 0;\n" + body);
  const std::string first = error_of(head + "#declare I = 2;\n" + body);
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(again, first);
  EXPECT_EQ(first, "t.pov:4:16: array index 2 out of range [0, 1]");
  EXPECT_EQ(debug_of("#macro M(X) str(X * 2, 0, 0) #end\n#for (K, 1, 3) #debug M(K) #end"), "246");
}

TEST(PovInterpreter, EndlessLoopStopsAtItsLine) {
  Options o;
  o.limits.loop_iterations = 1000;
  const std::string e = error_of("#declare A = 1;\n  #while (1)\n #declare A = A + 1; #end", o);
  EXPECT_EQ(e.rfind("t.pov:2:3: loops ran more than 1000 iterations", 0), 0u) << e;
  EXPECT_NE(e.find("--pov-max-iterations"), std::string::npos) << e;
}

TEST(PovInterpreter, RecursionIsBounded) {
  Options o;
  o.limits.macro_depth = 50;
  const std::string e = error_of("#macro R(N) R(N+1) #end\nR(0)", o);
  EXPECT_NE(e.find("nested deeper than 50"), std::string::npos) << e;
}

TEST(PovInterpreter, RecursiveMacroReturnsValue) {
  EXPECT_EQ(debug_of("#macro F(N) #if (N < 2) 1 #else N * F(N - 1) #end #end\n"
                     "#declare X = F(5); #debug str(X,0,0)"),
            "120");
}

TEST(PovInterpreter, OptionalParametersAndIfdef) {
  EXPECT_EQ(debug_of("#macro M(A, optional B) #ifdef(B) #debug \"B\" #else #debug \"noB\" "
                     "#end #end\nM(1, 2) M(1, )"),
            "BnoB");
}

// Pinned fuzz finding: a size past size_t's range was converted before it was compared.
TEST(PovInterpreter, HugeArraySize_IsAPositionedError) {
  const std::string e = error_of("#declare A = array[3e68];");
  EXPECT_NE(e.find("t.pov:1:20: an array of more than"), std::string::npos) << e;
  const std::string nan = error_of("#declare A = array[2][1e300];");
  EXPECT_NE(nan.find("an array of more than"), std::string::npos) << nan;
}

// Pinned fuzz finding: parentheses nested thousands deep overflowed the stack.
TEST(PovInterpreter, DeeplyNestedParentheses_AreAPositionedError) {
  const std::string deep =
      "#declare A = " + std::string(5000, '(') + "1" + std::string(5000, ')') + ";";
  const std::string e = error_of(deep);
  EXPECT_NE(e.find("t.pov:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("nested more than"), std::string::npos) << e;
  const std::string fine =
      "#declare A = " + std::string(40, '(') + "1" + std::string(40, ')') + ";";
  EXPECT_EQ(error_of(fine), "");
}

// POV-Ray compares only inside parentheses: after `#if (C)` a '<' opens a vector, and a
// block's `14 <-1, 0, 0>` is a count and a vector.
TEST(PovInterpreter, ComparisonsOnlyInsideParentheses) {
  EXPECT_EQ(debug_of("#declare P = 3;\n"
                     "#declare C = #if (P < 5) <0.7, 0.3, 0.1> #else <0, 0, 1> #end;\n"
                     "#debug vstr(3, C, \",\", 0, 1)"),
            "0.7,0.3,0.1");
  EXPECT_EQ(debug_of("#declare A = (1 < 2) + (2 >= 3) + select(1 < 2, 0, 1) + max(1 = 1, 0);\n"
                     "#debug str(A, 0, 0)"),
            "3");
  EXPECT_NE(error_of("#declare A = 0.6 < 1;"), "");
}

// rand gives POV-Ray 3.7's own sequence (values printed by povray 3.7 for these seeds), so
// scenes place their random things where POV-Ray does.
TEST(PovInterpreter, Rand_IsPovRaysSequence) {
  EXPECT_EQ(debug_of("#declare S = seed(1237);\n"
                     "#debug concat(str(rand(S), 0, 12), \" \", str(rand(S), 0, 12))"),
            "0.001633957494 0.896208123280");
  EXPECT_EQ(debug_of("#declare S = seed(-5);\n#debug str(rand(S), 0, 12)"), "0.890052870123");
  EXPECT_EQ(debug_of("#declare S = seed(3.7);\n#debug str(rand(S), 0, 12)"), "0.265972876983");
  EXPECT_EQ(debug_of("#declare S = seed(1e10);\n#debug str(rand(S), 0, 12)"), "0.500002874411");
}

TEST(PovInterpreter, StringsCompareInConditions) {
  EXPECT_EQ(debug_of("#declare V = \"tree\";\n"
                     "#if (V = \"tree\") #debug \"a\" #end #if (V != \"bush\") #debug \"b\" #end\n"
                     "#if (V = \"bush\") #debug \"c\" #end"),
            "ab");
  EXPECT_NE(error_of("#declare V = \"tree\";\n#if (V = 1) #end"), "");
}

// vturbulence is the push turbulence gives a point: zero nowhere in general, bounded by the
// octave sum, the same at the same point.
TEST(PovInterpreter, Vturbulence_IsBoundedAndRepeatable) {
  EXPECT_EQ(debug_of("#declare A = vturbulence(2, 0.5, 6, <0.3, 1.7, -2.2>);\n"
                     "#declare B = vturbulence(2, 0.5, 6, <0.3, 1.7, -2.2>);\n"
                     "#if (vlength(A - B) = 0 & vlength(A) > 0 & abs(A.x) <= 2 & abs(A.y) <= 2 "
                     "& abs(A.z) <= 2) #debug \"ok\" #end"),
            "ok");
}

// An array of colours picked by a macro inside a pigment is a colour (arrays.inc's
// Rand_Array_Item, as isocacti.pov uses it).
TEST(PovInterpreter, ColourFromAnArrayInAPigment) {
  EXPECT_EQ(error_of("#declare Cs = array[2] { rgb <1, 0, 0>, rgb <0, 1, 0> }\n"
                     "#macro Pick(A, I) A[I] #end\n"
                     "sphere { 0, 1 pigment { Pick(Cs, 1) * 0.5 } }\n"
                     "sphere { 0, 1 pigment { Cs[0] } }"),
            "");
}

// A directive written without its '#' after a value that an #if's #end closes (whiltile.pov:
// `#declare S = #ifdef (X) ... #else intersection { ... } #end` then `default { ... }`).
TEST(PovInterpreter, BareDirectiveAfterAnIfClosedInsideAValue) {
  EXPECT_EQ(error_of("#declare S = #ifdef (X) sphere { 0, 1 } #else box { -1, 1 } #end\n"
                     "default { texture { pigment { rgb 1 } } }\nobject { S }"),
            "");
}

// A macro whose value is chosen by #if goes on with the caller's operators after it.
TEST(PovInterpreter, MacroValueFromAnIf_TakesTheCallersOperators) {
  EXPECT_EQ(debug_of("#macro Pick(C) #if (C) 2 #else 3 #end #end\n"
                     "#declare A = Pick(1) * 10 + Pick(0);\n#debug str(A, 0, 0)"),
            "23");
}

// A pigment's name alone in a texture is its pigment, as POV-Ray reads it.
TEST(PovInterpreter, PigmentNameInATexture_IsItsPigment) {
  EXPECT_EQ(error_of("#declare P = pigment { rgb <1, 0, 0> }\n"
                     "sphere { 0, 1 texture { P finish { phong 1 } } }"),
            "");
}

TEST(PovInterpreter, UvMappingBeforeADeclaredPigment) {
  EXPECT_EQ(error_of("#declare P = pigment { rgb <1, 0, 0> }\n"
                     "sphere { 0, 1 pigment { uv_mapping P } }"),
            "");
}

// POV-Ray 3.1's refraction items in a finish are read (POV-Ray warns and goes on).
TEST(PovInterpreter, OldFinishRefractionItems_AreRead) {
  EXPECT_EQ(error_of("sphere { 0, 1 pigment { rgbf 1 } finish { refraction 1 ior 1.5 "
                     "caustics 0.5 } }"),
            "");
}

// A function held in an array is called like a declared one.
TEST(PovInterpreter, FunctionFromAnArrayElement_IsCalled) {
  EXPECT_EQ(debug_of("#declare Fns = array[2] { function(a, b) { a + b }, function { x * 2 } }\n"
                     "#declare V = <Fns[0](1, 2), Fns[1](4, 0, 0), 0>;\n"
                     "#debug vstr(2, V, \",\", 0, 0)"),
            "3,8");
}

// A macro whose body holds the value's `;` (`#if (C) Q; #else ... #end`): the #local that
// called it still names the caller's scope (POV-Ray's tracevines.pov).
TEST(PovInterpreter, LocalFromAMacroHoldingTheSemicolon_IsTheCallersLocal) {
  EXPECT_EQ(debug_of("#macro Find(C) #local Q = 7; #if (C) Q; #else 0; #end #end\n"
                     "#macro Outer() #local N = Find(1) #debug str(N, 0, 0) #end\nOuter()"),
            "7");
}

// Pinned fuzz finding: a directive inside a directive's value (`#declare A = #declare B = ...`)
// recursed without a bound; so did objects declared inside objects.
TEST(PovInterpreter, DirectivesNestedInValues_AreAPositionedError) {
  std::string chain;
  for (int i = 0; i < 5000; ++i) chain += "#declare A" + std::to_string(i) + " = ";
  const std::string e = error_of(chain + "1;");
  EXPECT_NE(e.find("t.pov:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("nested more than"), std::string::npos) << e;
  std::string objects;
  for (int i = 0; i < 3000; ++i) objects += "union { #declare U" + std::to_string(i) + " = ";
  const std::string o = error_of(objects);
  EXPECT_NE(o.find("more than"), std::string::npos) << o;
  EXPECT_EQ(error_of("#declare A = #declare B = 2; 3;\n#if (A != 3) #error \"A\" #end"), "");
}

// Bitwise operations, seed and vstr saturate numbers outside the integers' range.
TEST(PovInterpreter, NumbersPastTheIntegerRange_Saturate) {
  EXPECT_EQ(error_of("#declare S = seed(1e300);\n#declare B = bitwise_and(1e300, -1e300);\n"
                     "#declare T = vstr(1e300, <1, 2, 3>, \",\", 0, 1);"),
            "");
}

TEST(PovInterpreter, ArraysWithInitialisersAndDimensions) {
  EXPECT_EQ(debug_of(R"(#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#declare A[1][2] = 9;
#debug concat(str(A[0][1],0,0), str(A[1][2],0,0), str(dimensions(A),0,0),
str(dimension_size(A,2),0,0)))"),
            "2923");
  EXPECT_NE(error_of("#declare A = array[2];\n#declare B = A[5];").find("t.pov:2:16: array index"),
            std::string::npos);
}

TEST(PovInterpreter, StringFunctions) {
  EXPECT_EQ(debug_of(R"(#debug concat(substr("raycast",4,4), strupr("ab"), strlwr("CD"), chr(65),
str(asc("a"),0,0), str(strlen("four"),0,0), str(val("2.5"),0,1), str(strcmp("a","b"),0,0)))"),
            "castABcdA9742.5-1");
}

TEST(PovInterpreter, FloatFunctionsAndConstants) {
  EXPECT_EQ(debug_of(R"(#debug concat(str(mod(-7,3),0,0), " ", str(int(-2.5),0,0), " ",
str(select(-1,10,20),0,0), str(select(0,1,2,3),0,0), " ", str(bitwise_and(6,3),0,0), " ",
str(vlength(<3,4,0>),0,0), " ", vstr(3, vcross(x,y), ",", 0, 0), " ", str(degrees(pi),0,0),
" ", vstr(3, vrotate(x, <0,0,90>), ",", 0, 0), " ", str(defined(Nope),0,0)))"),
            "-1 -2 102 2 5 0,0,1 180 0,1,0 0");
}

TEST(PovInterpreter, UserFunctionsAndSplines) {
  EXPECT_EQ(debug_of(R"(#declare F = function(a, b) { a * a + b }
#declare G = function { F(x, y) * 2 }
#declare S = spline { linear_spline 0, <0,0,0>, 1, <2,4,6> }
#debug concat(str(F(3,1),0,0), " ", str(G(1,2,0),0,0), " ", vstr(3, S(0.5), ",", 0, 0)))"),
            "10 6 1,2,3");
}

TEST(PovInterpreter, IncludeLocalsDoNotLeak) {
  // scenes/locals.inc: #local Hidden = 1; #declare Shown = 2;
  EXPECT_EQ(debug_of("#include \"locals.inc\"\n#ifdef (Hidden) #debug \"leak\" #end "
                     "#debug str(Shown,0,0)"),
            "2");
}

TEST(PovInterpreter, ErrorsNameFileLineAndColumn) {
  EXPECT_EQ(error_of("sphere { 0, 1 }\n  #declare X = Y + 1;"),
            "t.pov:2:16: unknown word 'Y' (not #declared, and not a keyword of an expression)");
  EXPECT_EQ(error_of("#if (1)\n#debug \"x\""),
            "t.pov:1:1: this directive is never closed by #end (the file ends first)");
  EXPECT_EQ(error_of("\n#error \"stop here\""), "t.pov:2:1: #error: stop here");
  EXPECT_EQ(error_of("#include \"nowhere.inc\"").rfind("t.pov:1:1: cannot open #include file", 0),
            0u)
      << error_of("#include \"nowhere.inc\"");
}

TEST(PovInterpreter, UnsupportedIsOneWarningPerKindOrAnErrorWhenStrict) {
  const std::string text =
      "sphere { 0, 1 pigment { mandel 25 } }\nsphere { 0, 1 pigment { mandel 9 } }";
  Options o;
  o.system_library_path = false;
  const PovScene s = interpret_pov(text, "t.pov", ".", o);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(
      s.warnings[0].rfind("t.pov:1:25: warning: raycast does not render the mandel pattern", 0), 0u)
      << s.warnings[0];
  EXPECT_EQ(s.objects.size(), 2u);
  o.strict = true;
  EXPECT_EQ(error_of(text, o).rfind("t.pov:1:25: raycast does not render the mandel pattern", 0),
            0u);
}

TEST(PovInterpreter, DeclaresFromTheCommandLine) {
  Options o;
  o.declares = {{"Quality", "3"}, {"Name", "abc"}};
  EXPECT_EQ(debug_of("#debug concat(str(Quality,0,0), Name)", o), "3abc");
}

TEST(PovInterpreter, LocalOfAMacrosValueLandsInTheCallersScope) {
  // transforms.inc's idiom: #local M = Macro(...) with the value as the macro's body.
  EXPECT_EQ(debug_of("#macro Val(A) A * 2 #end\n#macro User() #local M = Val(3) #debug "
                     "str(M,0,0) #end\nUser()"),
            "6");
}

TEST(PovInterpreter, ForgivenSyntax) {
  // Commas left out, a trailing comma, a stray '#', `declare` without '#'.
  EXPECT_EQ(debug_of("#declare V = <1 2 3,>;\n#declare A = array[2] { 4 5 }\n#\n"
                     "declare B = 7;\n#macro M(P Q) P + Q #end\n"
                     "#debug concat(vstr(3,V,\",\",0,0), str(A[1],0,0), str(B,0,0), "
                     "str(M(1 2),0,0))"),
            "1,2,3573");
}

TEST(PovInterpreter, ObjectsFromArrayElements) {
  Options o;
  o.system_library_path = false;
  const PovScene s = interpret_pov(
      "#declare Arr = array[2] { sphere { 0, 1 }, box { -1, 1 } }\nobject { Arr[1] translate x }",
      "t.pov", ".", o);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].kind, Node::Box);
  ASSERT_EQ(s.objects[0].xforms.size(), 1u);
}

}  // namespace
}  // namespace raycast::pov

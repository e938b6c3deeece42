// The POV-Ray lexer: tokens with their positions, comments, and positioned errors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pov/lexer.h"

namespace raycast::pov {
namespace {

std::vector<Token> lex(const std::string& text) {
  Sources s;
  s.names = {"t.pov"};
  Lexer lexer(text, 0, s);
  std::vector<Token> out;
  for (;;) {
    out.push_back(lexer.next());
    if (out.back().kind == Token::End) return out;
  }
}

std::string lex_error(const std::string& text) {
  try {
    lex(text);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(PovLexer, TokensCarryLineAndColumn) {
  const auto t = lex("sphere {\n  <1, .5, 2e-1> // comment\n /* a\n /* nested */ b */ #declare");
  ASSERT_EQ(t.size(), 11u);
  EXPECT_EQ(t[0].kind, Token::Word);
  EXPECT_EQ(t[0].text, "sphere");
  EXPECT_EQ(t[1].text, "{");
  EXPECT_EQ(t[2].text, "<");
  EXPECT_EQ(t[2].pos.line, 2);
  EXPECT_EQ(t[2].pos.column, 3);
  EXPECT_EQ(t[3].kind, Token::Number);
  EXPECT_EQ(t[3].number, 1);
  EXPECT_EQ(t[5].number, 0.5);
  EXPECT_EQ(t[5].pos.column, 7);
  EXPECT_DOUBLE_EQ(t[7].number, 0.2);
  EXPECT_EQ(t[9].kind, Token::Directive);
  EXPECT_EQ(t[9].text, "declare");
  EXPECT_EQ(t[9].pos.line, 4);
  EXPECT_EQ(t[9].pos.column, 20);
  EXPECT_EQ(t[10].kind, Token::End);
}

TEST(PovLexer, StringsAndSymbols) {
  const auto t = lex("#include \"a b.inc\" x*-3");
  EXPECT_EQ(t[1].kind, Token::String);
  EXPECT_EQ(t[1].text, "a b.inc");
  EXPECT_EQ(t[3].text, "*");
  EXPECT_EQ(t[4].text, "-");
}

TEST(PovLexer, UnterminatedCommentIsReportedWhereItOpens) {
  EXPECT_EQ(lex_error("sphere\n  /* never /* closed */"),
            "t.pov:2:3: unterminated comment: '/*' is never closed");
}

TEST(PovLexer, UnterminatedString) {
  EXPECT_EQ(lex_error("#include \"abc\nsphere"),
            "t.pov:1:10: unterminated string: '\"' is never closed on its line");
}

TEST(PovLexer, MalformedNumbers) {
  EXPECT_EQ(lex_error("x 1e"), "t.pov:1:3: malformed number '1e': the exponent has no digits");
  EXPECT_EQ(lex_error("1.5.2"), "t.pov:1:1: malformed number '1.5.'");
  EXPECT_EQ(lex_error("  12abc"), "t.pov:1:3: malformed number '12a'");
}

TEST(PovLexer, OutOfRangeNumbersAreRejected) {
  EXPECT_EQ(lex_error("\n 1e999"),
            "t.pov:2:2: number '1e999' is out of range (not a finite double)");
}

TEST(PovLexer, StrayCharacters) {
  EXPECT_EQ(lex_error("sphere @"), "t.pov:1:8: unexpected character '@'");
  EXPECT_EQ(lex_error("a\x01"), "t.pov:1:2: unexpected character '\\x01'");
}

TEST(PovLexer, CommentNestingIsBounded) {
  std::string deep;
  for (int i = 0; i < 300; ++i) deep += "/*";
  EXPECT_NE(lex_error(deep).find("comments are nested deeper than 256"), std::string::npos);
}

}  // namespace
}  // namespace raycast::pov

#include <gtest/gtest.h>

#include <string>

#include "io/scene_error.h"
#include "load/loader.h"
#include "load/yaml_prescan.h"

namespace raycast {
namespace {

YamlDocument parse(const std::string& text) { return parse_yaml(text, "t.yaml", kMaxNesting); }

// The SceneError of parsing `text`, which must fail.
SceneError parse_error(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return SceneError("", 0, 0, "");
}

TEST(YamlDocument, NodesKeepTypesTextAndZeroBasedPositions) {
  const YamlDocument doc = parse("a: 1\nb: [x, 'y', \"z\"]\nc: {d: e}\n");
  const YamlNode root = doc.root();
  ASSERT_TRUE(root.IsMap());
  EXPECT_EQ(root.size(), 3u);
  EXPECT_EQ(root["a"].Scalar(), "1");
  EXPECT_EQ(root["a"].Mark().line, 0);
  EXPECT_EQ(root["a"].Mark().column, 3);
  const YamlNode b = root["b"];
  ASSERT_TRUE(b.IsSequence());
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[1].Scalar(), "y");
  EXPECT_FALSE(b[0].IsQuoted());
  EXPECT_TRUE(b[1].IsQuoted());
  EXPECT_EQ(b[2].Mark().column, 12);  // at the quote
  EXPECT_EQ(root["c"]["d"].Scalar(), "e");
  EXPECT_EQ(root["c"].Mark().line, 2);
  // Absent keys and indexes, and lookups into scalars, are undefined, not errors.
  EXPECT_FALSE(root["zz"].IsDefined());
  EXPECT_FALSE(b[3].IsDefined());
  EXPECT_FALSE(root["a"]["x"].IsDefined());
  EXPECT_EQ(root["a"].size(), 0u);
  int count = 0;
  for (const YamlNode entry : b) count += entry.IsScalar();
  EXPECT_EQ(count, 3);
}

TEST(YamlDocument, NullIsThePlainUntaggedSpellings) {
  const YamlDocument doc = parse("[~, null, Null, NULL, '', 'null', !!str null, nil]\n");
  const YamlNode l = doc.root();
  ASSERT_EQ(l.size(), 8u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_TRUE(l[i].IsNull()) << i;
  for (std::size_t i = 4; i < 8; ++i) EXPECT_TRUE(l[i].IsScalar()) << i;
  EXPECT_TRUE(parse("a:\n").root()["a"].IsNull());
  EXPECT_TRUE(parse("").root().IsNull());
  EXPECT_TRUE(parse("# a comment only\n").root().IsNull());
}

TEST(YamlDocument, ScalarsAreTheirTextAfterFoldingAndEscapes) {
  const YamlDocument doc = parse("a: \"x\\ty\\u00e9\"\nb: |\n  one\n  two\nc: p\n  q\n");
  EXPECT_EQ(doc.root()["a"].Scalar(), "x\ty\xC3\xA9");
  EXPECT_EQ(doc.root()["b"].Scalar(), "one\ntwo\n");
  EXPECT_EQ(doc.root()["c"].Scalar(), "p q");
}

TEST(YamlDocument, AliasesShareTheAnchoredNode) {
  const YamlDocument doc = parse("a: &x {r: 1}\nb: *x\nc: &s 5\nd: *s\n");
  EXPECT_EQ(doc.root()["b"]["r"].Scalar(), "1");
  EXPECT_EQ(doc.root()["b"].data(), doc.root()["a"].data());
  EXPECT_EQ(doc.root()["d"].Scalar(), "5");
  const SceneError e = parse_error("a: *nope\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 4);
  EXPECT_EQ(e.message(), "the referenced anchor is not defined");
}

TEST(YamlDocument, AnAliasInsideItsOwnAnchorIsUndefined_NoCycle) {
  const SceneError e = parse_error("a: &x [1, *x]\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 11);
  EXPECT_EQ(e.message(), "the referenced anchor is not defined");
}

TEST(YamlDocument, OnlyTheFirstDocumentIsRead) {
  const YamlDocument doc = parse("a: 1\n---\nb: [\n");
  EXPECT_EQ(doc.root()["a"].Scalar(), "1");
  EXPECT_FALSE(doc.root()["b"].IsDefined());
}

TEST(YamlDocument, ColumnsCountBytes) {
  // "é" is two bytes: the values after it start one byte later than their character count.
  const YamlDocument doc = parse("[\"\xC3\xA9\", ab, cd]\n");
  EXPECT_EQ(doc.root()[1].Mark().column, 7);
  EXPECT_EQ(doc.root()[2].Mark().column, 11);
  EXPECT_EQ(doc.root()[2].Scalar(), "cd");
}

TEST(YamlDocument, InvalidUtf8AndControlCharactersReadAsReplacementCharacters) {
  const YamlDocument doc = parse("a: x\xFFy\nb: \"p\x01q\"\n");
  EXPECT_EQ(doc.root()["a"].Scalar(), "x\xEF\xBF\xBDy");
  EXPECT_EQ(doc.root()["b"].Scalar(), "p\xEF\xBF\xBDq");
}

TEST(YamlDocument, SyntaxErrorsArePositioned) {
  SceneError e = parse_error("a: [1, 2\nb: 3\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 4);
  EXPECT_EQ(e.message().rfind("this '[' is never closed (end of sequence flow not found at ", 0),
            0u)
      << e.message();
  e = parse_error("a: {b: 1}}\n");
  EXPECT_EQ(e.line(), 1);
  EXPECT_EQ(e.column(), 10);
  EXPECT_EQ(e.message(), "illegal flow end");
  e = parse_error("a: 1\n b: 2\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.message(), "mapping values are not allowed in this context");
  e = parse_error("a: \"b\n");
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.message(), "found unexpected end of stream (while scanning a quoted scalar)");
}

TEST(YamlDocument, JsonIsRead) {
  const YamlDocument doc = parse(R"({"objects":[{"sphere":{"radius":2,"center":[1,2,3]}}]})");
  EXPECT_EQ(doc.root()["objects"][0]["sphere"]["center"][2].Scalar(), "3");
}

TEST(YamlDocument, DocumentOutlivesItsSourceText) {
  std::string text = "a: [x, y]\n";
  YamlDocument doc = parse(text);
  text.assign(text.size(), '#');
  EXPECT_EQ(doc.root()["a"][1].Scalar(), "y");
  const YamlDocument moved = std::move(doc);
  EXPECT_EQ(moved.root()["a"][0].Scalar(), "x");
}

TEST(YamlDocument, LargeScenesLoadWithTheirPositions) {
  // Big enough that the arena takes huge-page blocks: the values and positions stay exact.
  std::string text = "objects:\n";
  for (int i = 0; i < 20000; ++i)
    text += "  - {sphere: {center: [" + std::to_string(i) + ", 0, 0], radius: 0.5}}\n";
  text += "  - {sphere: {center: [0, 0, 0], radius: -1}}\n";
  try {
    load_scene_text(text, "big.yaml");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 20002);
    EXPECT_EQ(e.column(), 42);
    EXPECT_EQ(e.message(), "sphere.radius must be > 0, got -1");
  }
  text.resize(text.rfind("  - {sphere: {center: [0, 0, 0], radius: -1}}\n"));
  const Scene s = load_scene_text(text, "big.yaml");
  ASSERT_EQ(s.objects.size(), 20000u);
  EXPECT_EQ(std::get<Sphere>(s.objects[19999].shape).center, Vec3(19999, 0, 0));
  EXPECT_EQ(s.marks.entries[19999].line, 20001);
  EXPECT_EQ(s.marks.entries[19999].column, 5);
}

TEST(YamlDocument, NullKeysReadAsNullInMaterialNames) {
  // yaml-cpp's reading, which scenes were first written against.
  const Scene s = load_scene_text(
      "materials:\n  ~: {diffuse: 0.5}\nobjects:\n  - {sphere: {radius: 1}, "
      "material: 'null'}\n");
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[1].name, "null");
  EXPECT_EQ(s.objects[0].material, 1);
}

}  // namespace
}  // namespace raycast

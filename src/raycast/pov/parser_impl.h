#pragma once
// The POV-Ray parser's state and its methods, shared by parser.cpp (tokens, directives,
// expressions, textures, camera, lights) and parse_objects.cpp (shapes and CSG).
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pov/lexer.h"
#include "pov/parser.h"

namespace raycast::pov {

/// A float (dims 1) or a vector of 2 to 5 components (colours are 5: rgb, filter, transmit).
struct Val {
  int dims = 1;
  std::array<double, 5> v{};
};

/// What a #declare'd name holds.
struct Declared {
  enum Kind { Value, Object, TextureKind, PigmentKind, FinishKind, InteriorKind } kind = Value;
  Val val;
  bool colour = false;  // a Value declared as a colour (rgb...)
  std::shared_ptr<const Node> node;
  Texture texture;  // TextureKind (material too: the texture with its interior's ior)
  Pigment pigment;
  Finish finish;
  std::optional<double> ior;
};

class Parser {
 public:
  Parser(const std::string& text, const std::string& name, const std::string& dir);
  PovScene run();

  // Tokens.
  const Token& tok() const { return cur_; }
  void next();
  bool is_word(const char* w) const { return cur_.kind == Token::Word && cur_.text == w; }
  bool is_symbol(char c) const {
    return cur_.kind == Token::Symbol && cur_.text.size() == 1 && cur_.text[0] == c;
  }
  bool accept_symbol(char c);
  void expect_symbol(char c, const char* where);
  void skip_comma() { accept_symbol(','); }
  [[noreturn]] void fail_here(const std::string& message) const;
  [[noreturn]] void fail_at(const Pos& p, const std::string& message) const;
  [[noreturn]] void unexpected(const char* expected) const;
  std::string describe(const Token& t) const;

  // Expressions.
  Val expression(int depth = 0);
  double number(const char* what);
  Vec3 vector(const char* what);
  Colour colour(const char* what);
  bool starts_colour() const;
  bool boolean_option();

  // Directives; true when one was handled.
  bool directive();

  // Textures.
  Texture texture_block(const Texture& base, int depth);
  Pigment pigment_block(const Pigment& base);
  Finish finish_block(const Finish& base);
  std::optional<double> interior_block();
  Texture material_block(const Texture& base, int depth);
  void reflection_block(Finish& f);

  // Scene items.
  void camera_block();
  void light_block();
  void global_settings_block();

  // Objects (parse_objects.cpp).
  bool is_object_keyword() const;
  Node object(int depth);
  void object_body(Node& n, int depth);
  bool modifier(Node& n, int depth);
  void poly_coefficients(Node& n, int order);
  std::shared_ptr<const FnNode> function_expression(int depth);
  void isosurface_body(Node& n, int depth);
  void spline_points(Node& n, int min_count);
  void mesh_body(Node& n, int depth);
  void mesh2_body(Node& n, int depth);
  long count(const char* what);

  /// Counts what objects hold (each node, point, vertex, triangle, term) against
  /// kMaxPovWeight, so that declared objects used within each other cannot grow exponentially.
  void add_weight(std::size_t w, const Pos& at);

  PovScene scene_;
  std::size_t weight_ = 0;
  std::map<std::string, Declared> symbols_;
  Texture default_texture_;

 private:
  struct OpenFile {
    std::string text;
    std::string dir;
    std::unique_ptr<Lexer> lexer;
  };
  void open(std::string text, const std::string& name, const std::string& path,
            const std::string& dir);
  void include_file(const Pos& at);
  // Macros (#macro Name(params) ... #end): the body's tokens, replayed with each parameter
  // replaced by its argument's tokens.
  struct Macro {
    std::vector<std::string> params;
    std::vector<Token> body;
  };
  struct Replay {
    std::vector<Token> tokens;
    std::size_t at = 0;
  };
  Token raw_next();
  void define_macro(const Pos& at);
  void expand_macro();
  std::map<std::string, Macro> macros_;
  std::vector<Replay> replay_;  // macro expansions being read, innermost last
  std::size_t expanded_ = 0;    // tokens replayed in all
  void declare(bool local);
  void default_block();

  std::vector<std::unique_ptr<OpenFile>> files_;  // the include stack, innermost last
  Token cur_;
};

}  // namespace raycast::pov

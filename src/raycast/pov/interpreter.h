#pragma once
// The POV-Ray scene language's interpreter (docs/pov-import.md): a token stream in which
// directives run as they are met (POV-Ray allows them mid-statement), symbol tables with
// POV-Ray's scoping, expressions over every value type, and the statements that build the
// scene description (pov_scene.h). Split over several files by topic:
//   stream.cpp      tokens, includes, the directive dispatch, conditionals and loops
//   macros.cpp      #macro definitions and calls, arguments by reference
//   symbols.cpp     scopes, #declare / #local / #undef, rvalues of every kind
//   expression.cpp  operators, vectors, colours, postfix access
//   builtins.cpp    built-in constants and functions
//   files.cpp       #debug / #warning / #error / #fopen / #read / #write
//   parse_textures.cpp, parse_settings.cpp, parse_objects.cpp  the statements
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "pov/lexer.h"
#include "pov/options.h"
#include "pov/value.h"

namespace raycast::pov {

/// One symbol: a value, or (a macro's by-reference parameter) the caller's symbol it stands for.
struct Symbol {
  Value value;
  Symbol* ref = nullptr;
};

class Interpreter {
  friend class FunctionParser;  // functions.cpp: reads `function { }` bodies from the tokens

 public:
  /// One level of nesting (an expression, a parenthesis, a unary operator, a directive, an
  /// object), undone on every exit, throws included. Each costs the evaluator stack frames, so the
  /// levels are bounded (kMaxPovExpressionNesting) well inside the stack; past it, a positioned
  /// error.
  class NestingLevel {
   public:
    explicit NestingLevel(Interpreter& in);
    ~NestingLevel();
    NestingLevel(const NestingLevel&) = delete;
    NestingLevel& operator=(const NestingLevel&) = delete;

   private:
    Interpreter& in_;
  };

  Interpreter(const std::string& text, const std::string& name, const std::string& dir,
              const Options& options);
  /// Runs the whole scene; throws SceneError with the position of the first error.
  PovScene run();

  // ---- the token stream (stream.cpp) ----
  /// The current token (directives and macro calls before it have run).
  const Token& tok();
  /// Consumes the current token (the next one is read when asked for).
  void next() { have_ = false; }
  // Words and symbols are compared as string views: a literal's length is known where it is
  // written, and most comparisons fail on it without reading a character.
  bool is_word(std::string_view w) {
    return tok().kind == Token::Word && std::string_view(tok().text) == w;
  }
  bool is_symbol(std::string_view s) { return pov::is_symbol(tok(), s); }
  bool accept_symbol(std::string_view s);
  void expect_symbol(const char* s, const char* where);
  void skip_comma() { accept_symbol(","); }
  /// The current token when it continues an expression: a directive or macro call that ends
  /// a statement is left for the statement level (so loops do not nest the C++ stack).
  const Token& peek_operator();
  [[noreturn]] void fail_here(const std::string& message);
  [[noreturn]] void fail_at(const Pos& p, const std::string& message) const;
  [[noreturn]] void unexpected(const std::string& expected);
  std::string describe(const Token& t) const;
  /// One warning per kind for what raycast reads but does not render; an error with --strict.
  void unsupported_warning(const Pos& at, const std::string& kind, const std::string& detail = "");
  /// Consumes a `{ ... }` block (directives inside still run).
  void skip_block(const std::string& what);
  /// The rest of a block whose `{` was read, braces balanced, up to and with its `}`.
  void skip_block_rest(const std::string& what);

  // ---- expressions (expression.cpp, builtins.cpp) ----
  Value expression();
  double number(const char* what);
  /// A float inside `< >` lists (matrix, poly coefficients): a bare '>' ends it.
  double number_in_vector(const char* what);
  Vec3 vector(const char* what);
  Colour colour(const char* what);
  std::string string_value(const char* what);
  bool boolean_option();
  bool starts_colour();
  /// Whether the next token starts a float or vector expression (not a colour keyword).
  bool numeric_ahead();
  /// A declared value of `kind` at the current token (a name, or an array element), consumed.
  std::optional<Value> declared(Value::Kind kind);
  /// The values after a pattern's keyword (a number, a vector, a block ...).
  void pattern_arguments(const Token& t, bool colours);
  Value builtin(const Token& name);
  // builtin()'s parts: the functions by their argument types.
  Value call_builtin(const Token& t, const std::vector<Value>& a, const std::vector<Pos>& at);
  /// A function's argument as a 3-vector (a float promoted to all three components).
  Vec3 vector_argument(const std::string& function, const Value& v, const Pos& at);
  // trace, inside, min_extent, max_extent (object_functions.cpp): answered by
  // options_.object_queries; `normal_name` is trace's fourth argument.
  Value object_query(const Token& t, const std::vector<Value>& a, const std::vector<Pos>& at,
                     const std::optional<Token>& normal_name);
  Value float_builtin(const Token& t, double x, const Pos& at0);
  Value vector_string_builtin(const Token& t, const std::vector<Value>& a,
                              const std::vector<Pos>& at);
  /// A built-in float constant (clock, image_width ...) for function bodies.
  Value builtin_constant(const Token& name);
  Value primary(int vector_depth);
  Value sub_expression(int vector_depth);
  /// An expression read as a block's item (no comparisons outside parentheses).
  Value item_expression();
  Value vector_literal(const Pos& at);
  Value colour_keyword(const Token& kw);
  Value colour_expression(const Pos& at);
  /// Applies `red 1 filter 0.5 ...` after a colour.
  Value colour_modifiers(Value c);
  Value postfix(Value v);
  /// Calls a function or spline value with the arguments in ( ).
  Value call_value(const Value& f, const Token& name);
  bool pending_now() const;
  Pos tok_pos();
  bool is_builtin(const std::string& w) const;

  // ---- symbols (symbols.cpp) ----
  Symbol* find_symbol(const std::string& name);
  const Value* lookup(const std::string& name);
  /// Reads a value of any kind: an expression, a string, or a block (object, texture ...).
  Value rvalue();
  // `local_scope`: the index in scopes_ a #local writes to (default: the innermost).
  void assign(const std::string& name, Value v, bool local, const Pos& at,
              std::size_t local_scope = static_cast<std::size_t>(-1));

  // ---- statements ----
  Texture texture_block(const Texture& base, int depth);
  /// A texture's items up to `close` ("}" for a block, "]" for a texture map entry).
  Texture texture_body(const Texture& base, int depth, const char* close);
  /// texture_map { [v TEXTURE_ITEMS] ... } into `map`, sorted by value.
  void texture_map_block(const Texture& base, int depth, TextureMap& map);
  /// The first texture of a block holding textures among other items (material_map).
  std::optional<Texture> first_texture_in_block(const Texture& base, int depth,
                                                const std::string& what);
  Pigment pigment_block(const Pigment& base);
  /// A pigment's items up to `close` ("}" for a block, "]" for a pigment map entry).
  Pigment pigment_body(const Pigment& base, const char* close);
  /// One item of a pigment other than a modelled pattern keyword; false when t is none.
  bool pigment_item(const Token& t, Pigment& p, texture::Pigment& model, bool& modelled);
  void skip_pattern_modifier(const std::string& w);
  // ---- patterns in the texture system's terms (parse_patterns.cpp) ----
  /// A pattern keyword's own values (gradient's vector, spiral's arms), keeping the steps and
  /// turbulence already given.
  void start_pattern(texture::PatternKind kind, texture::Pattern& p);
  /// Reads a pattern modifier (turbulence, octaves, waves, frequency, warp ...) named w.
  bool pattern_modifier(const std::string& w, texture::Pattern& p);
  void warp_block(texture::Pattern& p);
  /// Reads to the '}' that closes the block being read (its inner blocks included).
  void skip_warp_rest();
  void skip_entry_rest();
  // An image_map / image_pattern block being read: the image, and what its pixels' final
  // colours wait on (the gamma, alpha, palette indices, filter and transmit items).
  struct ImageMapRead {
    texture::ImageMap image;
    std::vector<float> alpha;
    std::vector<std::uint8_t> index;
    int palette_size = 0;
    double gamma = -1;                                     // -1: not given; 0: srgb
    std::vector<std::pair<int, double>> filter, transmit;  // palette index (-1: all), amount
    bool use_index = false, use_alpha = false, from_function = false;
    double bump_size = 1;  // bump_map's
  };
  // The block after image_map / image_pattern / bump_map (nullptr for a format raycast does not
  // read); a bump_map's bump_size goes to `bump_size`.
  std::shared_ptr<const texture::ImageMap> image_map_block(const std::string& what,
                                                           double* bump_size = nullptr);
  bool image_map_modifier(ImageMapRead& r);
  void image_from_file(ImageMapRead& r, const std::string& name, const Pos& at);
  void image_from_function(ImageMapRead& r, const Pos& at);
  void finish_image(ImageMapRead& r);
  // The function of a `function` pattern: `{ ... }` or a declared function's name.
  std::shared_ptr<const texture::PatternFunction>
  pattern_function_argument();  // the rest of a map entry, through its ']'
  /// A block pattern's colours or pigments (checker, brick, hexagon ...).
  void block_list(texture::Pattern& pattern, texture::Pigment& model, Pigment& p);
  // An entry without a value is weighted 1 in an average's map, else one above the last.
  std::vector<texture::PigmentMapEntry> pigment_map_block(bool weights);
  texture::Normal normal_block(const std::optional<texture::Normal>& base);
  texture::Normal normal_body(const std::optional<texture::Normal>& base, const char* close);
  std::vector<texture::NormalMapEntry> normal_map_block();
  /// Transformations inside a texture: they move its pigment, normal and layers.
  void move_texture(Texture& t, const std::vector<XformOp>& ops);
  void move_pigment(Pigment& p, const std::vector<XformOp>& ops, const Transform& x);
  Finish finish_block(const Finish& base);
  Interior interior_block();
  Texture material_block(const Texture& base, int depth);
  void reflection_block(Finish& f);
  std::vector<MapEntry> colour_map_block();
  std::vector<XformOp> transform_block();
  bool transform_item(std::vector<XformOp>& ops);
  Camera camera_block(const Camera& base);
  // ---- the atmosphere (parse_atmosphere.cpp) ----
  /// sky_sphere { [NAME] pigment { } ... emission C TRANSFORMATIONS }, after the keyword.
  SkySphere sky_sphere_block();
  /// fog { [NAME] fog_type, distance, COLOUR, turbulence ..., fog_offset, fog_alt, up,
  /// TRANSFORMATIONS }, after the keyword.
  Fog fog_block();
  /// rainbow { direction, angle, width, distance, color_map, jitter, up, arc_angle,
  /// falloff_angle }, after the keyword.
  Rainbow rainbow_block();
  bool camera_angle(Camera& c, const Pos& at);
  bool light_number(Light& l, const std::string& w);
  void area_light_item(Light& l);
  void camera_finish(Camera& c, double look_distance, bool angle_given, bool frame_given);
  Node light_block();
  void global_settings_block();
  bool is_object_keyword();
  std::optional<Node> object(int depth);
  void object_body(Node& n, int depth);
  bool modifier(Node& n, int depth);
  void poly_coefficients(Node& n, int order);
  std::shared_ptr<const FnNode> function_expression(int depth,
                                                    const std::vector<std::string>& params);
  Value function_block(const Pos& at);
  Value spline_block(const Pos& at);
  void isosurface_body(Node& n, int depth);
  void spline_points(Node& n, int min_count);
  void prism_body(Node& n);
  void text_body(Node& n);
  void height_field_body(Node& n, int depth);
  void height_field_function(Node& n, const Pos& at);
  void blob_body(Node& n, int depth);
  Node blob_component(int depth);
  void triangle_body(Node& n, bool smooth);
  void place_declared(const std::shared_ptr<const Node>& object, Node& n);
  bool is_declared_object();
  std::optional<Node> bare_declared_object();
  void polynomial_terms(Node& n);
  void mesh_body(Node& n, int depth);
  void mesh2_body(Node& n, int depth);
  long count(const char* what);
  void add_weight(std::size_t w, const Pos& at);

  PovScene scene_;
  Texture default_texture_;
  const Options& options_;

 private:
  struct Input {
    int file = 0;
    Cursor cursor;
  };
  enum class FrameKind { If, While, For, Switch, Macro, Include };
  struct Frame {
    FrameKind kind = FrameKind::If;
    Pos pos;
    std::size_t inputs = 0;  // inputs_.size() when the frame opened
    Cursor loop;             // While: the condition; For: after the header
    std::string variable;    // For: the loop variable
    double end = 0, step = 1;
    std::size_t scopes = 0;                               // Macro: scopes_.size() before the call
    std::vector<std::pair<Symbol*, std::string>> by_ref;  // Macro
  };

  // stream.cpp
  Token raw();
  bool rereading() const;
  void fetch();
  void directive(const Token& d);
  void directive_body(const Token& d);
  void open_file(const std::string& text, const std::string& name, const std::string& path,
                 const std::string& dir);
  void include(const Pos& at);
  std::string find_include(const std::string& name, const Pos& at);
  /// The folders searched for included and data files: the including file's, the scene's, the
  /// library paths.
  std::vector<std::string> library_dirs() const;
  std::optional<std::string> find_on_library_path(const std::string& name) const;
  void close_file();
  /// Skips raw tokens to the #else / #elseif / #end (or, in a switch, #case / #range) of the
  /// construct being skipped; returns that directive (nested constructs are skipped whole).
  Token skip_to(bool stop_at_else, bool stop_at_case);
  void begin_if(const Token& d, bool value);
  void begin_switch(const Token& d);
  void end_directive(const Token& d);
  void begin_while(const Token& d);
  void begin_for(const Token& d);
  void break_directive(const Token& d);
  void count_iteration(const Frame& f);
  Value condition();
  double paren_number(const char* what);
  bool is_defined_test();

  // macros.cpp
  void define_macro(const Token& d);
  void call_macro(const Token& name, const MacroDef& m);
  void end_macro();

  // symbols.cpp
  void declare(const Token& d, bool local);
  void undef();
  void default_block();
  void apply_declares();

  // files.cpp
  void message_directive(const Token& d);
  void fopen_directive();
  void read_directive();
  void write_directive();
  void fclose_directive();

  std::vector<std::shared_ptr<const std::string>> texts_;  // by file index
  std::vector<std::string> dirs_;                          // by file index
  std::vector<Input> inputs_;
  std::vector<Frame> frames_;
  std::vector<std::unordered_map<std::string, Symbol>> scopes_;
  void unread();
  /// The next token without running it as a macro call (a name being declared or tested).
  Token raw_name();
  // Tokens read inside a #while, #for or macro, by file and offset, with the cursor after each:
  // a loop reads its text again at every iteration, and a token depends on nothing but the
  // text and where it starts (texts_ never change). Emptied when it reaches kTokenCacheSize.
  struct CachedToken {
    Token token;
    Cursor after;
  };
  static constexpr std::size_t kTokenCacheSize = std::size_t{1} << 16;
  std::unordered_map<std::uint64_t, CachedToken> token_cache_;
  Token cur_;
  std::size_t cur_input_ = 0;  // the input cur_ was read from, and the cursor before it
  Cursor cur_before_;
  int opaque_ = 0;

 public:
  // > 0 inside parentheses (grouping, a condition, a call's arguments): POV-Ray reads the
  // comparisons (< > <= >= = !=) only there, so a block's `14 <-1, 0, 0>` is a count and a
  // vector, and `#if (C) <1, 0, 0> #else` a condition and a vector.
  int paren_depth_ = 0;
  /// paren_depth_ set for a scope, restored on every exit.
  class ParenDepth {
   public:
    ParenDepth(Interpreter& in, int depth) : in_(in), saved_(in.paren_depth_) {
      in.paren_depth_ = depth;
    }
    ~ParenDepth() { in_.paren_depth_ = saved_; }
    ParenDepth(const ParenDepth&) = delete;
    ParenDepth& operator=(const ParenDepth&) = delete;

   private:
    Interpreter& in_;
    int saved_;
  };

 private:  // > 0: peek_operator runs no directive (a directive's own arguments)
  bool have_ = false;
  bool pending_ = false;  // cur_ is a directive or macro call not yet run (peek_operator)
  long long iterations_ = 0;
  int macro_depth_ = 0;
  int expression_depth_ = 0;  // expressions nested through parentheses, vectors and calls
  std::size_t weight_ = 0;
  long long reads_ = 0;
  std::set<std::string> warned_;
  // While quiet_ > 0 (a declared pigment or pattern function being read), what raycast does not
  // render is noted in quiet_missed_ instead of warned about: the function is then opaque and
  // its calls are warned about where the scene uses them.
  int quiet_ = 0;
  bool quiet_missed_ = false;
  std::vector<std::uint32_t> random_streams_;
  struct OpenFile;
  std::map<std::string, std::shared_ptr<OpenFile>> files_;
};

/// Reads a POV-Ray scene (and the files it includes) to its description.
/// `top` laid over `below` (layered textures): below's layers and below itself under top.
Texture layer_on_top(Texture below, Texture top);
/// Whether w is a pattern keyword (any POV-Ray pattern) or a pattern modifier keyword.
bool is_pattern_word(const std::string& w);
bool is_pattern_modifier_word(const std::string& w);

PovScene interpret_pov(const std::string& text, const std::string& name, const std::string& dir,
                       const Options& options);

/// Limits on nesting in expressions and blocks (the C++ stack).
inline constexpr int kMaxPovNesting = 200;
/// Levels of nesting (expressions, parentheses, unary operators, directives, objects) at most this
/// deep.
inline constexpr int kMaxPovExpressionNesting = 256;
inline constexpr long kMaxPovCount = 100'000'000;  // counts in meshes and point lists
inline constexpr std::size_t kPovNodeWeight = 64;  // an object's weight against scene_weight

}  // namespace raycast::pov

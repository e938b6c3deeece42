#include "pov/interpreter.h"

namespace raycast::pov {

void Interpreter::define_macro(const Token& d) {
  Token name = raw();
  if (name.kind != Token::Word) fail_at(name.pos, "expected a macro name after #macro");
  auto m = std::make_shared<MacroDef>();
  m->name = name.text;
  Token t = raw();
  if (!pov::is_symbol(t, "(")) fail_at(t.pos, "expected '(' after the macro's name");
  t = raw();
  while (!pov::is_symbol(t, ")")) {
    bool optional = false;
    if (t.kind == Token::Word && t.text == "optional") {
      optional = true;
      t = raw();
    }
    if (t.kind != Token::Word) fail_at(t.pos, "expected a parameter name in #macro " + m->name);
    m->params.push_back(t.text);
    m->optional.push_back(optional);
    t = raw();
    if (pov::is_symbol(t, ",")) t = raw();
  }
  m->file = inputs_.back().file;
  m->body_offset = inputs_.back().cursor.offset;
  m->body_line = inputs_.back().cursor.line;
  m->body_column = inputs_.back().cursor.column;
  Frame f;  // for the message if the body never ends
  f.pos = d.pos;
  frames_.push_back(f);
  skip_to(false, false);
  frames_.pop_back();
  Value v;
  v.kind = Value::Macro;
  v.macro = m;
  Symbol& s = scopes_.front()[m->name];
  s.value = std::move(v);
  s.ref = nullptr;
}

void Interpreter::call_macro(const Token& name, const MacroDef& m) {
  if (macro_depth_ >= options_.limits.macro_depth)
    fail_at(name.pos, "macro calls are nested deeper than " +
                          std::to_string(options_.limits.macro_depth) +
                          " (endless recursion?); raise the bound with --pov-max-recursion N");
  const auto keep = scopes_.front().find(m.name);  // the definition stays alive during the call
  const std::shared_ptr<const MacroDef> def =
      keep != scopes_.front().end() ? keep->second.value.macro : nullptr;
  expect_symbol("(", ("after the macro " + m.name).c_str());
  std::optional<ParenDepth> arguments(std::in_place, *this, 1);
  std::unordered_map<std::string, Symbol> locals;
  Frame f;
  f.kind = FrameKind::Macro;
  f.pos = name.pos;
  for (std::size_t i = 0; i < m.params.size(); ++i) {
    const bool last = i + 1 == m.params.size();
    if (is_symbol(")") || is_symbol(",")) {  // an omitted optional argument
      if (!m.optional[i])
        fail_here("the macro " + m.name + " needs an argument for " + m.params[i]);
      if (!last) expect_symbol(",", "between the macro's arguments");
      continue;
    }
    // A lone identifier is passed by reference: assigning the parameter assigns it.
    if (tok().kind == Token::Word && have_ && !pending_) {
      Symbol* target = find_symbol(tok().text);
      if (target && target->value.kind != Value::Macro) {
        const Cursor save = inputs_.back().cursor;
        const std::size_t input = inputs_.size();
        const Token after = raw();
        inputs_.back().cursor = save;
        if (inputs_.size() == input && (pov::is_symbol(after, ",") || pov::is_symbol(after, ")"))) {
          next();
          Symbol& p = locals[m.params[i]];
          p.ref = target;
          if (!last) accept_symbol(",");
          continue;
        }
      }
    }
    locals[m.params[i]].value = rvalue();
    if (!last) accept_symbol(",");  // POV-Ray reads arguments without commas where unambiguous
  }
  arguments.reset();
  if (!is_symbol(")"))
    unexpected("')' to close the call of " + m.name + " (it takes " +
               std::to_string(m.params.size()) + " arguments)");
  next();
  f.scopes = scopes_.size();
  scopes_.push_back(std::move(locals));
  f.inputs = inputs_.size() + 1;
  Input body;
  body.file = m.file;
  body.cursor = {m.body_offset, m.body_line, m.body_column};
  inputs_.push_back(body);
  frames_.push_back(f);
  ++macro_depth_;
  (void)def;
}

void Interpreter::end_macro() {
  const Frame f = frames_.back();
  frames_.pop_back();
  scopes_.resize(f.scopes);
  inputs_.resize(f.inputs - 1);
  --macro_depth_;
}

}  // namespace raycast::pov

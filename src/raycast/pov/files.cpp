// #debug, #warning, #error and the text files of #fopen / #read / #write / #fclose. Files are
// opened relative to the scene's folder; a path that leaves it is refused.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "pov/interpreter.h"

namespace raycast::pov {

struct Interpreter::OpenFile {
  std::fstream stream;
  bool writing = false;
  std::string path;
};

namespace {
std::string where(const Sources& s, const Pos& p) {
  const std::string& n = p.file >= 0 && p.file < static_cast<int>(s.names.size())
                             ? s.names[static_cast<std::size_t>(p.file)]
                             : std::string("<pov>");
  return n + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
}
}  // namespace

void Interpreter::message_directive(const Token& d) {
  ++opaque_;
  const std::string text = string_value(("#" + d.text).c_str());
  --opaque_;
  unread();
  if (d.text == "error") fail_at(d.pos, "#error: " + text);
  if (d.text == "warning") {
    (options_.debug ? *options_.debug : std::cerr)
        << where(scene_.sources, d.pos) << ": warning: " << text << "\n";
    return;
  }
  (options_.debug ? *options_.debug : std::cerr)
      << text;  // #debug prints as written (POV-Ray's debug stream)
}

void Interpreter::fopen_directive() {
  ++opaque_;
  if (tok().kind != Token::Word) unexpected("a file identifier after #fopen");
  const std::string id = tok().text;
  const Pos at = tok().pos;
  next();
  const std::string name = string_value("#fopen");
  if (tok().kind != Token::Word) unexpected("read, write or append");
  const std::string mode = tok().text;
  next();
  --opaque_;
  unread();
  namespace fs = std::filesystem;
  const fs::path base = fs::weakly_canonical(fs::path(dirs_[0]));
  const fs::path path = fs::weakly_canonical(base / name);
  const std::string rel = fs::relative(path, base).string();
  if (rel.empty() || rel.rfind("..", 0) == 0)
    fail_at(at, "#fopen: '" + name + "' is outside the scene's folder (" + base.string() + ")");
  auto f = std::make_shared<OpenFile>();
  f->path = path.string();
  if (mode == "read") {
    f->stream.open(path, std::ios::in);
  } else if ((mode == "write" || mode == "append") && !options_.file_output) {
    fail_at(at, "#fopen: writing files is turned off here");
  } else if (mode == "write" || mode == "append") {
    f->writing = true;
    f->stream.open(
        path, mode == "write" ? std::ios::out | std::ios::trunc : std::ios::out | std::ios::app);
  } else {
    fail_at(at, "#fopen's mode is read, write or append, got '" + mode + "'");
  }
  if (!f->stream) fail_at(at, "#fopen: cannot open '" + path.string() + "'");
  files_[id] = f;
  Value v = Value::string(id);
  assign(id, v, false, at);
}

void Interpreter::fclose_directive() {
  ++opaque_;
  if (tok().kind != Token::Word) unexpected("a file identifier after #fclose");
  files_.erase(tok().text);
  next();
  --opaque_;
}

namespace {
// One value of a #read file: a number, a "string" or a <vector>, then an optional comma.
bool read_item(std::istream& in, Value& out) {
  in >> std::ws;
  const int c = in.peek();
  if (c == EOF) return false;
  if (c == '"') {
    in.get();
    std::string s;
    std::getline(in, s, '"');
    out = Value::string(s);
  } else if (c == '<') {
    in.get();
    std::vector<double> comps;
    for (;;) {
      double d;
      if (!(in >> d)) return false;
      comps.push_back(d);
      in >> std::ws;
      const int n = in.get();
      if (n == '>') break;
      if (n != ',' || comps.size() >= 5) return false;
    }
    out.kind = Value::Vector;
    out.dims = static_cast<int>(comps.size());
    for (std::size_t i = 0; i < comps.size(); ++i) out.v[i] = comps[i];
  } else {
    double d;
    if (!(in >> d)) return false;
    out = Value::number(d);
  }
  in >> std::ws;
  if (in.peek() == ',') in.get();
  return true;
}
}  // namespace

void Interpreter::read_directive() {
  ++opaque_;
  expect_symbol("(", "after #read");
  if (tok().kind != Token::Word) unexpected("a file identifier");
  const auto it = files_.find(tok().text);
  if (it == files_.end() || it->second->writing)
    fail_here("#read: the file is not open for reading");
  next();
  while (accept_symbol(",")) {
    if (tok().kind != Token::Word) unexpected("a name to read into");
    const std::string name = tok().text;
    const Pos at = tok().pos;
    next();
    if (++reads_ > options_.limits.file_reads)
      fail_at(at,
              "#read: more than " + std::to_string(options_.limits.file_reads) + " values read");
    Value v;
    if (read_item(it->second->stream, v)) assign(name, v, false, at);
  }
  if (!is_symbol(")")) unexpected("')' to close #read (");
  next();
  --opaque_;
}

void Interpreter::write_directive() {
  ++opaque_;
  expect_symbol("(", "after #write");
  if (tok().kind != Token::Word) unexpected("a file identifier");
  const auto it = files_.find(tok().text);
  if (it == files_.end() || !it->second->writing)
    fail_here("#write: the file is not open for writing");
  next();
  while (!is_symbol(")")) {
    accept_symbol(",");
    if (is_symbol(")")) break;
    const Value v = expression();
    if (v.kind == Value::String) {
      it->second->stream << v.text;
    } else if (v.kind == Value::Float) {
      it->second->stream << v.v[0];
    } else if (v.kind == Value::Vector) {
      it->second->stream << "<";
      for (int i = 0; i < v.dims; ++i)
        it->second->stream << (i ? "," : "") << v.v[static_cast<std::size_t>(i)];
      it->second->stream << ">";
    }
  }
  if (!is_symbol(")")) unexpected("')' to close #write (");
  next();
  --opaque_;
}

}  // namespace raycast::pov

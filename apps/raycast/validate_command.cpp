// `raycast validate SCENE [--json]`: load and check a scene without rendering (docs/cli.md).
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "load/validate.h"

namespace raycast::cli {
namespace {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

Action add_validate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "validate", "Load and check a scene without rendering (exit 0 clean, 1 warnings, 2 errors)");
  auto scene_path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("SCENE", *scene_path, "Scene file (YAML or JSON)")->required();
  cmd->add_flag("--json", *json, "Print the findings as JSON on standard output");
  return [scene_path, json] {
    const std::vector<Finding> found = validate_scene_file(*scene_path);
    int errors = 0, warnings = 0;
    for (const Finding& f : found) {
      errors += f.severity == Severity::kError;
      warnings += f.severity == Severity::kWarning;
    }
    if (*json) {
      std::printf("{\"scene\": %s, \"errors\": %d, \"warnings\": %d, \"findings\": [",
                  json_string(*scene_path).c_str(), errors, warnings);
      for (std::size_t i = 0; i < found.size(); ++i)
        std::printf(
            "%s\n  {\"severity\": \"%s\", \"file\": %s, \"line\": %d, \"column\": %d, "
            "\"message\": %s}",
            i ? "," : "", severity_name(found[i].severity), json_string(found[i].file).c_str(),
            found[i].line, found[i].column, json_string(found[i].message).c_str());
      std::printf("%s]}\n", found.empty() ? "" : "\n");
    } else {
      for (const Finding& f : found) {
        if (f.line > 0)
          std::printf("%s:%d:%d: %s: %s\n", f.file.c_str(), f.line, f.column,
                      severity_name(f.severity), f.message.c_str());
        else
          std::printf("%s: %s: %s\n", f.file.c_str(), severity_name(f.severity), f.message.c_str());
      }
      std::printf("%s: %d errors, %d warnings\n", scene_path->c_str(), errors, warnings);
    }
    return errors > 0 ? 2 : warnings > 0 ? 1 : 0;
  };
}

}  // namespace raycast::cli

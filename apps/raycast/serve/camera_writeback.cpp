#include "serve/camera_writeback.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/scene_error.h"
#include "load/loader.h"
#include "serve/json_text.h"

namespace raycast::serve {

namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::size_t stop = end == std::string::npos ? text.size() : end + 1;
    lines.push_back(text.substr(start, stop - start));
    start = stop;
  }
  return lines;
}

bool is_blank_or_comment(const std::string& line) {
  const std::size_t i = line.find_first_not_of(" \t\r\n");
  return i == std::string::npos || line[i] == '#';
}

/// A top-level `camera:` key: at column 1, followed by optional spaces and a colon.
bool is_camera_key(const std::string& line) {
  if (line.compare(0, 6, "camera") != 0) return false;
  const std::size_t i = line.find_first_not_of(" \t", 6);
  return i != std::string::npos && line[i] == ':';
}

/// Whether a line continues the block above it: indented, or closing a flow collection.
bool continues_block(const std::string& line) {
  return line[0] == ' ' || line[0] == '\t' || line[0] == '}' || line[0] == ']' || line[0] == ',';
}

void write_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".raycast-tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp);
  }
  std::error_code ec;
  const auto perms = std::filesystem::status(path, ec).permissions();
  if (!ec) std::filesystem::permissions(tmp, perms, ec);
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("cannot replace " + path);
  }
}

bool same_camera(const CameraDesc& a, const CameraDesc& b) {
  return a.type == b.type && a.position == b.position && a.look_at == b.look_at && a.up == b.up &&
         (a.type == CameraType::kPerspective ? a.fov == b.fov : a.height == b.height);
}

}  // namespace

std::string camera_yaml(const CameraDesc& c) {
  std::ostringstream out;
  out << "camera: {type: " << (c.type == CameraType::kOrthographic ? "orthographic" : "perspective")
      << ", position: " << json_vec3(c.position) << ", look_at: " << json_vec3(c.look_at)
      << ", up: " << json_vec3(c.up);
  if (c.type == CameraType::kOrthographic)
    out << ", height: " << json_number(c.height) << "}";
  else
    out << ", fov: " << json_number(c.fov) << "}";
  return out.str();
}

bool replace_camera_block(const std::string& text, const CameraDesc& camera, std::string& out) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && (text[first] == '{' || text[first] == '['))
    return false;  // JSON or a flow-style document: no line-based block to replace
  const std::vector<std::string> lines = split_lines(text);
  std::size_t key = lines.size();
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (is_camera_key(lines[i])) {
      if (key != lines.size()) return false;  // twice: the loader refuses it anyway
      key = i;
    }
  std::ostringstream result;
  if (key == lines.size()) {
    // No camera yet: add one at the end.
    out = text;
    if (!out.empty() && out.back() != '\n') out += '\n';
    out += camera_yaml(camera) + "\n";
    return true;
  }
  // The block runs to the last continuation line before the next column-1 content; blank and
  // comment lines after it belong to what follows.
  std::size_t end = key + 1;
  for (std::size_t j = key + 1; j < lines.size(); ++j) {
    if (is_blank_or_comment(lines[j])) continue;
    if (!continues_block(lines[j])) break;
    end = j + 1;
  }
  const std::string& last = lines[end - 1];
  const bool crlf = last.size() >= 2 && last.compare(last.size() - 2, 2, "\r\n") == 0;
  for (std::size_t i = 0; i < key; ++i) result << lines[i];
  result << camera_yaml(camera) << (crlf ? "\r\n" : "\n");
  for (std::size_t i = end; i < lines.size(); ++i) result << lines[i];
  out = result.str();
  return true;
}

WriteResult write_camera(const std::string& scene_path, const CameraDesc& camera) {
  std::ifstream in(scene_path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + scene_path);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  WriteResult result;
  std::string updated;
  if (!replace_camera_block(text, camera, updated)) {
    result.reason =
        "the scene is JSON or flow-style YAML; its camera block cannot be replaced line by line";
  } else {
    // The new text must load and give exactly this camera, or the file stays as it is.
    const std::string dir = std::filesystem::path(scene_path).parent_path().string();
    try {
      const Scene check = load_scene_text(updated, scene_path, dir.empty() ? "." : dir);
      if (check.camera && same_camera(*check.camera, camera)) {
        write_file(scene_path, updated);
        result.path = scene_path;
        return result;
      }
      result.reason = "the edited scene did not read back with this camera";
    } catch (const SceneError& e) {
      result.reason = std::string("the edited scene did not load: ") + e.what();
    }
  }
  result.sidecar = true;
  result.path = scene_path + ".camera.yaml";
  std::ostringstream sidecar;
  sidecar << "# raycast serve: the camera chosen on the page (" << result.reason
          << "); paste it into " << std::filesystem::path(scene_path).filename().string() << "\n"
          << camera_yaml(camera) << "\n";
  write_file(result.path, sidecar.str());
  return result;
}

}  // namespace raycast::serve

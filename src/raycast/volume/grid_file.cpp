#include "volume/grid_file.h"

#include <yaml-cpp/yaml.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

namespace raycast {

namespace {

[[noreturn]] void fail(const std::string& file, const YAML::Mark& m, const std::string& msg) {
  throw VolumeFileError(file, m.line >= 0 ? m.line + 1 : 1, m.column >= 0 ? m.column + 1 : 1, msg);
}

std::array<double, 3> triple(const std::string& file, const YAML::Node& map, const char* key) {
  const YAML::Node n = map[key];
  if (!n) fail(file, map.Mark(), std::string("the grid sidecar needs \"") + key + "\"");
  if (!n.IsSequence() || n.size() != 3)
    fail(file, n.Mark(), std::string("\"") + key + "\" must be a list of 3 numbers");
  std::array<double, 3> out{};
  for (std::size_t i = 0; i < 3; ++i) {
    const YAML::Node v = n[i];
    double x = 0;
    if (!v.IsScalar() || !YAML::convert<double>::decode(v, x) || !std::isfinite(x))
      fail(file, v.Mark(), std::string("\"") + key + "\" must hold finite numbers");
    out[i] = x;
  }
  return out;
}

}  // namespace

std::string grid_sidecar_path(const std::string& raw_path) {
  std::filesystem::path p(raw_path);
  p.replace_extension(".json");
  return p.string();
}

ScalarGrid read_raw_grid(const std::string& raw_path) {
  const std::string side = grid_sidecar_path(raw_path);
  YAML::Node map;
  {
    std::ifstream f(side);
    if (!f)
      throw VolumeFileError(side, 1, 1,
                            "cannot open the grid's sidecar (needed beside " + raw_path + ")");
    try {
      map = YAML::Load(f);
    } catch (const YAML::Exception& e) {
      fail(side, e.mark, "not valid JSON: " + e.msg);
    }
  }
  if (!map.IsMap()) fail(side, map.Mark(), "the grid sidecar must be a JSON object");
  static const std::set<std::string> kKeys = {"dims", "min", "max", "type"};
  for (const auto& kv : map) {
    const std::string k = kv.first.Scalar();
    if (!kKeys.count(k))
      fail(side, kv.first.Mark(), "unknown key \"" + k + "\" (expected dims, min, max, type)");
  }
  if (map["type"]) {
    const YAML::Node t = map["type"];
    if (!t.IsScalar() || t.Scalar() != "float32")
      fail(side, t.Mark(), "\"type\" must be \"float32\"");
  }
  const std::array<double, 3> dims = triple(side, map, "dims");
  const std::array<double, 3> lo = triple(side, map, "min");
  const std::array<double, 3> hi = triple(side, map, "max");
  std::array<std::uint64_t, 3> n{};
  for (int a = 0; a < 3; ++a) {
    if (!(dims[a] >= 2 && dims[a] == std::floor(dims[a]) && dims[a] < 2e9))
      fail(side, map["dims"][a].Mark(), "\"dims\" must be whole numbers >= 2");
    n[a] = std::uint64_t(dims[a]);
    if (!(lo[a] < hi[a]))
      fail(side, map["max"][a].Mark(), "\"max\" must exceed \"min\" on every axis");
  }
  try {
    check_grid_fits(n);
  } catch (const std::length_error& e) {
    fail(side, map["dims"].Mark(), e.what());
  }
  const std::uint64_t count = n[0] * n[1] * n[2];
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(raw_path, ec);
  if (ec) throw VolumeFileError(raw_path, 1, 1, "cannot open the grid file");
  if (size != count * 4)
    throw VolumeFileError(raw_path, 1, 1,
                          "expected " + std::to_string(count * 4) + " bytes (" +
                              std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " +
                              std::to_string(n[2]) + " float32 values), the file has " +
                              std::to_string(size));
  ScalarGrid g;
  for (int a = 0; a < 3; ++a) {
    g.n[a] = int(n[a]);
    g.lo[a] = lo[a];
    g.cell[a] = (hi[a] - lo[a]) / double(n[a] - 1);
  }
  g.v.resize(count);
  std::ifstream f(raw_path, std::ios::binary);
  if (!f.read(reinterpret_cast<char*>(g.v.data()), std::streamsize(count * 4)))
    throw VolumeFileError(raw_path, 1, 1, "cannot read the grid file");
  // Little-endian on disk: swap on a big-endian host.
  if constexpr (std::endian::native == std::endian::big)
    for (float& v : g.v) {
      std::uint32_t u;
      std::memcpy(&u, &v, 4);
      u = __builtin_bswap32(u);
      std::memcpy(&v, &u, 4);
    }
  for (std::uint64_t i = 0; i < count; ++i)
    if (!std::isfinite(g.v[i]))
      throw VolumeFileError(raw_path, 1, 1,
                            "the value at node (" + std::to_string(i % n[0]) + ", " +
                                std::to_string(i / n[0] % n[1]) + ", " +
                                std::to_string(i / (n[0] * n[1])) + ") (byte " +
                                std::to_string(i * 4) + ") is not finite");
  return g;
}

}  // namespace raycast

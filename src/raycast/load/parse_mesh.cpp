// The `mesh` shape: from a file (OBJ, PLY, STL, glTF/GLB) or inline vertices and triangles.
#include <filesystem>
#include <stdexcept>

#include "io/mesh_file.h"
#include "load/shape_parsers.h"

namespace raycast {

namespace {

std::vector<std::array<std::uint32_t, 3>> read_triangles(const SourceContext& ctx,
                                                         const YamlNode& node) {
  if (!node.IsSequence())
    fail_at(ctx, node, "mesh.triangles must be a list of [i, j, k], got " + describe(node));
  std::vector<std::array<std::uint32_t, 3>> out;
  out.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YamlNode t = node[i];
    if (!t.IsSequence() || t.size() != 3)
      fail_at(ctx, t,
              "mesh.triangles[" + std::to_string(i) + "] must be [i, j, k], got " + describe(t));
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const double v = read_number(ctx, t[k], "mesh.triangles[" + std::to_string(i) + "]");
      if (!(v >= 0 && v < 4294967295.0 && v == static_cast<double>(static_cast<std::uint32_t>(v))))
        fail_at(ctx, t[k],
                "mesh.triangles[" + std::to_string(i) +
                    "] indices must be whole numbers >= 0, got " + describe(t[k]));
      tri[k] = static_cast<std::uint32_t>(v);
    }
    out.push_back(tri);
  }
  return out;
}

std::vector<Vec3f> to_float(const SourceContext& ctx, const YamlNode& node,
                            const std::vector<Vec3>& points, const std::string& what) {
  std::vector<Vec3f> out;
  out.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3f p(points[i]);
    if (!is_finite(p))
      fail_at(ctx, node[i], what + "[" + std::to_string(i) + "] is beyond float range");
    out.push_back(p);
  }
  return out;
}

// File normals are used only when every one is finite and non-zero; otherwise they are ignored
// (and smooth meshes get angle-weighted normals instead).
bool usable(const std::vector<Vec3f>& normals) {
  for (const Vec3f& n : normals)
    if (!is_finite(n) || !(length_squared(Vec3(n)) > 0)) return false;
  return true;
}

}  // namespace

ShapeVariant parse_shape(std::type_identity<MeshShape>, Fields& f) {
  MeshOptions options;
  options.smooth = f.boolean("smooth", false);
  const SourceContext& ctx = f.ctx();
  if (f.has("file")) {
    for (const char* key : {"vertices", "triangles", "normals"})
      if (f.has(key)) f.fail(key, std::string("mesh has both file and ") + key);
    const std::string name = f.string("file");
    const std::filesystem::path p(name);
    const std::string path = p.is_absolute() ? name : (std::filesystem::path(ctx.dir) / p).string();
    if (ctx.files) ctx.files->push_back(path);
    try {
      MeshFileData data = load_mesh_file(path);
      if (!usable(data.normals)) data.normals.clear();
      return MeshShape{make_mesh(std::move(data.soup.positions), std::move(data.soup.triangles),
                                 options.smooth ? std::move(data.normals) : std::vector<Vec3f>{},
                                 options)};
    } catch (const MeshFileError& e) {
      f.fail("file", "mesh.file '" + name + "': " + e.what());
    } catch (const std::invalid_argument& e) {
      f.fail("file", "mesh.file '" + name + "': " + e.what());
    }
  }
  const YamlNode vnode = f.required("vertices");
  std::vector<Vec3f> positions =
      to_float(ctx, vnode, read_points(ctx, vnode, "mesh.vertices"), "mesh.vertices");
  std::vector<std::array<std::uint32_t, 3>> triangles =
      read_triangles(ctx, f.required("triangles"));
  std::vector<Vec3f> normals;
  if (f.has("normals")) {
    const YamlNode nnode = f.required("normals");
    normals = to_float(ctx, nnode, read_points(ctx, nnode, "mesh.normals"), "mesh.normals");
  }
  try {
    return MeshShape{
        make_mesh(std::move(positions), std::move(triangles), std::move(normals), options)};
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    f.fail(m.rfind("normal", 0) == 0 ? "normals"
                                     : (m.rfind("vertex", 0) == 0 ? "vertices" : "triangles"),
           std::string("mesh: ") + m);
  }
}

}  // namespace raycast

#include "pov/pov_transform.h"

namespace raycast::pov {

std::optional<Transform> pov_transform(const std::vector<XformOp>& ops) {
  Transform t;
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const XformOp& x : ops) {
    switch (x.kind) {
      case XformOp::Translate:
        t = Transform::translate(x.v) * t;
        break;
      case XformOp::Scale:
        t = Transform::scale(x.v) * t;  // zero factors were replaced by 1 when read
        break;
      case XformOp::Rotate:
        // About x, then y, then z.
        for (int i = 0; i < 3; ++i)
          if (x.v[std::size_t(i)] != 0) t = Transform::rotate(axes[i], x.v[std::size_t(i)]) * t;
        break;
      case XformOp::Matrix: {
        // POV-Ray's rows act on row vectors: p' = x r0 + y r1 + z r2 + t.
        Mat4 m = Mat4::identity();
        for (std::size_t i = 0; i < 3; ++i) {
          for (std::size_t j = 0; j < 3; ++j) m.m[i][j] = x.m[3 * j + i];
          m.m[i][3] = x.m[9 + i];
        }
        const std::optional<Transform> tm = Transform::from_matrix(m);
        if (!tm) return std::nullopt;
        t = *tm * t;
        break;
      }
    }
  }
  return t;
}

}  // namespace raycast::pov

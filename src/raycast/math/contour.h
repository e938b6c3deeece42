#pragma once
// Closed 2-D contours made of Bezier pieces: what prisms are swept from and what font outlines
// are read into.
#include <array>
#include <vector>

namespace raycast {

/// One piece of a contour: the Bezier curve of the given degree (1 to 3) through its control
/// points p[0..degree]; p[0] is the previous piece's last point.
struct ContourPiece {
  int degree = 1;
  std::array<std::array<double, 2>, 4> p{};
};

/// A closed contour: pieces end to end, the last one ending at the first one's start.
using Contour = std::vector<ContourPiece>;

}  // namespace raycast

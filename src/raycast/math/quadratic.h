#pragma once
// Real roots of a t^2 + b t + c = 0 without catastrophic cancellation.
namespace raycast {

/// Writes the real roots in increasing order to t0 <= t1 and returns their count (0, 1 or 2; a
/// double root is reported twice, as t0 == t1). With a == 0 the linear equation b t + c = 0 is
/// solved (one root, written to both). All-zero or non-finite input gives 0 roots.
/// Uses q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, t = q / a and c / q (Numerical Recipes 5.6).
int solve_quadratic(double a, double b, double c, double& t0, double& t1);

}  // namespace raycast

// SPDX-License-Identifier: MIT
#include "alignment.hpp"

#include <algorithm>
#include <cmath>

namespace swarmpath::sim {

double error_angle(double theta1, double theta2) { return kPi - std::fabs(wrap_angle(theta1 - theta2)); }

Vec2 alignment_target(Vec2 a, Vec2 b, const Params& p) {
  const Vec2 ab = b - a;
  const double len2 = norm2(ab);
  if (len2 == 0.0) return a;
  const double len = std::sqrt(len2);
  // foot of the perpendicular from the origin (the robot)
  double t = std::clamp(dot(-a, ab) / len2, 0.0, 1.0);
  // keep both references in sight: |P - A| = t |AB| <= R_keep and |P - B| = (1 - t) |AB| <= R_keep
  const double t_hi = p.r_keep / len;
  const double t_lo = 1.0 - p.r_keep / len;
  t = t_lo > t_hi ? 0.5 : std::clamp(t, std::max(0.0, t_lo), std::min(1.0, t_hi));
  const Vec2 foot = a + t * ab;
  return (1.0 - p.lambda_mid) * foot + p.lambda_mid * (0.5 * (a + b));
}

bool aligned(double theta1, double theta2, Vec2 target, const Params& p) {
  return error_angle(theta1, theta2) <= deg2rad(p.e_tol) || norm(target) <= p.d_tol;
}

}  // namespace swarmpath::sim

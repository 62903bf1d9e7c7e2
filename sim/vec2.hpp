// SPDX-License-Identifier: MIT
// Plain 2-D vectors and angle functions used throughout the simulator (SI units unless named).
#pragma once

#include <cmath>
#include <numbers>

namespace swarmpath::sim {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2& operator+=(Vec2 o) {
    x += o.x;
    y += o.y;
    return *this;
  }

  constexpr Vec2& operator-=(Vec2 o) {
    x -= o.x;
    y -= o.y;
    return *this;
  }

  constexpr Vec2& operator*=(double k) {
    x *= k;
    y *= k;
    return *this;
  }

  friend constexpr bool operator==(Vec2, Vec2) = default;
};

constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }

constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }

constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }

constexpr Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }

constexpr Vec2 operator*(Vec2 a, double k) { return {k * a.x, k * a.y}; }

constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }

constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

constexpr double norm2(Vec2 a) { return dot(a, a); }

inline double norm(Vec2 a) { return std::sqrt(norm2(a)); }

inline double dist(Vec2 a, Vec2 b) { return norm(a - b); }

inline double angle_of(Vec2 a) { return std::atan2(a.y, a.x); }

/// Unit vector at angle `a` [rad].
inline Vec2 unit(double a) { return {std::cos(a), std::sin(a)}; }

/// Rotate `v` by the rotation whose cosine and sine are (c, s).
constexpr Vec2 rotate(Vec2 v, double c, double s) { return {c * v.x - s * v.y, s * v.x + c * v.y}; }

/// Rotate `v` by the inverse of (c, s): world frame to body frame.
constexpr Vec2 unrotate(Vec2 v, double c, double s) { return {c * v.x + s * v.y, -s * v.x + c * v.y}; }

inline constexpr double kPi = std::numbers::pi;

constexpr double deg2rad(double deg) { return deg * (kPi / 180.0); }

constexpr double rad2deg(double rad) { return rad * (180.0 / kPi); }

/// Wrap an angle into (-pi, pi].
inline double wrap_angle(double a) {
  a = std::remainder(a, 2.0 * kPi);  // [-pi, pi]
  return a <= -kPi ? a + 2.0 * kPi : a;
}

}  // namespace swarmpath::sim

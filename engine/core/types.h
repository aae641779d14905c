// Basic numeric types shared by the whole engine.
//
// All quantities inside the engine are SI: metres, kilograms, seconds, radians, newtons.
// Vectors and matrices have a small fixed upper size so that nothing is heap-allocated in the
// integration loop (an action has at most kMaxDof joint coordinates).
#pragma once

#include <Eigen/Core>
#include <Eigen/Dense>

namespace pat {

/// Most joint coordinates any model may have (grand: 6, plus a few for model extensions).
inline constexpr int kMaxDof = 8;
/// Most first-order states: positions and velocities.
inline constexpr int kMaxState = 2 * kMaxDof;

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

/// Joint-space vector (q, q̇, q̈, generalized forces), at most kMaxDof entries, no heap.
using DofVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDof, 1>;
/// Joint-space matrix (mass matrix, force Jacobians).
using DofMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDof, kMaxDof>;
/// First-order state y = (q, q̇), at most kMaxState entries.
using StateVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxState, 1>;
/// First-order Jacobian ∂f/∂y.
using StateMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxState, kMaxState>;

/// z-component of the planar cross product a × b.
inline double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}
/// ẑ × v: v rotated by +90°.
inline Vec2 perp(const Vec2& v) {
  return Vec2(-v.y(), v.x());
}
/// Rotation of v by angle (rad, counter-clockwise).
inline Vec2 rotate(const Vec2& v, double c, double s) {
  return Vec2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kGravity = 9.81;  // m/s², standard value used throughout
inline double deg(double rad) {
  return rad * 180.0 / kPi;
}
inline double rad(double degrees) {
  return degrees * kPi / 180.0;
}

}  // namespace pat

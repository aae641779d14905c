// sin and cos of one angle from a table and two short polynomials, for the body rotations of the
// dynamics (six per position update, a tenth of a right-hand-side evaluation with the library's
// sincos). History-free: the result depends on the angle only.
//
//   a = k/64 + d,  k = round(64 a),  |d| ≤ 1/128 (exact: d is a difference of nearby doubles)
//   cos a = C_k + (C_k (cos d − 1) − S_k sin d),   sin a = S_k + (S_k (cos d − 1) + C_k sin d)
//   cos d − 1 = −d²/2 + d⁴/24 − d⁶/720  (first omitted term d⁸/8! < 1e-21),
//   sin d = d − d³/6 + d⁵/120 − d⁷/5040  (first omitted term d⁹/9! < 3e-19 d)
//
// C_k, S_k: the library's cos and sin of k/64 (exact arguments), tabulated for |a| ≤ 16 rad;
// larger angles use std::cos and std::sin. Error: about one unit in the last place.
#pragma once

#include <array>
#include <cmath>

namespace pat {

namespace table_sincos_detail {

inline constexpr int kPerRadian = 64;
inline constexpr int kHalfRange = 16 * kPerRadian;  // table entries either side of 0

struct Table {
  std::array<double, 2 * kHalfRange + 1> cos{}, sin{};
  Table() {
    for (int k = -kHalfRange; k <= kHalfRange; ++k) {
      cos[k + kHalfRange] = std::cos(static_cast<double>(k) / kPerRadian);
      sin[k + kHalfRange] = std::sin(static_cast<double>(k) / kPerRadian);
    }
  }
};

inline const Table& table() {
  static const Table instance;
  return instance;
}

}  // namespace table_sincos_detail

/// cos and sin of `angle` (rad).
inline void table_sincos(double angle, double& cos_out, double& sin_out) {
  using namespace table_sincos_detail;
  const double scaled = angle * kPerRadian;
  if (!(std::abs(scaled) <= kHalfRange - 1)) {  // out of the table, or not finite
    cos_out = std::cos(angle);
    sin_out = std::sin(angle);
    return;
  }
  // nearest k (half away from zero: any rounding keeps |d| ≤ 1/128)
  const int k = static_cast<int>(scaled + (scaled >= 0.0 ? 0.5 : -0.5));
  const double d = angle - static_cast<double>(k) / kPerRadian;
  const double d2 = d * d;
  const double cos_d_minus_1 = d2 * (-0.5 + d2 * (1.0 / 24.0 + d2 * (-1.0 / 720.0)));
  const double sin_d = d * (1.0 + d2 * (-1.0 / 6.0 + d2 * (1.0 / 120.0 + d2 * (-1.0 / 5040.0))));
  const Table& t = table();
  const int index = k + kHalfRange;
  const double c = t.cos[index], s = t.sin[index];
  cos_out = c + (c * cos_d_minus_1 - s * sin_d);
  sin_out = s + (s * cos_d_minus_1 + c * sin_d);
}

}  // namespace pat

// Cholesky solve for the small symmetric positive definite systems of the dynamics (n ≤ 8):
// A = L Lᵀ, then L y = b, Lᵀ x = y. Written out because Eigen's generic dynamic-size routines
// cost more than the arithmetic at this size; this runs twice per integration step.
#pragma once

#include <cmath>

#include "core/types.h"

namespace pat {

/// Solves a x = b in place (a is overwritten by L, b by x). Returns false if a is not positive
/// definite.
inline bool cholesky_solve_in_place(DofMatrix& a, DofVector& b) {
  const int n = static_cast<int>(a.rows());
  for (int j = 0; j < n; ++j) {
    double d = a(j, j);
    for (int k = 0; k < j; ++k) d -= a(j, k) * a(j, k);
    if (!(d > 0.0)) return false;
    const double l = std::sqrt(d);
    a(j, j) = l;
    for (int i = j + 1; i < n; ++i) {
      double s = a(i, j);
      for (int k = 0; k < j; ++k) s -= a(i, k) * a(j, k);
      a(i, j) = s / l;
    }
  }
  for (int i = 0; i < n; ++i) {
    double s = b[i];
    for (int k = 0; k < i; ++k) s -= a(i, k) * b[k];
    b[i] = s / a(i, i);
  }
  for (int i = n - 1; i >= 0; --i) {
    double s = b[i];
    for (int k = i + 1; k < n; ++k) s -= a(k, i) * b[k];
    b[i] = s / a(i, i);
  }
  return true;
}

}  // namespace pat

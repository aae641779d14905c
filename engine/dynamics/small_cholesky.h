// Cholesky solve for the small symmetric positive definite systems of the dynamics (n ≤ kMaxDof):
// A = L Lᵀ, then L y = b, Lᵀ x = y. Written out because Eigen's generic dynamic-size routines
// cost more than the arithmetic at this size; this runs at every right-hand-side evaluation.
// The size is a template parameter so that the compiler unrolls the loops; the runtime-size
// entry point dispatches to it.
#pragma once

#include <cmath>

#include "core/types.h"

namespace pat {

/// Fixed-capacity square matrix of the joint space; only the leading n×n block is used. Fixed
/// size so that clearing and copying it are a few vector moves.
using SmallMatrix = Eigen::Matrix<double, kMaxDof, kMaxDof>;
/// Fixed-capacity joint-space vector (leading n entries used).
using SmallVector = Eigen::Matrix<double, kMaxDof, 1>;

/// Solves a x = b for the leading N×N block of a (only the lower triangle is read; it is
/// overwritten by L) and b (overwritten by x). Returns false if a is not positive definite.
template <int N>
inline bool cholesky_solve_fixed(SmallMatrix& a, SmallVector& b) {
  double inverse_diagonal[N];
  for (int j = 0; j < N; ++j) {
    double d = a(j, j);
    for (int k = 0; k < j; ++k) d -= a(j, k) * a(j, k);
    if (!(d > 0.0)) return false;
    inverse_diagonal[j] = 1.0 / std::sqrt(d);
    for (int i = j + 1; i < N; ++i) {
      double s = a(i, j);
      for (int k = 0; k < j; ++k) s -= a(i, k) * a(j, k);
      a(i, j) = s * inverse_diagonal[j];
    }
  }
  for (int i = 0; i < N; ++i) {
    double s = b[i];
    for (int k = 0; k < i; ++k) s -= a(i, k) * b[k];
    b[i] = s * inverse_diagonal[i];
  }
  for (int i = N - 1; i >= 0; --i) {
    double s = b[i];
    for (int k = i + 1; k < N; ++k) s -= a(k, i) * b[k];
    b[i] = s * inverse_diagonal[i];
  }
  return true;
}

/// Runtime-size form of cholesky_solve_fixed, 1 ≤ n ≤ kMaxDof (false otherwise).
inline bool cholesky_solve_in_place(SmallMatrix& a, SmallVector& b, int n) {
  switch (n) {
    case 1:
      return cholesky_solve_fixed<1>(a, b);
    case 2:
      return cholesky_solve_fixed<2>(a, b);
    case 3:
      return cholesky_solve_fixed<3>(a, b);
    case 4:
      return cholesky_solve_fixed<4>(a, b);
    case 5:
      return cholesky_solve_fixed<5>(a, b);
    case 6:
      return cholesky_solve_fixed<6>(a, b);
    case 7:
      return cholesky_solve_fixed<7>(a, b);
    case 8:
      return cholesky_solve_fixed<8>(a, b);
    default:
      return false;
  }
}
static_assert(kMaxDof == 8, "extend cholesky_solve_in_place's dispatch");

}  // namespace pat

// LU factorization with partial (row) pivoting for the small dense systems of the W-method
// (the n×n Schur complement, n ≤ kMaxDof): P A = L U, L unit lower triangular. Fixed capacity and
// plain loops, because Eigen's dynamic-size routines cost more than the arithmetic at this size
// (the solve runs twice per step). Same pivot choice as Eigen::PartialPivLU (largest |entry| in
// the column).
#pragma once

#include <cmath>
#include <utility>

#include "core/types.h"

namespace pat {

class SmallLu {
 public:
  using Matrix = Eigen::Matrix<double, kMaxDof, kMaxDof>;
  using Vector = Eigen::Matrix<double, kMaxDof, 1>;

  /// Factors the leading n×n block of a. Returns false for an exactly singular matrix.
  bool compute(const Matrix& a, int n) {
    switch (n) {
      case 1:
        return compute_fixed<1>(a);
      case 2:
        return compute_fixed<2>(a);
      case 3:
        return compute_fixed<3>(a);
      case 4:
        return compute_fixed<4>(a);
      case 5:
        return compute_fixed<5>(a);
      case 6:
        return compute_fixed<6>(a);
      case 7:
        return compute_fixed<7>(a);
      case 8:
        return compute_fixed<8>(a);
      default:
        n_ = 0;
        return false;
    }
  }

  /// Solves A x = b in place on the first n entries of b.
  void solve_in_place(Vector& b) const {
    switch (n_) {
      case 1:
        return solve_fixed<1>(b);
      case 2:
        return solve_fixed<2>(b);
      case 3:
        return solve_fixed<3>(b);
      case 4:
        return solve_fixed<4>(b);
      case 5:
        return solve_fixed<5>(b);
      case 6:
        return solve_fixed<6>(b);
      case 7:
        return solve_fixed<7>(b);
      case 8:
        return solve_fixed<8>(b);
      default:
        return;
    }
  }

 private:
  /// The factorization for n = N, a compile-time size so that the loops unroll.
  template <int N>
  bool compute_fixed(const Matrix& a) {
    n_ = N;
    lu_ = a;
    for (int k = 0; k < N; ++k) {
      int pivot = k;
      for (int i = k + 1; i < N; ++i)
        if (std::abs(lu_(i, k)) > std::abs(lu_(pivot, k))) pivot = i;
      row_of_[k] = pivot;
      if (pivot != k)
        for (int j = 0; j < N; ++j) std::swap(lu_(k, j), lu_(pivot, j));
      if (lu_(k, k) == 0.0) return false;
      const double inverse = 1.0 / lu_(k, k);
      for (int i = k + 1; i < N; ++i) {
        const double l = lu_(i, k) * inverse;
        lu_(i, k) = l;
        for (int j = k + 1; j < N; ++j) lu_(i, j) -= l * lu_(k, j);
      }
    }
    return true;
  }

  /// The solve for n = N, a compile-time size so that the loops unroll (it runs twice per step).
  template <int N>
  void solve_fixed(Vector& b) const {
    for (int k = 0; k < N; ++k)
      if (row_of_[k] != k) std::swap(b[k], b[row_of_[k]]);
    for (int i = 1; i < N; ++i) {
      double s = b[i];
      for (int k = 0; k < i; ++k) s -= lu_(i, k) * b[k];
      b[i] = s;
    }
    for (int i = N - 1; i >= 0; --i) {
      double s = b[i];
      for (int k = i + 1; k < N; ++k) s -= lu_(i, k) * b[k];
      b[i] = s / lu_(i, i);
    }
  }

  Matrix lu_ = Matrix::Zero();
  int row_of_[kMaxDof] = {};  ///< row swapped with row k at step k
  int n_ = 0;
};

static_assert(kMaxDof == 8, "extend SmallLu::compute's and solve_in_place's dispatch");

}  // namespace pat

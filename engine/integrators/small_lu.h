// LU factorization with partial (row) pivoting for the small dense systems of the W-method
// (the n×n Schur complement, n ≤ kMaxDof): P A = L U, L unit lower triangular. Fixed capacity and
// plain loops, because Eigen's dynamic-size routines cost more than the arithmetic at this size
// (the solve runs twice per step). Same pivot choice as Eigen::PartialPivLU (largest |entry| in
// the column).
#pragma once

#include <cmath>
#include <type_traits>
#include <utility>

#include "core/types.h"

namespace pat {

/// Calls f(std::integral_constant<int, N>{}) with N = n, for 1 ≤ n ≤ kMaxDof (n below 1 is taken
/// as 1, above kMaxDof as kMaxDof: callers check the range), so that loops over n unroll at
/// compile time.
template <int N = 1, class F>
decltype(auto) with_fixed_size(int n, F&& f) {
  if constexpr (N >= kMaxDof) {
    return f(std::integral_constant<int, N>{});
  } else {
    if (n <= N) return f(std::integral_constant<int, N>{});
    return with_fixed_size<N + 1>(n, std::forward<F>(f));
  }
}

class SmallLu {
 public:
  using Matrix = Eigen::Matrix<double, kMaxDof, kMaxDof>;
  using Vector = Eigen::Matrix<double, kMaxDof, 1>;

  /// Factors the leading n×n block of a. Returns false for an exactly singular matrix.
  bool compute(const Matrix& a, int n) {
    if (n < 1 || n > kMaxDof) {
      n_ = 0;
      return false;
    }
    return with_fixed_size(n, [&](auto size) { return compute_fixed<size.value>(a); });
  }

  /// Solves A x = b in place on the first n entries of b.
  void solve_in_place(Vector& b) const {
    if (n_ < 1) return;
    with_fixed_size(n_, [&](auto size) { solve_fixed<size.value>(b); });
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

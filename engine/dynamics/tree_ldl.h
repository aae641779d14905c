// Sparse LᵀDL factorization of the joint-space mass matrix of a kinematic tree (Featherstone,
// "Efficient factorization of the joint-space inertia matrix for branched kinematic trees",
// IJRR 24(6), 2005; Rigid Body Dynamics Algorithms, section 6.2).
//
// With relative joint coordinates, M_ij ≠ 0 only when joint i is an ancestor of joint j or the
// reverse (M_ij sums over the bodies moved by both joints). Numbering parents before children
// (λ(i) < i), the factorization M = Lᵀ D L, L unit lower triangular, keeps that pattern (no fill
// in) and runs from the leaves to the roots:
//
//   for k = n−1 … 0:  for each ancestor i of k:  a = M_ki / M_kk,
//                       M_ij −= a M_kj for every ancestor-or-self j of i,   L_ki = a;   D_k = M_kk
//
// then M x = b is  Lᵀ y = b (leaves to roots), z = D⁻¹ y, L x = z (roots to leaves). For the grand
// action (key, whippen + jack + repetition lever, hammer, damper: four independent chains) that is
// two eliminations and six divisions, against a dense 6×6 Cholesky's 56 multiply-adds, six square
// roots and six divisions. Plain loops over the parent array; only the lower triangle is read.
#pragma once

#include "core/types.h"

namespace pat {

/// Fixed-capacity square matrix of the joint space; only the leading n×n block is used. Fixed
/// size so that clearing and copying it are a few vector moves.
using SmallMatrix = Eigen::Matrix<double, kMaxDof, kMaxDof>;
/// Fixed-capacity joint-space vector (leading n entries used).
using SmallVector = Eigen::Matrix<double, kMaxDof, 1>;

class TreeLdl {
 public:
  /// parent[i] < i for every joint with a parent, −1 for a joint on the frame; n ≤ kMaxDof.
  void set_tree(const int* parent, int n) {
    n_ = n;
    for (int i = 0; i < n; ++i) parent_[i] = parent[i];
  }
  int size() const { return n_; }
  int parent(int i) const { return parent_[i]; }

  /// Factors the tree entries of the lower triangle of m (row ≥ column; entries off the tree's
  /// pattern are not read) in place into L (below the diagonal) and D (on it). False if m is not
  /// positive definite (a pivot D_k ≤ 0).
  bool factor_in_place(SmallMatrix& m) const {
    for (int k = n_ - 1; k >= 0; --k) {
      const double d = m(k, k);
      if (!(d > 0.0)) return false;
      if (parent_[k] < 0) continue;  // a joint on the frame: nothing to eliminate
      const double inverse_d = 1.0 / d;
      for (int i = parent_[k]; i >= 0; i = parent_[i]) {
        const double a = m(k, i) * inverse_d;
        for (int j = i; j >= 0; j = parent_[j]) m(i, j) -= a * m(k, j);
        m(k, i) = a;
      }
    }
    return true;
  }
  /// Solves M x = b in place on b with a factor from factor_in_place.
  void solve(const SmallMatrix& factor, SmallVector& b) const {
    for (int i = n_ - 1; i >= 0; --i)  // Lᵀ y = b
      for (int j = parent_[i]; j >= 0; j = parent_[j]) b[j] -= factor(i, j) * b[i];
    for (int i = 0; i < n_; ++i) b[i] /= factor(i, i);  // z = D⁻¹ y
    for (int i = 0; i < n_; ++i)                        // L x = z
      for (int j = parent_[i]; j >= 0; j = parent_[j]) b[i] -= factor(i, j) * b[j];
  }
  /// solve() on each of the first `columns` columns of b (n rows), in one pass over the tree: the
  /// same operations in the same order for every column, so the same results bit for bit.
  void solve_columns(const SmallMatrix& factor, SmallMatrix& b, int columns) const {
    for (int i = n_ - 1; i >= 0; --i)  // Lᵀ Y = B
      for (int j = parent_[i]; j >= 0; j = parent_[j]) {
        const double l = factor(i, j);
        for (int c = 0; c < columns; ++c) b(j, c) -= l * b(i, c);
      }
    for (int i = 0; i < n_; ++i) {  // Z = D⁻¹ Y
      const double d = factor(i, i);
      for (int c = 0; c < columns; ++c) b(i, c) /= d;
    }
    for (int i = 0; i < n_; ++i)  // L X = Z
      for (int j = parent_[i]; j >= 0; j = parent_[j]) {
        const double l = factor(i, j);
        for (int c = 0; c < columns; ++c) b(i, c) -= l * b(j, c);
      }
  }
  /// factor_in_place, then solve; b is unchanged when m is not positive definite.
  bool solve_in_place(SmallMatrix& m, SmallVector& b) const {
    if (!factor_in_place(m)) return false;
    solve(m, b);
    return true;
  }

 private:
  int n_ = 0;
  int parent_[kMaxDof] = {};
};

}  // namespace pat

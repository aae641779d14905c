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
// roots and six divisions. Plain loops over the list of (joint, ancestor) pairs, precomputed from
// the parent array (a joint on the frame costs only its division); only the lower triangle is read.
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
    // the (joint, ancestor) pairs, joints from the leaves down and each joint's ancestors nearest
    // first (the order of the eliminations and of Lᵀ y = b), then joints from the roots up (the
    // order of L x = z); a joint's pairs are consecutive, from first_pair_
    pair_count_ = 0;
    for (int k = n - 1; k >= 0; --k) {
      first_pair_[k] = pair_count_;
      for (int i = parent[k]; i >= 0; i = parent[i]) {
        joint_of_pair_[pair_count_] = k;
        ancestor_of_pair_[pair_count_++] = i;
      }
      pairs_of_[k] = pair_count_ - first_pair_[k];
    }
    int next = 0;
    for (int k = 0; k < n; ++k)
      for (int p = 0; p < pairs_of_[k]; ++p) rising_pair_[next++] = first_pair_[k] + p;
  }
  int size() const { return n_; }
  int parent(int i) const { return parent_[i]; }

  /// Factors the tree entries of the lower triangle of m (row ≥ column; entries off the tree's
  /// pattern are not read) in place into L (below the diagonal) and D (on it). False if m is not
  /// positive definite (a pivot D_k ≤ 0). The pairs only: a joint without ancestors eliminates
  /// nothing, and its pivot is checked at the end.
  bool factor_in_place(SmallMatrix& m) const {
    for (int p = 0; p < pair_count_;) {
      const int k = joint_of_pair_[p];
      const double d = m(k, k);  // final: k's descendants were eliminated before it
      if (!(d > 0.0)) return false;
      const double inverse_d = 1.0 / d;
      for (const int end = p + pairs_of_[k]; p < end; ++p) {
        const int i = ancestor_of_pair_[p];
        const double a = m(k, i) * inverse_d;
        m(i, i) -= a * m(k, i);
        for (int q = first_pair_[i], q_end = q + pairs_of_[i]; q < q_end; ++q) {
          const int j = ancestor_of_pair_[q];
          m(i, j) -= a * m(k, j);
        }
        m(k, i) = a;
      }
    }
    for (int k = 0; k < n_; ++k)
      if (!(m(k, k) > 0.0)) return false;
    return true;
  }
  /// Solves M x = b in place on b with a factor from factor_in_place.
  void solve(const SmallMatrix& factor, SmallVector& b) const {
    for (int p = 0; p < pair_count_; ++p) {  // Lᵀ y = b
      const int i = joint_of_pair_[p], j = ancestor_of_pair_[p];
      b[j] -= factor(i, j) * b[i];
    }
    for (int i = 0; i < n_; ++i) b[i] /= factor(i, i);  // z = D⁻¹ y
    for (int r = 0; r < pair_count_; ++r) {             // L x = z
      const int p = rising_pair_[r];
      const int i = joint_of_pair_[p], j = ancestor_of_pair_[p];
      b[i] -= factor(i, j) * b[j];
    }
  }
  /// solve() on each of the first `columns` columns of b (n rows), in one pass over the tree: the
  /// same operations in the same order for every column, so the same results bit for bit.
  void solve_columns(const SmallMatrix& factor, SmallMatrix& b, int columns) const {
    for (int p = 0; p < pair_count_; ++p) {  // Lᵀ Y = B
      const int i = joint_of_pair_[p], j = ancestor_of_pair_[p];
      const double l = factor(i, j);
      for (int c = 0; c < columns; ++c) b(j, c) -= l * b(i, c);
    }
    for (int i = 0; i < n_; ++i) {  // Z = D⁻¹ Y
      const double d = factor(i, i);
      for (int c = 0; c < columns; ++c) b(i, c) /= d;
    }
    for (int r = 0; r < pair_count_; ++r) {  // L X = Z
      const int p = rising_pair_[r];
      const int i = joint_of_pair_[p], j = ancestor_of_pair_[p];
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
  static constexpr int kMaxPairs = kMaxDof * (kMaxDof - 1) / 2;  // a chain
  int n_ = 0;
  int parent_[kMaxDof] = {};
  int pair_count_ = 0;
  int joint_of_pair_[kMaxPairs] = {}, ancestor_of_pair_[kMaxPairs] = {};
  int first_pair_[kMaxDof] = {}, pairs_of_[kMaxDof] = {};
  int rising_pair_[kMaxPairs] = {};  ///< pair indices, joints from the roots up
};

}  // namespace pat

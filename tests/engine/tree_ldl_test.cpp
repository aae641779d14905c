// The tree LᵀDL solve of the mass matrix against a dense solve.
#include "dynamics/tree_ldl.h"

#include <gtest/gtest.h>

#include <random>

namespace pat {
namespace {

/// A symmetric positive definite matrix with the sparsity of the tree `parent` (n joints):
/// M = Lᵀ D L with random unit-lower L on the tree pattern and D > 0, which is exactly the class
/// of matrices the factorization handles (a joint-space mass matrix is one).
SmallMatrix tree_matrix(const int* parent, int n, std::mt19937& random) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0), pivot(0.1, 2.0);
  SmallMatrix l = SmallMatrix::Identity(), d = SmallMatrix::Zero();
  for (int k = 0; k < n; ++k) {
    d(k, k) = pivot(random);
    for (int i = parent[k]; i >= 0; i = parent[i]) l(k, i) = entry(random);
  }
  return l.transpose() * d * l;
}

TEST(TreeLdl, SolvesMassMatricesOfBranchedTreesLikeADenseSolve) {
  // the grand's tree (key, whippen with jack and repetition lever, hammer, damper), a chain,
  // independent joints, and a deeper branched tree
  const std::vector<std::vector<int>> trees = {
      {-1, -1, 1, 1, -1, -1}, {-1, 0, 1, 2, 3}, {-1, -1, -1}, {-1, 0, 0, 1, 1, 2, 5, -1}};
  std::mt19937 random(7);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  for (const std::vector<int>& parent : trees) {
    const int n = static_cast<int>(parent.size());
    TreeLdl ldl;
    ldl.set_tree(parent.data(), n);
    for (int trial = 0; trial < 20; ++trial) {
      const SmallMatrix m = tree_matrix(parent.data(), n, random);
      SmallVector b = SmallVector::Zero();
      for (int i = 0; i < n; ++i) b[i] = entry(random);
      const Eigen::VectorXd expected =
          m.topLeftCorner(n, n).ldlt().solve(Eigen::VectorXd(b.head(n)));
      // only the lower triangle is read: poison the upper one
      SmallMatrix work = m;
      for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) work(i, j) = std::nan("");
      ASSERT_TRUE(ldl.solve_in_place(work, b));
      // the pivots are ≥ 0.1 and the entries O(1): the condition number stays below ~1e4, so
      // both solves agree to well within 1e-10
      for (int i = 0; i < n; ++i) EXPECT_NEAR(b[i], expected[i], 1e-10) << "n " << n;
    }
  }
}

TEST(TreeLdl, SolvesSeveralColumnsExactlyLikeOneAtATime) {
  // the grand's tree and a deeper branched one; the velocity Jacobian relies on the batched solve
  // giving the same bits as the column-by-column one (the same operations in the same order)
  const std::vector<std::vector<int>> trees = {{-1, -1, 1, 1, -1, -1}, {-1, 0, 0, 1, 1, 2, 5, -1}};
  std::mt19937 random(11);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  for (const std::vector<int>& parent : trees) {
    const int n = static_cast<int>(parent.size());
    TreeLdl ldl;
    ldl.set_tree(parent.data(), n);
    SmallMatrix factor = tree_matrix(parent.data(), n, random);
    ASSERT_TRUE(ldl.factor_in_place(factor));
    SmallMatrix columns = SmallMatrix::Zero();
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < n; ++c) columns(i, c) = entry(random);
    SmallMatrix batched = columns;
    ldl.solve_columns(factor, batched, n);
    for (int c = 0; c < n; ++c) {
      SmallVector one = columns.col(c);
      ldl.solve(factor, one);
      for (int i = 0; i < n; ++i) EXPECT_EQ(batched(i, c), one[i]) << "n " << n << " column " << c;
    }
  }
}

TEST(TreeLdl, ReportsAMatrixThatIsNotPositiveDefinite) {
  const int parent[] = {-1, 0};
  TreeLdl ldl;
  ldl.set_tree(parent, 2);
  SmallMatrix m = SmallMatrix::Zero();
  m(0, 0) = 1.0;
  m(1, 1) = 1.0;
  m(1, 0) = 2.0;  // det = 1 − 4 < 0
  SmallVector b = SmallVector::Ones();
  EXPECT_FALSE(ldl.solve_in_place(m, b));
}

}  // namespace
}  // namespace pat

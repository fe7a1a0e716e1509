// Direct alternative to the conjugate gradient: sparse Cholesky R = L L^T (Eigen::SimplicialLLT, AMD ordering) of
// the symmetric block matrix. The symbolic analysis (ordering + elimination tree) is kept while the block pattern
// (block rows and link list) is unchanged, and redone otherwise; each call refactorises the values.
// The lower triangle is written straight into a compressed column matrix through a fill plan computed with the
// pattern, so an unchanged pattern costs no index work (Eigen's numeric factorisation allocates internally).
#pragma once
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <vector>

#include "linalg/block_matrix.hpp"

namespace suspend {

class PatternCholesky {
 public:
  // Factorises a; throws NumericalError if it is not positive definite.
  void factorize(const SymmetricBlockMatrix& a);
  // x = R^-1 b with the last factorisation.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  // Number of symbolic analyses so far (one per pattern change).
  int analyses() const { return analyses_; }

 private:
  void build_pattern(const SymmetricBlockMatrix& a);

  // Per block column c, the links of its lower part (blocks (r, c), r > c), sorted by r; rank = position among
  // the distinct r, so two links between the same particles add into the same entries.
  struct LowerBlock {
    std::uint32_t link;
    bool transposed;  // the block (r, c) is coupling(link)^T when the link is (c, r)
    std::uint32_t rank;
  };
  std::size_t pattern_rows_ = 0;
  std::vector<BlockLink> pattern_links_;
  std::vector<std::uint32_t> column_start_;  // into lower_
  std::vector<LowerBlock> lower_;
  std::vector<std::uint32_t> distinct_;  // distinct lower blocks per block column
  Eigen::SparseMatrix<double> matrix_;   // lower triangle, compressed column
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt_;
  int analyses_ = 0;
  bool analysed_ = false;
};

}  // namespace suspend

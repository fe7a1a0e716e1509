// Preconditioned conjugate gradient for the symmetric positive definite resistance matrix (Hestenes & Stiefel 1952;
// Saad, "Iterative Methods for Sparse Linear Systems", 2nd ed., Algorithm 9.1), with the block-Jacobi
// preconditioner M^-1 = diag(D_i^-1) built from the 6x6 diagonal blocks.
//
// Stops when the relative residual |b - A x| / |b| (recurrence residual, Euclidean norm) is <= tolerance, or after
// max_iterations. x holds the initial guess on entry (warm start) and the solution on exit.
// Deterministic: every dot product is summed over fixed chunks of 64 block rows, the chunk sums added in order, so
// the iterates are bit-identical for any number of threads.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "dem/integrate/block_matrix.hpp"

namespace suspend {

struct ConjugateGradientReport {
  int iterations = 0;
  double residual = 0.0;  // |b - A x| / |b| at exit (0 when b = 0)
  bool converged = false;
};

class BlockJacobiConjugateGradient {
 public:
  // Inverts the diagonal blocks of a (Cholesky of each 6x6 block). Throws NumericalError if one is not SPD.
  void set_preconditioner(const SymmetricBlockMatrix& a);
  ConjugateGradientReport solve(const SymmetricBlockMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                double tolerance, int max_iterations);

 private:
  void precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;
  double dot(const Eigen::VectorXd& u, const Eigen::VectorXd& v);

  std::vector<Matrix6> inverse_diagonal_;
  Eigen::VectorXd r_, z_, p_, q_;
  std::vector<double> chunk_sums_;
};

}  // namespace suspend

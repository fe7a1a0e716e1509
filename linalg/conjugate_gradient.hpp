// Preconditioned conjugate gradient for the symmetric positive definite resistance matrix A (Hestenes & Stiefel
// 1952; Saad, "Iterative Methods for Sparse Linear Systems", 2nd ed. (2003), Algorithm 9.1 and section 10.2).
//
// The matrix is first scaled by its diagonal blocks: D_i = L_i L_i^T (Cholesky of each 6x6 block), S = diag(L_i^-1),
// A' = S A S^T = I + N + N^T with unit diagonal blocks and strictly lower block part N; the scaled matrix replaces the
// plain one in place (block_matrix.hpp). CG then solves for the
// correction d to the initial guess x0 (A d = b - A x0), with one of two preconditioners:
//  * block_jacobi: M = D, i.e. plain CG on A'. Every operation is a row gather, parallel over block rows.
//  * symmetric_gauss_seidel (default): M = K D^-1 K^T, K = D + L (block SSOR, omega = 1), applied with Eisenstat's
//    trick (Eisenstat, SIAM J. Sci. Stat. Comput. 2, 1 (1981)): with K' = I + N, CG on K'^-1 A' K'^-T, whose
//    product is t + K'^-1 (v - t), t = K'^-T v: one forward and one backward sweep, the work of one product with A.
//    It roughly halves the iterations of block Jacobi on dense suspensions; the sweeps are sequential.
// Stops when the true relative residual |b - A x| / |b| (Euclidean) is <= tolerance: the recurrence residual is
// only used to decide when to check it. After max_iterations the last iterate is returned, not converged.
// x holds the initial guess on entry (warm start; dropped if its residual exceeds |b|) and the solution on exit.
// Deterministic: dot products are summed over fixed chunks of 64 block rows, the chunk sums added in order, and the
// sweeps are sequential, so the result is bit-identical for any number of threads.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "linalg/block_matrix.hpp"

namespace suspend {

enum class Preconditioner { block_jacobi, symmetric_gauss_seidel };

struct ConjugateGradientReport {
  int iterations = 0;
  double residual = 0.0;  // |b - A x| / |b| at exit (0 when b = 0)
  bool converged = false;
};

class PreconditionedConjugateGradient {
 public:
  // Factorises the diagonal blocks of a and scales it in place (SymmetricBlockMatrix::factor_diagonal; a keeps its
  // products with A). Throws NumericalError if a diagonal block is not positive definite.
  void prepare(SymmetricBlockMatrix& a);
  // a: a matrix prepared by prepare() (InputError otherwise).
  ConjugateGradientReport solve(const SymmetricBlockMatrix& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                double tolerance, int max_iterations, Preconditioner kind);

 private:
  // In the scaled space (unit diagonal blocks):
  // hat: scratch of the pair form (G_j^T of the rows done), distinct from v and y.
  void multiply(const SymmetricBlockMatrix& a, const Eigen::VectorXd& v, Eigen::VectorXd& y,
                Eigen::VectorXd& hat) const;  // y = A' v
  void forward(const SymmetricBlockMatrix& a, const Eigen::VectorXd& v, Eigen::VectorXd& y,
               Eigen::VectorXd& hat) const;  // K'^-1 v
  void backward(const SymmetricBlockMatrix& a, const Eigen::VectorXd& v, Eigen::VectorXd& y,
                Eigen::VectorXd& hat) const;  // K'^-T v
  static void scale(const SymmetricBlockMatrix& a, const Eigen::VectorXd& r, Eigen::VectorXd& y);    // y = S r
  static void unscale(const SymmetricBlockMatrix& a, const Eigen::VectorXd& u, Eigen::VectorXd& y);  // y = S^T u
  double dot(const Eigen::VectorXd& u, const Eigen::VectorXd& v);

  Eigen::VectorXd rho_, u_, p_, q_, t_, w_;
  // The true residual of the guess before the iterations, the pair-form sweeps' scratch within them, and the
  // candidate x + d when it is checked: one vector, each use ending before the next begins.
  Eigen::VectorXd spare_;
  std::vector<double> chunk_sums_;
};

}  // namespace suspend

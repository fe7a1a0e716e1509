#include "dem/integrate/conjugate_gradient.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace suspend {
namespace {
constexpr std::ptrdiff_t chunk = 6 * 64;  // scalars per partial sum
constexpr std::ptrdiff_t parallel_threshold = 6 * 512;
}  // namespace

void BlockJacobiConjugateGradient::set_preconditioner(const SymmetricBlockMatrix& a) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.block_rows());
  inverse_diagonal_.resize(n);
  bool spd = true;
#pragma omp parallel for schedule(static) if (6 * n > parallel_threshold) reduction(&& : spd)
  for (std::ptrdiff_t r = 0; r < n; ++r) {
    const Eigen::LLT<Matrix6> llt(a.diagonal()[r]);
    spd = spd && llt.info() == Eigen::Success;
    inverse_diagonal_[r] = llt.solve(Matrix6::Identity());
  }
  if (!spd) throw NumericalError("resistance solve: a diagonal 6x6 block is not positive definite");
}

void BlockJacobiConjugateGradient::precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(inverse_diagonal_.size());
#pragma omp parallel for schedule(static) if (6 * n > parallel_threshold)
  for (std::ptrdiff_t i = 0; i < n; ++i) z.segment<6>(6 * i).noalias() = inverse_diagonal_[i] * r.segment<6>(6 * i);
}

double BlockJacobiConjugateGradient::dot(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  const std::ptrdiff_t size = u.size();
  const std::ptrdiff_t chunks = (size + chunk - 1) / chunk;
  chunk_sums_.resize(chunks);
#pragma omp parallel for schedule(static) if (size > parallel_threshold)
  for (std::ptrdiff_t c = 0; c < chunks; ++c) {
    const std::ptrdiff_t begin = c * chunk, len = std::min(chunk, size - begin);
    chunk_sums_[c] = u.segment(begin, len).dot(v.segment(begin, len));
  }
  double s = 0.0;
  for (double c : chunk_sums_) s += c;
  return s;
}

ConjugateGradientReport BlockJacobiConjugateGradient::solve(const SymmetricBlockMatrix& a, const Eigen::VectorXd& b,
                                                            Eigen::VectorXd& x, double tolerance,
                                                            int max_iterations) {
  const std::ptrdiff_t size = b.size();
  ConjugateGradientReport report;
  r_.resize(size);
  z_.resize(size);
  p_.resize(size);
  q_.resize(size);
  if (x.size() != size) x = Eigen::VectorXd::Zero(size);
  const double b_norm = std::sqrt(dot(b, b));
  if (b_norm == 0.0) {
    x.setZero();
    report.converged = true;
    return report;
  }
  a.multiply(x, q_);
  r_ = b - q_;
  double r_norm = std::sqrt(dot(r_, r_));
  // A warm start worse than the zero guess (e.g. after a large change of forcing) is dropped.
  if (r_norm > b_norm) {
    x.setZero();
    r_ = b;
    r_norm = b_norm;
  }
  precondition(r_, z_);
  p_ = z_;
  double rz = dot(r_, z_);
  int k = 0;
  while (r_norm > tolerance * b_norm && k < max_iterations) {
    a.multiply(p_, q_);
    const double pq = dot(p_, q_);
    if (!(pq > 0.0)) break;  // breakdown: not SPD, or not finite
    const double alpha = rz / pq;
    x.noalias() += alpha * p_;
    r_.noalias() -= alpha * q_;
    precondition(r_, z_);
    const double rz_new = dot(r_, z_);
    r_norm = std::sqrt(dot(r_, r_));
    p_ = z_ + (rz_new / rz) * p_;
    rz = rz_new;
    ++k;
  }
  report.iterations = k;
  report.residual = r_norm / b_norm;
  report.converged = std::isfinite(report.residual) && r_norm <= tolerance * b_norm;
  return report;
}

}  // namespace suspend

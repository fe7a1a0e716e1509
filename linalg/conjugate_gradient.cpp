#include "linalg/conjugate_gradient.hpp"

#include <algorithm>
#include <cmath>
#include <unistd.h>

#include "core/error.hpp"

namespace suspend {
namespace {
constexpr std::ptrdiff_t chunk = 6 * 64;  // scalars per partial sum
constexpr std::ptrdiff_t parallel_threshold = 6 * 512;

using Entry = SymmetricBlockMatrix::RowEntry;

// acc -= B x_column for the block B of a row entry (stored block or its transpose).
inline void subtract(const Entry& e, const std::vector<Matrix6>& blocks, const Eigen::VectorXd& x, Vector6& acc) {
  const auto xc = x.segment<6>(6 * static_cast<Eigen::Index>(e.column));
  if (e.transposed)
    acc.noalias() -= blocks[e.link].transpose() * xc;
  else
    acc.noalias() -= blocks[e.link] * xc;
}
// Fetches the coupling blocks of the entries [begin, end) towards the cache ahead of their use (a block is 288 B,
// five lines; a sweep reads them in row order, which is not their storage order, so the hardware does not). Pays
// only when the blocks do not fit the core's L2 cache: frictionless phi 0.50, one thread, two binaries side by side,
// N = 2000 (1.7 MB of blocks) 6-8% faster per strain, N = 500 (0.45 MB) 4-8% slower (docs/performance.md f).
// The L2 size is the system's (sysconf), 512 KB where it does not say.
inline void prefetch_blocks(const Entry* begin, const Entry* end, const std::vector<Matrix6>& blocks) {
  for (const Entry* e = begin; e != end; ++e) {
    const char* p = reinterpret_cast<const char*>(&blocks[e->link]);
    for (std::size_t line = 0; line < sizeof(Matrix6); line += 64) __builtin_prefetch(p + line);
  }
}
constexpr std::size_t prefetch_rows_ahead = 2;
bool blocks_outgrow_cache(const SymmetricBlockMatrix& a) {
  static const std::size_t l2 = [] {
    const long bytes = sysconf(_SC_LEVEL2_CACHE_SIZE);
    return bytes > 0 ? static_cast<std::size_t>(bytes) : std::size_t{512} << 10;
  }();
  return a.links() * sizeof(Matrix6) > l2;
}
// y_i = in_i, then solve(L_i, y_i), for every block row i (L_i: the factor a holds in scaled form).
template <class Solve>
void for_each_block(const SymmetricBlockMatrix& a, const Eigen::VectorXd& in, Eigen::VectorXd& y, Solve solve) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.block_rows());
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    y.segment<6>(6 * i) = in.segment<6>(6 * i);
    solve(a.diagonal()[i], y.segment<6>(6 * i));
  }
}
// One row of a pair-form sweep over the entries [begin, end) of row i: y_i = v_i - G_i sum C_ij hat_j, and
// hat_i = G_i^T y_i for the rows after it.
inline void pair_form_sweep_row(const SymmetricBlockMatrix& a, std::size_t i, const Entry* begin, const Entry* end,
                                const Eigen::VectorXd& v, Eigen::VectorXd& y, Eigen::VectorXd& hat) {
  Vector6 acc = Vector6::Zero();
  for (const Entry* e = begin; e != end; ++e) acc += a.pair_form_times(*e, hat);
  const Vector6 s = v.segment<6>(6 * i) - a.g_times(i, acc);
  y.segment<6>(6 * i) = s;
  hat.segment<6>(6 * i) = a.g_transpose_times(i, s);
}
}  // namespace

void PreconditionedConjugateGradient::prepare(SymmetricBlockMatrix& a) {
  if (!a.factor_diagonal()) throw NumericalError("resistance solve: a diagonal 6x6 block is not positive definite");
}

void PreconditionedConjugateGradient::multiply(const SymmetricBlockMatrix& a, const Eigen::VectorXd& v,
                                               Eigen::VectorXd& y, Eigen::VectorXd& hat) const {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.block_rows());
  if (a.storage() == CouplingStorage::pair_form) {  // y_i = v_i + G_i sum_j C_ij (G_j^T v_j)
    hat.resize(v.size());
#pragma omp parallel for schedule(static) if (6 * n > parallel_threshold)
    for (std::ptrdiff_t i = 0; i < n; ++i)
      hat.segment<6>(6 * i) = a.g_transpose_times(i, v.segment<6>(6 * i));
#pragma omp parallel for schedule(static) if (6 * n > parallel_threshold)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      Vector6 acc = Vector6::Zero();
      for (const Entry* e = a.row_begin(i); e != a.row_end(i); ++e) acc += a.pair_form_times(*e, hat);
      y.segment<6>(6 * i) = v.segment<6>(6 * i) + a.g_times(i, acc);
    }
    return;
  }
#pragma omp parallel for schedule(static) if (6 * n > parallel_threshold)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    Vector6 s = v.segment<6>(6 * i);
    Vector6 off = Vector6::Zero();
    for (const Entry* e = a.row_begin(i); e != a.row_end(i); ++e) subtract(*e, a.coupling(), v, off);
    y.segment<6>(6 * i) = s - off;
  }
}

// y_i = v_i - sum_{j<i} A'_ij y_j, i ascending.
void PreconditionedConjugateGradient::forward(const SymmetricBlockMatrix& a, const Eigen::VectorXd& v,
                                              Eigen::VectorXd& y, Eigen::VectorXd& hat) const {
  const std::size_t n = a.block_rows();
  if (a.storage() == CouplingStorage::pair_form) {  // y_i = v_i - G_i sum_{j<i} C_ij hat_j, hat_i = G_i^T y_i
    hat.resize(v.size());
    for (std::size_t i = 0; i < n; ++i) pair_form_sweep_row(a, i, a.row_begin(i), a.row_diagonal(i), v, y, hat);
    return;
  }
  const bool prefetch = blocks_outgrow_cache(a);
  for (std::size_t i = 0; i < n; ++i) {
    if (prefetch && i + prefetch_rows_ahead < n) {
      const std::size_t k = i + prefetch_rows_ahead;
      prefetch_blocks(a.row_begin(k), a.row_diagonal(k), a.coupling());
    }
    Vector6 s = v.segment<6>(6 * i);
    for (const Entry* e = a.row_begin(i); e != a.row_diagonal(i); ++e) subtract(*e, a.coupling(), y, s);
    y.segment<6>(6 * i) = s;
  }
}

// y_i = v_i - sum_{j>i} A'_ij y_j, i descending.
void PreconditionedConjugateGradient::backward(const SymmetricBlockMatrix& a, const Eigen::VectorXd& v,
                                               Eigen::VectorXd& y, Eigen::VectorXd& hat) const {
  if (a.storage() == CouplingStorage::pair_form) {
    hat.resize(v.size());
    for (std::size_t i = a.block_rows(); i-- > 0;)
      pair_form_sweep_row(a, i, a.row_diagonal(i), a.row_end(i), v, y, hat);
    return;
  }
  const bool prefetch = blocks_outgrow_cache(a);
  for (std::size_t i = a.block_rows(); i-- > 0;) {
    if (prefetch && i >= prefetch_rows_ahead) {
      const std::size_t k = i - prefetch_rows_ahead;
      prefetch_blocks(a.row_diagonal(k), a.row_end(k), a.coupling());
    }
    Vector6 s = v.segment<6>(6 * i);
    for (const Entry* e = a.row_diagonal(i); e != a.row_end(i); ++e) subtract(*e, a.coupling(), y, s);
    y.segment<6>(6 * i) = s;
  }
}

void PreconditionedConjugateGradient::scale(const SymmetricBlockMatrix& a, const Eigen::VectorXd& r,
                                            Eigen::VectorXd& y) {
  if (a.storage() == CouplingStorage::pair_form) {  // the packed diagonal holds G_i = L_i^-1
    for (std::size_t i = 0; i < a.block_rows(); ++i) y.segment<6>(6 * i) = a.g_times(i, r.segment<6>(6 * i));
    return;
  }
  for_each_block(a, r, y, [](const Matrix6& l, auto&& v) { solve_lower(l, v); });
}

void PreconditionedConjugateGradient::unscale(const SymmetricBlockMatrix& a, const Eigen::VectorXd& u,
                                              Eigen::VectorXd& y) {
  if (a.storage() == CouplingStorage::pair_form) {
    for (std::size_t i = 0; i < a.block_rows(); ++i) y.segment<6>(6 * i) = a.g_transpose_times(i, u.segment<6>(6 * i));
    return;
  }
  for_each_block(a, u, y, [](const Matrix6& l, auto&& v) { solve_lower_transpose(l, v); });
}

double PreconditionedConjugateGradient::dot(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
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

ConjugateGradientReport PreconditionedConjugateGradient::solve(const SymmetricBlockMatrix& a,
                                                               const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                                               double tolerance, int max_iterations,
                                                               Preconditioner kind) {
  if (!a.scaled()) throw InputError("conjugate gradient: the matrix was not prepared (scaled) for it");
  const std::ptrdiff_t size = b.size();
  Eigen::VectorXd& r = spare_;  // the true residual, used only before the iterations
  for (Eigen::VectorXd* v : {&rho_, &u_, &p_, &q_, &t_, &w_, &spare_}) v->resize(size);
  if (x.size() != size) x = Eigen::VectorXd::Zero(size);
  ConjugateGradientReport report;
  report.converged = true;
  const double b_norm = std::sqrt(dot(b, b));
  if (b_norm == 0.0) {
    x.setZero();
    return report;
  }
  const bool ssor = kind == Preconditioner::symmetric_gauss_seidel;
  // True residual of the guess; a guess worse than zero (e.g. after a jump in the forcing) is dropped.
  a.multiply(x, q_);
  r = b - q_;
  double true_norm = std::sqrt(dot(r, r));
  if (true_norm > b_norm) {
    x.setZero();
    r = b;
    true_norm = b_norm;
  }
  report.residual = true_norm / b_norm;
  if (true_norm <= tolerance * b_norm) return report;

  // Correction d = S^T u (Jacobi) or S^T K'^-T u (Gauss-Seidel); CG residual rho = S r or K'^-1 S r.
  scale(a, r, ssor ? w_ : rho_);
  if (ssor) forward(a, w_, rho_, spare_);
  u_.setZero();
  p_ = rho_;
  double rr = dot(rho_, rho_);
  double target = std::sqrt(rr) * tolerance * b_norm / true_norm;  // assumes |rho| proportional to |r|
  // The candidate x + d and the norm of its true residual b - A (x + d).
  auto check_candidate = [&] {
    if (ssor) {
      backward(a, u_, w_, spare_);
      unscale(a, w_, t_);
    } else {
      unscale(a, u_, t_);
    }
    spare_ = x + t_;  // the candidate
    a.multiply(spare_, q_);
    w_ = b - q_;
    return std::sqrt(dot(w_, w_));
  };
  int k = 0;
  bool checked = true;
  while (k < max_iterations) {
    if (ssor) {  // q = t + K'^-1 (p - t), t = K'^-T p
      backward(a, p_, t_, spare_);
      w_ = p_ - t_;
      forward(a, w_, q_, spare_);
      q_ += t_;
    } else {
      multiply(a, p_, q_, spare_);
    }
    const double pq = dot(p_, q_);
    if (!(pq > 0.0)) {  // breakdown: not SPD or not finite; the candidate of the current iterate is formed again
      checked = false;
      break;
    }
    const double alpha = rr / pq;
    u_.noalias() += alpha * p_;
    rho_.noalias() -= alpha * q_;
    const double rr_new = dot(rho_, rho_);
    p_ = rho_ + (rr_new / rr) * p_;
    rr = rr_new;
    ++k;
    checked = false;
    if (std::sqrt(rr) <= target || k == max_iterations) {
      const double r_norm = check_candidate();
      checked = true;
      true_norm = r_norm;
      if (!std::isfinite(r_norm) || r_norm <= tolerance * b_norm) break;
      target = 0.5 * std::sqrt(rr) * tolerance * b_norm / r_norm;
    }
  }
  if (!checked) true_norm = check_candidate();  // breakdown before a check: report the last iterate honestly
  if (k > 0) x = spare_;
  report.iterations = k;
  report.residual = true_norm / b_norm;
  report.converged = std::isfinite(report.residual) && true_norm <= tolerance * b_norm;
  return report;
}

}  // namespace suspend

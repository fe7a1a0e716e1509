// Right-preconditioned GMRES (Saad & Schultz 1986; Saad, "Iterative Methods for Sparse Linear Systems", 2nd ed.,
// Algorithm 9.5) without restart, for matrix-free operators whose every application is expensive (one FCM Stokes
// solve). Eigen's unsupported GMRES preconditions from the left (it stops on the preconditioned residual) and spends
// an operator application on the initial residual; here the caller passes the initial residual r0 = b - A x0
// (which its warm start costs anyway) and the stopping test is on the true residual norm |r0 - A dx|, which right
// preconditioning leaves unchanged.
//   apply(v, out): out = A v;   precondition(v, out): out ~ P^-1 v.
// The preconditioned vectors z_j are kept and dx = Z y, so the preconditioner may change from one iteration to the
// next (flexible GMRES, Saad, SIAM J. Sci. Comput. 14, 461 (1993)): e.g. an inexact inner iterative solve.
// Solves A dx = r0 for dx; stops when |r0 - A dx| <= tolerance or after max_iterations.
#pragma once
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

namespace suspend::coupling {

struct GmresReport {
  int iterations = 0;
  double residual = 0.0;  // |r0 - A dx| (Arnoldi estimate, exact in exact arithmetic)
};

template <class Apply, class Precondition>
GmresReport gmres(Apply&& apply, Precondition&& precondition, const Eigen::VectorXd& r0, Eigen::VectorXd& dx,
                  double tolerance, int max_iterations) {
  GmresReport rep;
  const Eigen::Index n = r0.size();
  dx.setZero(n);
  const double beta = r0.norm();
  rep.residual = beta;
  if (beta <= tolerance || max_iterations <= 0) return rep;
  const int m = max_iterations;
  std::vector<Eigen::VectorXd> v, z;
  v.reserve(m + 1);
  z.reserve(m);
  v.push_back(r0 / beta);
  // Hessenberg columns grow with the iterations: a warm-started coupled solve takes 1-3 of max_iterations (1000),
  // and zeroing a full (m + 1) x m matrix (8 MB at m = 1000) in every solve is wasted memory traffic.
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, std::min(m, 8));
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1), cs(m), sn(m);
  g(0) = beta;
  Eigen::VectorXd w(n);
  int k = 0;
  for (; k < m; ++k) {
    if (k == h.cols()) h.conservativeResizeLike(Eigen::MatrixXd::Zero(m + 1, std::min(m, 2 * k)));
    z.emplace_back(n);
    precondition(v[k], z[k]);
    apply(z[k], w);
    for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
      h(i, k) = v[i].dot(w);
      w -= h(i, k) * v[i];
    }
    h(k + 1, k) = w.norm();
    for (int i = 0; i < k; ++i) {  // previous Givens rotations
      const double t = cs(i) * h(i, k) + sn(i) * h(i + 1, k);
      h(i + 1, k) = -sn(i) * h(i, k) + cs(i) * h(i + 1, k);
      h(i, k) = t;
    }
    const double rho = std::hypot(h(k, k), h(k + 1, k));
    cs(k) = rho > 0.0 ? h(k, k) / rho : 1.0;
    sn(k) = rho > 0.0 ? h(k + 1, k) / rho : 0.0;
    const double hk1 = h(k + 1, k);
    h(k, k) = rho;
    h(k + 1, k) = 0.0;
    g(k + 1) = -sn(k) * g(k);
    g(k) = cs(k) * g(k);
    rep.residual = std::abs(g(k + 1));
    ++rep.iterations;
    if (rep.residual <= tolerance || !(hk1 > 0.0)) {
      ++k;
      break;
    }
    v.push_back(w / hk1);
  }
  // y = H^-1 g (upper triangular k x k), dx = Z y.
  const Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  for (int i = 0; i < k; ++i) dx += y(i) * z[i];
  return rep;
}

}  // namespace suspend::coupling

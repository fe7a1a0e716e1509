// The right-preconditioned GMRES against a direct LU solve on a nonsymmetric system, and its iteration bound
// (n iterations at most for an n x n system, exact arithmetic; Saad & Schultz 1986).
#include <gtest/gtest.h>

#include "linalg/gmres.hpp"

using namespace suspend::coupling;

TEST(CouplingGmres, SolvesANonsymmetricSystemLikeLu) {
  const int n = 40;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) a(i, j) = 0.3 * std::sin(1.7 * i + 0.9 * j * j) / (1.0 + std::abs(i - j));
  for (int i = 0; i < n; ++i) a(i, i) += 2.0 + 10.0 * (i % 5);  // badly scaled diagonal: the preconditioner's job
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b(i) = std::cos(0.37 * i);
  const Eigen::VectorXd exact = a.partialPivLu().solve(b);
  const Eigen::VectorXd d = a.diagonal();
  Eigen::VectorXd x0 = Eigen::VectorXd::Constant(n, 0.1);
  const Eigen::VectorXd r0 = b - a * x0;
  Eigen::VectorXd dx;
  const GmresReport rep = gmres([&](const Eigen::VectorXd& v, Eigen::VectorXd& out) { out = a * v; },
                                [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) { out = v.cwiseQuotient(d); },
                                r0, dx, 1e-12 * b.norm(), n);
  const Eigen::VectorXd x = x0 + dx;
  EXPECT_LE(rep.iterations, n);
  EXPECT_LT((x - exact).norm(), 1e-10 * exact.norm());
  EXPECT_NEAR(rep.residual, (b - a * x).norm(), 1e-10 * b.norm());
}

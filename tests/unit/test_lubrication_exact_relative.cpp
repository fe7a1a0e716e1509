// The pairwise option `lubrication.functions: exact_relative` against the exact two-sphere table
// (tests/data/two_sphere_resistance_table.txt, lambda = 1): with Stokes drag added, the relative-motion
// combinations of A, B, G (X11A - X12A, ...) and the C, H functions equal the exact ones; rigid translation of the
// pair stays force-free; the pair (with drag) stays positive definite. The unequal pair lambda = 1.4
// (tests/data/two_sphere_resistance_table_lambda1.4.txt): the exact 12x12 resistance is built here from the table's
// scalars (the block forms of lubrication.hpp, written out again), and the model with drag must give the same
// dissipation for every motion with U_i + U_j = 0, no force for rigid translation, equal and opposite strain forces
// whose difference is exact, and the exact strain torques, seen from either sphere. Ratios without a table keep the
// singular terms.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "dem/hydro/lubrication.hpp"
#include "tests/two_sphere_table.hpp"

using namespace suspend;
using namespace suspend::hydro;

namespace {

LubricationParams exact_params() {
  LubricationParams p;
  p.inner_cutoff = 1e-6;
  p.outer_cutoff = 0.5;
  p.exact_relative = true;
  return p;
}

// Exact table at lambda = 1: s' -> {"11" row, "12" row}, columns XA YA YB XC YC XG YG YH.
suspend::test::TwoSphereTable exact_table() {
  return suspend::test::read_two_sphere_table("two_sphere_resistance_table.txt", 1.0);
}

}  // namespace

TEST(LubricationExactRelative, RelativeMotionAndRotationFunctionsAreExact) {
  const PairLubrication law(1.0, 1.0, exact_params());
  const auto table = exact_table();
  int checked = 0;
  for (const auto& [sp, rows] : table) {
    const double xi = sp - 2.0;
    if (xi < 0.005 || xi > 0.25) continue;
    ResistanceScalars si, sj;
    law.scalars(xi, si, sj);  // gap h = xi (a_1 + a_2)/2 = xi
    add_stokes_drag(si);
    const auto& e11 = rows[0];
    const auto& e12 = rows[1];
    const auto near = [](double got, double want) { EXPECT_NEAR(got, want, 1e-6 * (1.0 + std::abs(want))); };
    near(si.x11a - si.x12a, e11[0] - e12[0]);
    near(si.y11a - si.y12a, e11[1] - e12[1]);
    near(si.y11b - si.y12b, e11[2] - e12[2]);
    near(si.x11g - si.x12g, e11[5] - e12[5]);
    near(si.y11g - si.y12g, e11[6] - e12[6]);
    near(si.x11c, e11[3]);
    near(si.x12c, e12[3]);
    near(si.y11c, e11[4]);
    near(si.y12c, e12[4]);
    near(si.y11h, e11[7]);
    near(si.y12h, e12[7]);
    // Rigid translation costs nothing, as in the singular model.
    EXPECT_NEAR(si.x11a - 1.0 + si.x12a, 0.0, 1e-12 * si.x11a);
    EXPECT_NEAR(si.y11a - 1.0 + si.y12a, 0.0, 1e-12);
    EXPECT_NEAR(sj.x11a, si.x11a - 1.0, 1e-12 * si.x11a);
    ++checked;
  }
  EXPECT_GE(checked, 5);  // table nodes at xi = 0.005 ... 0.25
}

TEST(LubricationExactRelative, PairWithDragIsPositiveDefiniteAndTranslationFree) {
  const PairLubrication law(1.0, 1.0, exact_params());
  const Vec3 n = Vec3(1.0, 2.0, -0.5).normalized();
  for (double gap : {1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.3}) {
    Matrix12 r = law.resistance(n, gap);
    Vector12 t;
    t << Vec3(0.3, -1.0, 0.7), Vec3::Zero(), Vec3(0.3, -1.0, 0.7), Vec3::Zero();
    EXPECT_LT((r * t).cwiseAbs().maxCoeff(), 1e-12 * r.cwiseAbs().maxCoeff()) << gap;
    for (int k : {0, 1, 2, 6, 7, 8}) r(k, k) += 6.0 * std::numbers::pi;
    for (int k : {3, 4, 5, 9, 10, 11}) r(k, k) += 8.0 * std::numbers::pi;
    const Eigen::SelfAdjointEigenSolver<Matrix12> eig(r);
    EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0) << gap;
  }
}

namespace {

constexpr double pi = std::numbers::pi;

// The lambda = 1.4 file's "11" and "12" rows (XA YA YB XC YC XG YG YH) at s' for the given lambda.
suspend::test::TwoSphereRow unequal_row(double lambda, double sp) {
  const auto table = suspend::test::lambda_1_4_table(lambda);
  const auto it = table.find(sp);
  EXPECT_TRUE(it != table.end()) << lambda << " " << sp;
  return it == table.end() ? suspend::test::TwoSphereRow{} : it->second;
}

struct ExactPair {
  Matrix12 r;       // exact resistance, Stokes drag included
  Vector12 strain;  // exact forces and torques of the strain rates e_i, e_j
};

// Exact two-sphere resistance of spheres a_i, a_j at s' along n from the table (functions of sphere alpha seen
// from alpha in its units, d_alpha pointing to the other sphere).
ExactPair exact_pair(double a_i, double a_j, double sp, const Vec3& n, const Mat3& e_i, const Mat3& e_j) {
  const auto ti = unequal_row(a_j / a_i, sp), tj = unequal_row(a_i / a_j, sp);
  enum { XA, YA, YB, XC, YC, XG, YG, YH };
  const Mat3 nn = n * n.transpose(), tt = Mat3::Identity() - nn;
  const auto cross = [](const Vec3& d) {
    Mat3 m;  // m v = v x d
    m << 0.0, d.z(), -d.y(), -d.z(), 0.0, d.x(), d.y(), -d.x(), 0.0;
    return m;
  };
  const double a[2] = {a_i, a_j};
  const Vec3 d[2] = {n, -n};
  const suspend::test::TwoSphereRow* t[2] = {&ti, &tj};
  ExactPair out;
  for (int al = 0; al < 2; ++al)
    for (int be = 0; be < 2; ++be) {
      const auto& f = (*t[al])[al == be ? 0 : 1];
      const double ar = a[al];
      out.r.block<3, 3>(6 * al, 6 * be) = 6 * pi * ar * (f[XA] * nn + f[YA] * tt);
      out.r.block<3, 3>(6 * al + 3, 6 * be + 3) = 8 * pi * ar * ar * ar * (f[XC] * nn + f[YC] * tt);
      out.r.block<3, 3>(6 * al + 3, 6 * be) = 4 * pi * ar * ar * f[YB] * cross(d[al]);  // torque of alpha, U_beta
      out.r.block<3, 3>(6 * be, 6 * al + 3) = out.r.block<3, 3>(6 * al + 3, 6 * be).transpose();
    }
  // Strain: F_beta += G^{alpha beta} : E_alpha, T_beta += H^{alpha beta} : E_alpha (the stresslet of alpha due to the
  // motion of beta, by reciprocity).
  const Mat3 e[2] = {e_i, e_j};
  out.strain.setZero();
  for (int al = 0; al < 2; ++al)
    for (int be = 0; be < 2; ++be) {
      const auto& f = (*t[al])[al == be ? 0 : 1];
      const double ar = a[al];
      const Vec3 ed = e[al] * d[al];
      const double ded = d[al].dot(ed);
      out.strain.segment<3>(6 * be) += 4 * pi * ar * ar * (f[XG] * ded * d[al] + 2 * f[YG] * (ed - ded * d[al]));
      out.strain.segment<3>(6 * be + 3) += 8 * pi * ar * ar * ar * 2 * f[YH] * d[al].cross(ed);
    }
  return out;
}

Matrix12 drag(double a_i, double a_j) {
  Vector12 v;
  v << Vec3::Constant(6 * pi * a_i), Vec3::Constant(8 * pi * a_i * a_i * a_i), Vec3::Constant(6 * pi * a_j),
      Vec3::Constant(8 * pi * a_j * a_j * a_j);
  return v.asDiagonal();
}

}  // namespace

TEST(LubricationExactRelative, UnequalPairIsExactForEveryMotionWithoutMeanTranslation) {
  const Vec3 n = Vec3(0.3, -1.0, 0.6).normalized();
  Mat3 e_i, e_j;
  e_i << 0.1, 0.5, -0.2, 0.5, 0.3, 0.05, -0.2, 0.05, -0.4;
  e_j << -0.3, 0.2, 0.4, 0.2, 0.1, -0.25, 0.4, -0.25, 0.2;
  // Basis of the motions with U_i + U_j = 0: relative translation and both rotations.
  Eigen::Matrix<double, 12, 9> q = Eigen::Matrix<double, 12, 9>::Zero();
  for (int k = 0; k < 3; ++k) {
    q(k, k) = 1.0;
    q(6 + k, k) = -1.0;
    q(3 + k, 3 + k) = 1.0;
    q(9 + k, 6 + k) = 1.0;
  }
  for (const auto& [a_i, a_j] : {std::pair{1.0, 1.4}, std::pair{1.4, 1.0}}) {
    const PairLubrication law(a_i, a_j, exact_params());
    ASSERT_TRUE(law.exact());
    for (double sp : {2.0001, 2.001, 2.01, 2.05, 2.1, 2.2}) {
      const double gap = (sp - 2.0) * 0.5 * (a_i + a_j);
      const ExactPair ex = exact_pair(a_i, a_j, sp, n, e_i, e_j);
      const Matrix12 model = law.resistance(n, gap) + drag(a_i, a_j);
      const Eigen::Matrix<double, 9, 9> want = q.transpose() * ex.r * q, got = q.transpose() * model * q;
      EXPECT_LT((got - want).cwiseAbs().maxCoeff(), 1e-6 * want.cwiseAbs().maxCoeff()) << a_i << " " << sp;
      // Rigid translation costs nothing, as in the singular model.
      Vector12 t;
      t << Vec3(0.3, -1.0, 0.7), Vec3::Zero(), Vec3(0.3, -1.0, 0.7), Vec3::Zero();
      EXPECT_LT((law.resistance(n, gap) * t).cwiseAbs().maxCoeff(), 1e-12 * model.cwiseAbs().maxCoeff()) << sp;
      const Eigen::SelfAdjointEigenSolver<Matrix12> eig(model);
      EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0) << sp;
      // Strain: the lubrication forces are equal and opposite with the exact difference; the torques are exact.
      const Vector12 f = law.strain_forces(n, gap, e_i, e_j);
      const double scale = ex.strain.cwiseAbs().maxCoeff();
      EXPECT_LT((f.segment<3>(0) + f.segment<3>(6)).norm(), 1e-12 * scale) << sp;
      EXPECT_LT((f.segment<3>(0) - f.segment<3>(6) - ex.strain.segment<3>(0) + ex.strain.segment<3>(6)).norm(),
                1e-6 * scale) << a_i << " " << sp;
      EXPECT_LT((f.segment<3>(3) - ex.strain.segment<3>(3)).norm(), 1e-6 * scale) << a_i << " " << sp;
      EXPECT_LT((f.segment<3>(9) - ex.strain.segment<3>(9)).norm(), 1e-6 * scale) << a_i << " " << sp;
    }
  }
}

TEST(LubricationExactRelative, RatiosWithoutATableKeepTheSingularTerms) {
  const PairLubrication exact(1.0, 2.0, exact_params());
  LubricationParams p = exact_params();
  p.exact_relative = false;
  const PairLubrication singular(1.0, 2.0, p);
  EXPECT_FALSE(exact.exact());
  const Vec3 n = Vec3(1.0, 0.2, -0.3).normalized();
  EXPECT_EQ(exact.resistance(n, 0.01), singular.resistance(n, 0.01));
}

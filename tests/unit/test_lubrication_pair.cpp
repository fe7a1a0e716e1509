// The assembled pair lubrication law (dem/hydro/lubrication.hpp): symmetry, dissipation, Newton's third law,
// frame invariance, rigid-body motion, the strain terms against the squeeze terms, Lorentz reciprocity between
// strain forces and stresslets, and the gap regularisation / cutoffs.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <random>

#include "core/error.hpp"
#include "dem/hydro/lubrication.hpp"

using namespace suspend;
using namespace suspend::hydro;

namespace {

LubricationParams params(double inner = 1e-6, double outer = 0.5, double eps = 0.0) {
  LubricationParams p;
  p.inner_cutoff = inner;
  p.outer_cutoff = outer;
  p.regularization = eps;
  return p;
}

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Vec3 v(g(rng), g(rng), g(rng));
  return v.normalized();
}

Mat3 random_strain(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Mat3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = g(rng);
  Mat3 e = 0.5 * (m + m.transpose());
  return e - e.trace() / 3.0 * Mat3::Identity();
}

Vector12 random_motion(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Vector12 v;
  for (int k = 0; k < 12; ++k) v(k) = g(rng);
  return v;
}

Mat3 random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> g;
  const Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized().toRotationMatrix();
}

PairMotion motion_from(const Vector12& v, const Mat3& e_i, const Mat3& e_j) {
  PairMotion m;
  m.du_i = v.segment<3>(0);
  m.dw_i = v.segment<3>(3);
  m.du_j = v.segment<3>(6);
  m.dw_j = v.segment<3>(9);
  m.e_i = e_i;
  m.e_j = e_j;
  return m;
}

struct Case {
  double a_i, a_j, gap;
};
constexpr Case cases[] = {{1.0, 1.0, 1e-3}, {1.0, 1.4, 0.02}, {1.0, 3.0, 1e-4}, {3.0, 1.0, 0.1}, {1.0, 10.0, 1e-3}};

}  // namespace

TEST(PairLubrication, ResistanceIsSymmetricPositiveSemiDefinite) {
  std::mt19937 rng(11);
  for (const Case& c : cases) {
    const PairLubrication law(c.a_i, c.a_j, params());
    const Matrix12 r = law.resistance(random_unit(rng), c.gap);
    EXPECT_LT((r - r.transpose()).cwiseAbs().maxCoeff(), 1e-13 * r.cwiseAbs().maxCoeff());
    const Eigen::SelfAdjointEigenSolver<Matrix12> eig(r);
    const double largest = eig.eigenvalues().maxCoeff();
    EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12 * largest) << "a_j/a_i = " << c.a_j / c.a_i << " gap " << c.gap;
    // Dissipation (V - V_inf) . R (V - V_inf) >= 0 for any motion.
    for (int k = 0; k < 20; ++k) {
      const Vector12 v = random_motion(rng);
      EXPECT_GE(v.dot(r * v), -1e-12 * largest * v.squaredNorm());
    }
  }
}

// Rigid-body motion of the pair (translation plus rotation about any point) moves no fluid through the gap:
// the singular lubrication terms give no force and no torque.
TEST(PairLubrication, RigidBodyMotionOfThePairIsForceFree) {
  std::mt19937 rng(12);
  for (const Case& c : cases) {
    const PairLubrication law(c.a_i, c.a_j, params());
    const Vec3 n = random_unit(rng);
    const double r = c.a_i + c.a_j + c.gap;
    const Vec3 u = random_unit(rng), w = random_unit(rng);
    Vector12 v;
    v << u, w, u + w.cross(r * n), w;  // x_i at the origin, x_j = r n
    const Matrix12 res = law.resistance(n, c.gap);
    const Vector12 f = res * v;
    // Compare with the squeeze scale 6 pi a_i X11A |u|: the residual is O(h) relative to the singular terms.
    EXPECT_LT(f.cwiseAbs().maxCoeff(), 2.0 * c.gap * res.cwiseAbs().maxCoeff())
        << "a_j/a_i = " << c.a_j / c.a_i;
    Vector12 t;
    t << u, Vec3::Zero(), u, Vec3::Zero();
    EXPECT_LT((res * t).cwiseAbs().maxCoeff(), 1e-12 * res.cwiseAbs().maxCoeff());
  }
}

// Squeeze: equal and opposite forces along n, repulsive when approaching; magnitude 6 pi a_i X11A^lub (U_i - U_j).n.
TEST(PairLubrication, SqueezeObeysNewtonsThirdLaw) {
  const double a_i = 1.0, a_j = 2.0, gap = 0.01;
  const PairLubrication law(a_i, a_j, params());
  const Vec3 n(0.0, 0.6, 0.8);
  PairMotion m;
  m.du_i = 0.3 * n;  // approaching
  m.du_j = -0.2 * n;
  const PairHydroForce f = law.evaluate(n, gap, m);
  EXPECT_LT((f.force_i + f.force_j).norm(), 1e-12 * f.force_i.norm());
  EXPECT_LT(f.force_i.dot(n), 0.0);  // pushed back, away from j
  const double lambda = a_j / a_i, xi = 2.0 * gap / (a_i + a_j);
  const double x11a = 2.0 * lambda * lambda / std::pow(1.0 + lambda, 3) / xi +
                      lambda * (1.0 + 7.0 * lambda + lambda * lambda) / (5.0 * std::pow(1.0 + lambda, 3)) *
                          std::log(1.0 / xi);
  EXPECT_NEAR(f.force_i.dot(n), -6.0 * std::numbers::pi * a_i * x11a * 0.5, 1e-10 * f.force_i.norm());
  EXPECT_LT(f.torque_i.norm() + f.torque_j.norm(), 1e-12 * f.force_i.norm());
}

// Rotating the whole configuration (n, velocities, strain rates) rotates every force, torque and stresslet.
TEST(PairLubrication, FrameInvariance) {
  std::mt19937 rng(13);
  for (const Case& c : cases) {
    const PairLubrication law(c.a_i, c.a_j, params());
    const Vec3 n = random_unit(rng);
    const PairMotion m = motion_from(random_motion(rng), random_strain(rng), random_strain(rng));
    const Mat3 q = random_rotation(rng);
    PairMotion mq;
    mq.du_i = q * m.du_i;
    mq.dw_i = q * m.dw_i;
    mq.du_j = q * m.du_j;
    mq.dw_j = q * m.dw_j;
    mq.e_i = q * m.e_i * q.transpose();
    mq.e_j = q * m.e_j * q.transpose();
    const PairHydroForce f = law.evaluate(n, c.gap, m);
    const PairHydroForce fq = law.evaluate(q * n, c.gap, mq);
    const double scale = f.force_i.norm() + f.force_j.norm() + f.torque_i.norm() + f.torque_j.norm();
    EXPECT_LT((fq.force_i - q * f.force_i).norm(), 1e-12 * scale);
    EXPECT_LT((fq.force_j - q * f.force_j).norm(), 1e-12 * scale);
    EXPECT_LT((fq.torque_i - q * f.torque_i).norm(), 1e-12 * scale);
    EXPECT_LT((fq.torque_j - q * f.torque_j).norm(), 1e-12 * scale);
    const double s_scale = f.stresslet_i.norm() + f.stresslet_j.norm();
    EXPECT_LT((fq.stresslet_i - q * f.stresslet_i * q.transpose()).norm(), 1e-12 * s_scale);
    EXPECT_LT((fq.stresslet_j - q * f.stresslet_j * q.transpose()).norm(), 1e-12 * s_scale);
  }
}

// Two spheres carried affinely by a straining flow cannot approach without bound: the 1/xi squeeze force of the
// affine relative velocity, R_lub V_inf, is cancelled by the 1/xi strain force X^G (Jeffrey 1992: for force-free
// spheres the relative normal velocity vanishes at contact). What remains is O(ln(1/xi)), not O(1/xi).
TEST(PairLubrication, StrainForceCancelsAffineSqueezeAtLeadingOrder) {
  for (double lambda : {1.0, 0.3, 4.0}) {
    const double a_i = 1.0, a_j = lambda;
    const PairLubrication law(a_i, a_j, params(1e-9));
    const Vec3 n(1.0, 0.0, 0.0);
    Mat3 e = Mat3::Zero();
    e(0, 0) = 1.0;
    e(1, 1) = -0.5;
    e(2, 2) = -0.5;  // uniaxial extension along n
    for (double gap : {1e-4, 1e-6}) {
      const double r = a_i + a_j + gap;
      PairMotion m;  // particles held fixed: V - V_inf = -V_inf, U_inf(x) = E x with x_i = 0, x_j = r n
      m.du_i = Vec3::Zero();
      m.du_j = -(e * (r * n));
      m.e_i = e;
      m.e_j = e;
      const PairHydroForce f = law.evaluate(n, gap, m);
      PairMotion squeeze_only = m;
      squeeze_only.e_i.setZero();
      squeeze_only.e_j.setZero();
      const double squeeze = std::abs(law.evaluate(n, gap, squeeze_only).force_i.dot(n));
      // The squeeze part alone grows like 1/xi; the total is smaller by a factor ~ xi ln(1/xi).
      const double xi = 2.0 * gap / (a_i + a_j);
      EXPECT_LT(std::abs(f.force_i.dot(n)), 10.0 * xi * std::log(1.0 / xi) * squeeze) << "lambda " << lambda;
      EXPECT_LT((f.force_i + f.force_j).norm(), 1e-9 * squeeze);  // uniform E: no net force on the pair
    }
  }
}

// Lorentz reciprocal theorem: the strain-force operator R_FE and the stresslet-from-velocity operator R_SU are
// transposes: (V - V_inf) . (R_FE : E) = -sum_a E_a : S_a(V - V_inf; E = 0).
TEST(PairLubrication, StrainForcesAndStressletsAreReciprocal) {
  std::mt19937 rng(14);
  for (const Case& c : cases) {
    const PairLubrication law(c.a_i, c.a_j, params());
    const Vec3 n = random_unit(rng);
    const Vector12 v = random_motion(rng);
    const Mat3 e_i = random_strain(rng), e_j = random_strain(rng);
    const double work = v.dot(law.strain_forces(n, c.gap, e_i, e_j));
    const PairHydroForce s = law.evaluate(n, c.gap, motion_from(v, Mat3::Zero(), Mat3::Zero()));
    const double stress_work = (e_i.cwiseProduct(s.stresslet_i)).sum() + (e_j.cwiseProduct(s.stresslet_j)).sum();
    EXPECT_NEAR(work, -stress_work, 1e-10 * (std::abs(work) + 1.0)) << "a_j/a_i = " << c.a_j / c.a_i;
  }
}

// Approaching equal spheres: stresslet compressive along n (negative S_nn: a positive particle pressure, as a
// repulsive contact), equal on both spheres.
TEST(PairLubrication, ApproachingPairGivesCompressiveStresslet) {
  const PairLubrication law(1.0, 1.0, params());
  const Vec3 n(0.0, 1.0, 0.0);
  PairMotion m;
  m.du_i = 0.5 * n;
  m.du_j = -0.5 * n;
  const PairHydroForce f = law.evaluate(n, 1e-3, m);
  EXPECT_LT(n.dot(f.stresslet_i * n), 0.0);
  EXPECT_NEAR((f.stresslet_i - f.stresslet_j).norm(), 0.0, 1e-12 * f.stresslet_i.norm());
}

// In the lubrication limit the squeeze force acts at the gap, a lever arm a_i from the centre of i: the stresslet of
// each sphere is the deviatoric part of -a_alpha n (F_j . n) n (Batchelor & Green 1972's force-dipole form, paper 000
// eq. 9b), so S_i / S_j = a_i / a_j and the pair's stresslet is the deviatoric part of -sym(d F_j).
TEST(PairLubrication, SqueezeStressletIsTheForceDipoleAtTheGap) {
  for (double lambda : {1.0, 3.0, 0.5}) {
    const double a_i = 1.0, a_j = lambda, gap = 1e-7;
    const PairLubrication law(a_i, a_j, params(1e-9));
    const Vec3 n = Vec3(1.0, 2.0, 2.0) / 3.0;
    PairMotion m;
    m.du_i = 0.4 * n;
    m.du_j = -0.1 * n;
    const PairHydroForce f = law.evaluate(n, gap, m);
    const Mat3 dev = n * n.transpose() - Mat3::Identity() / 3.0;
    const double fn = f.force_j.dot(n);
    EXPECT_NEAR((f.stresslet_i + a_i * fn * dev).norm(), 0.0, 1e-4 * a_i * std::abs(fn)) << "lambda " << lambda;
    EXPECT_NEAR((f.stresslet_j + a_j * fn * dev).norm(), 0.0, 1e-4 * a_j * std::abs(fn)) << "lambda " << lambda;
  }
}

TEST(PairLubrication, SaturationRegularisationAndTruncation) {
  const PairLubrication law(1.0, 2.0, params(0.01, 0.3, 0.0));
  const Vec3 n(0.0, 0.0, 1.0);
  // Below the inner cutoff the resistance saturates: equal at h = 0.01, 0.001 and at an overlap h = -0.05.
  const Matrix12 at_cutoff = law.resistance(n, 0.01);
  EXPECT_EQ((law.resistance(n, 0.001) - at_cutoff).norm(), 0.0);
  EXPECT_EQ((law.resistance(n, -0.05) - at_cutoff).norm(), 0.0);
  EXPECT_DOUBLE_EQ(law.scaled_gap(-0.05), 2.0 * 0.01 / 3.0);
  // Above it the resistance falls with the gap; beyond the outer cutoff it is exactly zero.
  EXPECT_LT(law.resistance(n, 0.1)(2, 2), at_cutoff(2, 2));
  EXPECT_GT(law.resistance(n, 0.3)(2, 2), 0.0);
  EXPECT_EQ(law.resistance(n, 0.3000001).norm(), 0.0);
  EXPECT_FALSE(law.active(0.31));
  EXPECT_EQ(law.strain_forces(n, 0.31, Mat3::Identity(), Mat3::Identity()).norm(), 0.0);
  // The regularisation epsilon is added to xi: at contact the law equals the unregularised one at xi = epsilon.
  const PairLubrication reg(1.0, 2.0, params(0.0, 0.3, 0.002));
  const PairLubrication plain(1.0, 2.0, params(1e-9, 0.3, 0.0));
  EXPECT_NEAR((reg.resistance(n, 0.0) - plain.resistance(n, 0.002 * 3.0 / 2.0)).norm(), 0.0,
              1e-12 * reg.resistance(n, 0.0).norm());
}

TEST(PairLubrication, ParametersAreValidated) {
  EXPECT_NO_THROW(LubricationParams{}.validate());
  EXPECT_THROW(params(0.0, 0.3, 0.0).validate(), InputError);  // nothing keeps an overlapping pair finite
  EXPECT_THROW(params(0.3, 0.1, 0.0).validate(), InputError);  // outer below inner
  EXPECT_THROW(params(-0.1, 0.3, 0.0).validate(), InputError);
  EXPECT_THROW(params(0.0, 0.3, -1.0).validate(), InputError);
  EXPECT_THROW(PairLubrication(0.0, 1.0, LubricationParams{}), InputError);
  EXPECT_THROW(PairLubrication(1.0, 1.0, params(1e-3, 1.0, 0.0)), InputError);  // xi_out = 1: ln(1/xi) = 0
  EXPECT_NO_THROW(PairLubrication(1.0, 1.0, params(1e-3, 0.9, 0.0)));
}

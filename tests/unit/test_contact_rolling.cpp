// Rolling resistance (paper 000 Appendix B): u_r = a_ij (n x omega_i - n x omega_j), T_i = a_ij n x k_r xi_r,
// T_j = -T_i, |k_r xi_r| <= mu_r |F_n|. Checks the sign (the torque opposes the relative rotation), the analytic
// torque, that sliding contacts and rigid rotations load no rolling spring, and the Coulomb-like cap.
#include <gtest/gtest.h>

#include <random>

#include "contact_test_support.hpp"
#include "dem/contact/contact_model.hpp"

using namespace suspend;
using namespace suspend::test;

namespace {
LinearSpringCoulombRolling law(double kr, double mu_r) {
  LinearSpringCoulombRolling l;
  l.normal.p = {1.0e4};
  l.kt = 2.0e3;
  l.friction.p.mu = 1.0;
  l.rolling.p = {kr, mu_r};
  l.validate();
  return l;
}
}  // namespace

TEST(Rolling, CounterRotatingSpheresRollWithoutSlipAndFeelTheAnalyticTorque) {
  // Equal unit spheres on x, omega_i = +w z, omega_j = -w z: the surfaces move together (no slip) and the pair
  // rolls. a_ij = 1, u_r = n x (omega_i - omega_j) = x x 2w z = -2w y, so after N steps xi_r = -2 w N dt y and
  // T_i = n x k_r xi_r = -2 k_r w N dt z, opposing omega_i; T_j = -T_i opposes omega_j.
  const double kr = 100.0, w = 0.5, dt = 1e-3;
  const auto l = law(kr, 10.0);
  const PairGeometry g = PairGeometry::from(Vec3(1.99, 0.0, 0.0), 1.0, 1.0);
  const RelativeMotion m{Vec3::Zero(), Vec3::Zero(), Vec3(0.0, 0.0, w), Vec3(0.0, 0.0, -w)};
  PairHistory h;
  PairForce f;
  for (int s = 0; s < 20; ++s) f = l(g, m, dt, h);
  EXPECT_LT(f[Contribution::contact_tangential].norm(), 1e-12);  // rolling is not sliding
  EXPECT_NEAR(f.torque_i.z(), -2.0 * kr * w * 20 * dt, 1e-12);
  EXPECT_NEAR(f.torque_j.z(), 2.0 * kr * w * 20 * dt, 1e-12);
  EXPECT_NEAR(h.rolling_stretch.y(), -2.0 * w * 20 * dt, 1e-15);
  EXPECT_LT(f.torque_i.z() * m.omega_i.z(), 0.0);
  EXPECT_LT(f.torque_j.z() * m.omega_j.z(), 0.0);
}

TEST(Rolling, ReducedRadiusOfUnequalSpheres) {
  const double kr = 100.0, dt = 1e-3, a_ij = 2.0 * 1.0 * 1.4 / 2.4;
  const auto l = law(kr, 10.0);
  const PairGeometry g = PairGeometry::from(Vec3(0.0, 0.0, 2.39), 1.0, 1.4);
  const RelativeMotion m{Vec3::Zero(), Vec3::Zero(), Vec3(1.0, 0.0, 0.0), Vec3::Zero()};
  // The rolling part alone (omega_i also makes the contact slide, which the full law adds on top).
  PairForce f;
  Vec3 xi_r = Vec3::Zero();
  l.rolling.apply(g, m, 1.0e4 * 0.01, dt, xi_r, f);
  // u_r = a_ij z x x = a_ij y; T_i = a_ij z x (k_r a_ij dt y) = -k_r a_ij^2 dt x.
  EXPECT_NEAR(f.torque_i.x(), -kr * a_ij * a_ij * dt, 1e-12);
  EXPECT_LT((f.torque_i + f.torque_j).norm(), 1e-15);
  EXPECT_EQ(f.total_on_j().norm(), 0.0);  // a pseudo-force: torques only
}

TEST(Rolling, RigidRotationLoadsNoRollingSpring) {
  const auto l = law(100.0, 10.0);
  const Vec3 Omega(0.3, -0.2, 0.9);
  const Vec3 d(1.2, 1.9, -0.3);
  const PairGeometry g = PairGeometry::from(d.normalized() * 2.385, 1.0, 1.4);
  const RelativeMotion m{Vec3::Zero(), Omega.cross(g.d), Omega, Omega};
  PairHistory h;
  const PairForce f = l(g, m, 1e-2, h);
  EXPECT_EQ(h.rolling_stretch.norm(), 0.0);
  EXPECT_LT(h.tangential_stretch.norm(), 1e-16);
  EXPECT_LT(f.torque_i.norm(), 1e-12);
}

TEST(Rolling, TorqueOpposesAnyRelativeRotationFromRest) {
  const auto l = law(100.0, 10.0);
  std::mt19937_64 rng(31);
  for (int trial = 0; trial < 100; ++trial) {
    const PairGeometry g = PairGeometry::from(2.385 * random_vector(rng).normalized(), 1.0, 1.4);
    const Vec3 wi = random_vector(rng), wj = random_vector(rng);
    // Only rotations: the tangential spring is loaded too, so isolate rolling with the pseudo-force alone.
    PairForce f;
    Vec3 xi_r = Vec3::Zero();
    l.rolling.apply(g, {Vec3::Zero(), Vec3::Zero(), wi, wj}, 1.0e4 * 0.015, 1e-3, xi_r, f);
    EXPECT_LE(f.torque_i.dot(wi - wj), 1e-15);  // power of the rolling torques, T_i . (w_i - w_j) <= 0
    EXPECT_LT((f.torque_i + f.torque_j).norm(), 1e-15);
    EXPECT_LT(std::abs(f.torque_i.dot(g.n)), 1e-15);  // a rolling torque, no twisting
  }
}

TEST(Rolling, RollingTorqueSaturatesAtMuRTimesNormalForce) {
  const double kr = 100.0, mu_r = 0.01, w = 5.0;
  const auto l = law(kr, mu_r);
  const PairGeometry g = PairGeometry::from(Vec3(1.99, 0.0, 0.0), 1.0, 1.0);
  const RelativeMotion m{Vec3::Zero(), Vec3::Zero(), Vec3(0.0, 0.0, w), Vec3(0.0, 0.0, -w)};
  PairHistory h;
  PairForce f;
  for (int s = 0; s < 100; ++s) f = l(g, m, 1e-3, h);  // k_r 2 w t = 100 >> mu_r F_n = 1
  const double fn = 1.0e4 * 0.01;
  EXPECT_NEAR(f.torque_i.z(), -mu_r * fn, 1e-12);  // a_ij = 1
  EXPECT_NEAR(kr * h.rolling_stretch.norm(), mu_r * fn, 1e-12);
  EXPECT_NEAR(power(f, m), -mu_r * fn * 2.0 * w, 1e-9);  // all the rolling work is dissipated
}

TEST(Rolling, ResultRotatesWithThePair) {
  const auto l = law(100.0, 0.05);
  std::mt19937_64 rng(32);
  for (int trial = 0; trial < 30; ++trial) {
    const Mat3 R = random_rotation(rng);
    const Vec3 d = 2.385 * random_vector(rng).normalized();
    const RelativeMotion m{random_vector(rng), random_vector(rng), random_vector(rng), random_vector(rng)};
    PairHistory h{random_vector(rng, 1e-3), random_vector(rng, 1e-2), true};
    PairHistory h_rot = rotated(R, h);
    const PairGeometry g = PairGeometry::from(d, 1.0, 1.4);
    const PairForce f = l(g, m, 1e-3, h);
    const PairForce f_rot = l(PairGeometry::from(R * d, 1.0, 1.4), rotated(R, m), 1e-3, h_rot);
    EXPECT_LT((R * f.torque_i - f_rot.torque_i).norm(), 1e-9);
    EXPECT_LT((R * f.torque_j - f_rot.torque_j).norm(), 1e-9);
    EXPECT_LT((R * h.rolling_stretch - h_rot.rolling_stretch).norm(), 1e-14);
    EXPECT_LT(angular_momentum_residual(g, f).norm(), 1e-11);
  }
}

// Linear spring-dashpot + Coulomb stick/slide (paper 000 eqs. 4-5): analytic two-sphere values, Newton's third law,
// angular momentum balance, energy gradient, dashpot dissipation, the Coulomb switch, frame invariance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact_test_support.hpp"
#include "dem/contact/contact_model.hpp"

using namespace suspend;
using namespace suspend::test;

namespace {
LinearSpringCoulomb law(double kn, double kt, double gamma_n, double mu) {
  LinearSpringCoulomb l;
  l.normal.p = {kn};
  l.kt = kt;
  l.damping = NormalDamping::viscous(gamma_n);  // paper 000 eq. 4a's dashpot
  l.friction.p.mu = mu;
  l.validate();
  return l;
}
RelativeMotion at_rest() { return {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}; }
}  // namespace

TEST(LinearSpring, NormalForceIsKnTimesOverlapOnJAlongN) {
  const auto l = law(1.0e4, 2.0e3, 0.0, 1.0);
  const PairGeometry g = PairGeometry::from(Vec3(2.39, 0.0, 0.0), 1.0, 1.4);  // overlap 0.01
  PairHistory h;
  const PairForce f = l(g, at_rest(), 1e-3, h);
  EXPECT_NEAR(f[Contribution::contact_normal].x(), 1.0e4 * 0.01, 1e-9);
  EXPECT_EQ(f[Contribution::contact_normal].tail<2>().norm(), 0.0);
  EXPECT_EQ(f[Contribution::contact_tangential].norm(), 0.0);
  EXPECT_EQ(f.torque_i.norm() + f.torque_j.norm(), 0.0);
  EXPECT_TRUE(h.in_contact);
}

TEST(LinearSpring, NoForceAndHistoryResetOnceApart) {
  const auto l = law(1.0e4, 2.0e3, 1.0, 1.0);
  PairHistory h{Vec3(0.0, 1e-3, 0.0), Vec3(0.0, 0.0, 1e-3), true};
  const RelativeMotion m{Vec3::Zero(), Vec3(-1.0, 0.5, 0.0), Vec3::Zero(), Vec3::Zero()};
  const PairForce f = l(PairGeometry::from(Vec3(2.0 + 1e-12, 0.0, 0.0), 1.0, 1.0), m, 1e-3, h);
  EXPECT_EQ(f.total_on_j().norm(), 0.0);
  EXPECT_FALSE(h.in_contact);
  EXPECT_EQ(h.tangential_stretch.norm(), 0.0);
}

TEST(LinearSpring, DashpotAddsGammaTimesApproachSpeed) {
  const double kn = 1.0e4, gamma_n = 3.0, v = 0.7;
  const auto l = law(kn, 2.0e3, gamma_n, 1.0);
  const PairGeometry g = PairGeometry::from(Vec3(0.0, 1.99, 0.0), 1.0, 1.0);
  PairHistory h;
  const RelativeMotion m{Vec3::Zero(), Vec3(0.0, -v, 0.0), Vec3::Zero(), Vec3::Zero()};  // j approaches i
  const PairForce f = l(g, m, 1e-3, h);
  EXPECT_NEAR(f[Contribution::contact_normal].y(), kn * 0.01 + gamma_n * v, 1e-9);
}

TEST(LinearSpring, DashpotNeverDoesPositiveWork) {
  const double kn = 1.0e4, gamma_n = 3.0;
  const auto l = law(kn, 2.0e3, gamma_n, 0.0);  // frictionless: only spring and dashpot
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 n = random_vector(rng).normalized();
    const PairGeometry g = PairGeometry::from(1.995 * n, 1.0, 1.0);
    const RelativeMotion m{random_vector(rng), random_vector(rng), random_vector(rng), random_vector(rng)};
    PairHistory h;
    const PairForce f = l(g, m, 1e-3, h);
    const Vec3 dashpot = f[Contribution::contact_normal] - kn * 0.005 * g.n;
    const double p = dashpot.dot(m.u_j - m.u_i);
    EXPECT_LE(p, 1e-12);
    EXPECT_NEAR(p, -gamma_n * std::pow((m.u_j - m.u_i).dot(n), 2), 1e-9);
  }
}

TEST(LinearSpring, ElasticNormalForceIsMinusEnergyGradient) {
  const auto l = law(1.0e4, 2.0e3, 0.0, 1.0);
  for (double r : {2.38, 2.39, 2.3995}) {
    const Vec3 n(0.3, -0.4, std::sqrt(0.75));
    PairHistory h;
    const PairForce f = l(PairGeometry::from(r * n, 1.0, 1.4), at_rest(), 1e-3, h);
    EXPECT_NEAR(f[Contribution::contact_normal].dot(n), numerical_normal_force(l, r, 1.0, 1.4), 1e-5);
  }
}

TEST(LinearSpring, StickingSpringIntegratesTheSlip) {
  // Equal unit spheres along x, overlap 0.01, j slides along y at V: after N steps xi = N V dt and F_t = -k_t xi.
  const double kt = 2.0e3, V = 0.3, dt = 1e-4;
  const auto l = law(1.0e4, kt, 0.0, 1.0);  // mu F_n = 100, far above the spring force reached
  const PairGeometry g = PairGeometry::from(Vec3(1.99, 0.0, 0.0), 1.0, 1.0);
  const RelativeMotion m{Vec3::Zero(), Vec3(0.0, V, 0.0), Vec3::Zero(), Vec3::Zero()};
  PairHistory h;
  PairForce f;
  for (int step = 0; step < 10; ++step) f = l(g, m, dt, h);
  const double ft = -kt * 10 * V * dt;
  EXPECT_NEAR(f[Contribution::contact_tangential].y(), ft, 1e-12);
  EXPECT_NEAR(h.tangential_stretch.y(), 10 * V * dt, 1e-15);
  // Torques at the contact point r/2 from each centre (paper 000 eq. 4d-4e with l_i = l_j = r/2).
  EXPECT_NEAR(f.torque_i.z(), -(1.99 / 2) * ft, 1e-12);  // (l n) x (-F_t): x cross (-ft y) = -ft z
  EXPECT_NEAR(f.torque_j.z(), -(1.99 / 2) * ft, 1e-12);
}

TEST(LinearSpring, StickToSlipSwitchesExactlyAtTheCoulombLimit) {
  // Exact binary numbers: k = 2, slip 0.5 in one step -> trial force 1.
  const Vec3 n(1.0, 0.0, 0.0), u(0.0, 0.5, 0.0);
  Vec3 xi = Vec3::Zero();
  StickSlideResult s = stick_slide(xi, n, u, 1.0, 2.0, 1.0);  // |F| == limit: still sticking
  EXPECT_FALSE(s.sliding);
  EXPECT_EQ(s.force_on_j, Vec3(0.0, -1.0, 0.0));
  EXPECT_EQ(xi, Vec3(0.0, 0.5, 0.0));
  xi.setZero();
  s = stick_slide(xi, n, u, 1.0, 2.0, 0.75);  // limit below the trial force: slides at the limit
  EXPECT_TRUE(s.sliding);
  EXPECT_EQ(s.force_on_j, Vec3(0.0, -0.75, 0.0));
  EXPECT_EQ(xi, Vec3(0.0, 0.375, 0.0));  // the stretch of a spring at the limit
}

TEST(LinearSpring, ASlipAcrossTheWholeElasticRangeSticksWhereTheSpringUnloaded) {
  // k = 2, limit 1: the stored stretch (0, 0.5) is at the limit. Exact binary numbers throughout.
  const Vec3 n(1.0, 0.0, 0.0);
  // A reversal the step resolves (slip 0.25 < 2 limit / k = 1): the spring unloads and sticks where the slip left it.
  Vec3 xi(0.0, 0.5, 0.0);
  StickSlideResult s = stick_slide(xi, n, Vec3(0.0, -0.25, 0.0), 1.0, 2.0, 1.0);
  EXPECT_FALSE(s.sliding);
  EXPECT_EQ(xi, Vec3(0.0, 0.25, 0.0));
  // A slip of 3 across the range (2 F_max / k = 1): the trial stretch (0, -2.5) points against the stored one. Not
  // a slide at the limit the other way round, but a stick at the smallest stretch along the path: (0, 0, 0).
  xi = Vec3(0.0, 0.5, 0.0);
  s = stick_slide(xi, n, Vec3(0.0, -3.0, 0.0), 1.0, 2.0, 1.0);
  EXPECT_FALSE(s.sliding);
  EXPECT_EQ(xi, Vec3::Zero());
  EXPECT_EQ(s.force_on_j, Vec3::Zero());
  // An oblique slip across the range keeps the part of the stretch across it: from (0, 0.5, 0) by (0, -2, 2), the
  // path's closest point to zero, where the force is below the limit.
  xi = Vec3(0.0, 0.5, 0.0);
  s = stick_slide(xi, n, Vec3(0.0, -2.0, 2.0), 1.0, 2.0, 1.0);
  EXPECT_FALSE(s.sliding);
  EXPECT_NEAR(xi.y(), 0.25, 1e-15);  // start - (start.slip / |slip|^2) slip = (0, 0.5) - (-1 / 8) (-2, 2)
  EXPECT_NEAR(xi.z(), 0.25, 1e-15);
  EXPECT_LT(2.0 * xi.norm(), 1.0);
  // A sliding contact whose slip turns (no reversal: the trial stretch still points along the stored one) keeps
  // sliding at the limit in the trial's direction, as before.
  xi = Vec3(0.0, 0.5, 0.0);
  s = stick_slide(xi, n, Vec3(0.0, -0.25, 2.0), 1.0, 2.0, 1.0);
  EXPECT_TRUE(s.sliding);
  EXPECT_NEAR(s.force_on_j.norm(), 1.0, 1e-15);
  EXPECT_GT(xi.dot(Vec3(0.0, 0.5, 0.0)), 0.0);
}

TEST(LinearSpring, SlidingForceIsMuTimesNormalForceAndDissipatesMuFnV) {
  const double kn = 1.0e4, mu = 0.4, V = 2.0, dt = 1e-3;
  const auto l = law(kn, 2.0e3, 0.0, mu);
  const PairGeometry g = PairGeometry::from(Vec3(0.0, 0.0, 1.99), 1.0, 1.0);
  const RelativeMotion m{Vec3::Zero(), Vec3(V, 0.0, 0.0), Vec3::Zero(), Vec3::Zero()};
  PairHistory h;
  PairForce f;
  for (int step = 0; step < 100; ++step) f = l(g, m, dt, h);  // k_t V t = 400 >> mu F_n = 40
  const double fn = kn * 0.01;
  EXPECT_NEAR(f[Contribution::contact_tangential].norm(), mu * fn, 1e-10);
  EXPECT_NEAR(f[Contribution::contact_tangential].x(), -mu * fn, 1e-10);
  EXPECT_NEAR(h.tangential_stretch.norm(), mu * fn / 2.0e3, 1e-14);
  // All work of the frictional force and its torques is dissipated: P = -mu F_n V.
  PairForce tangential;
  tangential.add_tangential(g, f[Contribution::contact_tangential], Contribution::contact_tangential);
  EXPECT_NEAR(power(tangential, m), -mu * fn * V, 1e-9);
}

TEST(LinearSpring, ForceOnIIsMinusForceOnJWhenThePairIsListedTheOtherWay) {
  const auto l = law(1.0e4, 2.0e3, 2.0, 0.5);
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 n = random_vector(rng).normalized();
    const PairGeometry g = PairGeometry::from(2.39 * n, 1.0, 1.4);
    const PairGeometry g_swapped = PairGeometry::from(-2.39 * n, 1.4, 1.0);
    const RelativeMotion m{random_vector(rng), random_vector(rng), random_vector(rng), random_vector(rng)};
    const RelativeMotion m_swapped{m.u_j, m.u_i, m.omega_j, m.omega_i};
    PairHistory h{random_vector(rng, 1e-3), Vec3::Zero(), true};
    PairHistory h_swapped = h.swapped();
    const PairForce f = l(g, m, 1e-3, h);
    const PairForce f_swapped = l(g_swapped, m_swapped, 1e-3, h_swapped);
    for (std::size_t c = 0; c < contribution_count; ++c)
      EXPECT_LT((f.on_j[c] + f_swapped.on_j[c]).norm(), 1e-9 * (1.0 + f.on_j[c].norm()));
    EXPECT_LT((f.torque_i - f_swapped.torque_j).norm(), 1e-9);
    EXPECT_LT((f.torque_j - f_swapped.torque_i).norm(), 1e-9);
    EXPECT_LT((h.tangential_stretch - h_swapped.swapped().tangential_stretch).norm(), 1e-15);
  }
}

TEST(LinearSpring, TorquesBalanceTheAngularMomentumOfTheFrictionalForce) {
  const auto l = law(1.0e4, 2.0e3, 2.0, 0.5);
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 50; ++trial) {
    const PairGeometry g = PairGeometry::from(2.38 * random_vector(rng).normalized(), 1.0, 1.4);
    const RelativeMotion m{random_vector(rng), random_vector(rng), random_vector(rng), random_vector(rng)};
    PairHistory h{random_vector(rng, 1e-2), Vec3::Zero(), true};
    const PairForce f = l(g, m, 1e-3, h);
    EXPECT_GT(f[Contribution::contact_tangential].norm(), 0.0);
    EXPECT_LT(angular_momentum_residual(g, f).norm(), 1e-11);
  }
}

TEST(LinearSpring, RotatingThePairConfigurationRotatesTheResult) {
  const auto l = law(1.0e4, 2.0e3, 2.0, 0.5);
  std::mt19937_64 rng(13);
  for (int trial = 0; trial < 50; ++trial) {
    const Mat3 R = random_rotation(rng);
    const Vec3 d = 2.385 * random_vector(rng).normalized();
    const RelativeMotion m{random_vector(rng), random_vector(rng), random_vector(rng), random_vector(rng)};
    PairHistory h{random_vector(rng, 5e-3), Vec3::Zero(), true};
    PairHistory h_rot = rotated(R, h);
    const PairForce f = l(PairGeometry::from(d, 1.0, 1.4), m, 1e-3, h);
    const PairForce f_rot = l(PairGeometry::from(R * d, 1.0, 1.4), rotated(R, m), 1e-3, h_rot);
    for (std::size_t c = 0; c < contribution_count; ++c) EXPECT_LT((R * f.on_j[c] - f_rot.on_j[c]).norm(), 1e-9);
    EXPECT_LT((R * f.torque_i - f_rot.torque_i).norm(), 1e-9);
    EXPECT_LT((R * f.torque_j - f_rot.torque_j).norm(), 1e-9);
    EXPECT_LT((R * h.tangential_stretch - h_rot.tangential_stretch).norm(), 1e-14);
  }
}

TEST(LinearSpring, RigidRotationOfAnOverlappingPairLeavesTheSpringUnloaded) {
  // The pair spins as one body about z: the contact point does not slip, so a fresh contact builds no stretch and
  // an existing stretch keeps its length as it turns with the pair.
  const auto l = law(1.0e4, 2.0e3, 0.0, 1.0);
  const Vec3 Omega(0.0, 0.0, 1.0);
  const double dt = 1e-3, r = 2.38;
  PairHistory fresh, loaded{Vec3(0.0, 2e-3, 0.0), Vec3::Zero(), true};
  for (int step = 0; step < 500; ++step) {
    const double angle = step * dt;
    const Vec3 d = r * Vec3(std::cos(angle), std::sin(angle), 0.0);
    const RelativeMotion m{Vec3::Zero(), Omega.cross(d), Omega, Omega};
    l(PairGeometry::from(d, 1.0, 1.4), m, dt, fresh);
    l(PairGeometry::from(d, 1.0, 1.4), m, dt, loaded);
  }
  EXPECT_LT(fresh.tangential_stretch.norm(), 1e-15);
  EXPECT_NEAR(loaded.tangential_stretch.norm(), 2e-3, 1e-15);
  const Vec3 n_end(std::cos(499 * dt), std::sin(499 * dt), 0.0);
  EXPECT_LT(std::abs(loaded.tangential_stretch.dot(n_end)), 1e-15);
}

TEST(LinearSpring, RejectsNonPositiveStiffness) {
  LinearSpringCoulomb l;
  l.normal.p.kn = 0.0;
  EXPECT_THROW(l.validate(), InputError);
  l.normal.p.kn = 1.0;
  l.friction.p.mu = -1.0;
  EXPECT_THROW(l.validate(), InputError);
}

// Critical-load friction (paper 002 section 3.2; Seto et al. 2013): frictionless while F_n < F_CL, otherwise
// |F_t| <= mu (F_n - F_CL), reached exactly when sliding.
#include <gtest/gtest.h>

#include <random>

#include "contact_test_support.hpp"
#include "dem/contact/contact_model.hpp"

using namespace suspend;
using namespace suspend::test;

namespace {
LinearSpringCriticalLoad law(double mu, double f_cl) {
  LinearSpringCriticalLoad l;
  l.normal.p = {1.0e4};
  l.kt = 2.0e3;
  l.friction.p = {mu, f_cl};
  l.validate();
  return l;
}
// Equal unit spheres along x with overlap delta (F_n = 1e4 delta), j sliding along z at speed V.
PairForce slide(const LinearSpringCriticalLoad& l, double delta, double V, int steps, PairHistory& h) {
  const PairGeometry g = PairGeometry::from(Vec3(2.0 - delta, 0.0, 0.0), 1.0, 1.0);
  const RelativeMotion m{Vec3::Zero(), Vec3(0.0, 0.0, V), Vec3::Zero(), Vec3::Zero()};
  PairForce f;
  for (int s = 0; s < steps; ++s) f = l(g, m, 1e-3, h);
  return f;
}
}  // namespace

TEST(CriticalLoad, FrictionlessBelowTheCriticalLoad) {
  const auto l = law(1.0, 50.0);
  PairHistory h;
  const PairForce f = slide(l, 0.004, 1.0, 200, h);  // F_n = 40 < F_CL = 50
  EXPECT_EQ(f[Contribution::contact_tangential].norm(), 0.0);
  EXPECT_EQ(f.torque_i.norm() + f.torque_j.norm(), 0.0);
  EXPECT_EQ(h.tangential_stretch.norm(), 0.0);
  EXPECT_NEAR(f[Contribution::contact_normal].x(), 40.0, 1e-9);
}

TEST(CriticalLoad, ThresholdItselfCarriesNoFriction) {
  const CriticalLoadFriction c{{0.7, 50.0}};
  EXPECT_EQ(c.limit(50.0), 0.0);
  EXPECT_EQ(c.limit(-10.0), 0.0);
  EXPECT_DOUBLE_EQ(c.limit(60.0), 0.7 * 10.0);
}

TEST(CriticalLoad, AboveTheLoadFrictionIsCappedAtMuTimesExcessLoad) {
  const double mu = 0.5, f_cl = 50.0;
  const auto l = law(mu, f_cl);
  PairHistory h;
  for (int steps = 1; steps <= 200; ++steps) {
    PairHistory h_n;
    const PairForce f = slide(l, 0.008, 1.0, steps, h_n);  // F_n = 80
    EXPECT_LE(f[Contribution::contact_tangential].norm(), mu * (80.0 - f_cl) * (1.0 + 1e-12));
  }
  const PairForce f = slide(l, 0.008, 1.0, 200, h);  // k_t V t = 400 >> 15: sliding
  EXPECT_NEAR(f[Contribution::contact_tangential].z(), -mu * (80.0 - f_cl), 1e-10);
}

TEST(CriticalLoad, UnloadingBelowTheThresholdReleasesTheSpring) {
  const auto l = law(0.5, 50.0);
  PairHistory h;
  slide(l, 0.008, 1.0, 5, h);  // sticking above F_CL: stretch 5e-3
  EXPECT_NEAR(h.tangential_stretch.z(), 5e-3, 1e-15);
  const PairForce f = slide(l, 0.003, 0.0, 1, h);  // load drops to 30 < 50
  EXPECT_EQ(f[Contribution::contact_tangential].norm(), 0.0);
  EXPECT_EQ(h.tangential_stretch.norm(), 0.0);
  EXPECT_TRUE(h.in_contact);
}

TEST(CriticalLoad, TorquesBalanceAndResultRotatesWithThePair) {
  const auto l = law(0.5, 20.0);
  std::mt19937_64 rng(21);
  for (int trial = 0; trial < 30; ++trial) {
    const Mat3 R = random_rotation(rng);
    const Vec3 d = 2.39 * random_vector(rng).normalized();
    const RelativeMotion m{random_vector(rng), random_vector(rng), random_vector(rng), random_vector(rng)};
    PairHistory h{random_vector(rng, 1e-2), Vec3::Zero(), true};
    PairHistory h_rot = rotated(R, h);
    const PairGeometry g = PairGeometry::from(d, 1.0, 1.4);
    const PairForce f = l(g, m, 1e-3, h);
    const PairForce f_rot = l(PairGeometry::from(R * d, 1.0, 1.4), rotated(R, m), 1e-3, h_rot);
    EXPECT_LT(angular_momentum_residual(g, f).norm(), 1e-11);
    EXPECT_LT((R * f.total_on_j() - f_rot.total_on_j()).norm(), 1e-9);
    EXPECT_LT((R * f.torque_i - f_rot.torque_i).norm(), 1e-9);
  }
}

TEST(CriticalLoad, RejectsNegativeThreshold) {
  EXPECT_THROW((CriticalLoadFriction{{0.5, -1.0}}.validate()), InputError);
}

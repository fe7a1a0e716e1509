// JKR adhesion with hysteresis (dem/contact/jkr_adhesion.hpp) against Johnson, Kendall & Roberts (1971): a pair
// pulled apart quasi-statically bonds at touching with F = -(4/3) pi W R*, holds through tension, peaks at the
// pull-off force (3/2) pi W R* and snaps at delta_c = -(3/4) (pi^2 W^2 R* / E*^2)^(1/3) with F = -(5/6) pi W R*;
// approaching again it feels nothing until the surfaces touch. The force is the derivative of the branch's energy,
// W = 0 is Hertz, and the composed model keeps the bond in the pair history without a friction law.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact_test_support.hpp"
#include "dem/contact/contact_law.hpp"

using namespace suspend;
using namespace suspend::test;
using std::numbers::pi;

namespace {
const Vec3 axis = Vec3(0.3, -0.4, std::sqrt(0.75));

// F_n (positive = repulsive) of the pair at overlap delta, updating its history.
double normal_force(const JkrAdhesion& law, double delta, double a_i, double a_j, PairHistory& h) {
  const PairGeometry g = PairGeometry::from((a_i + a_j - delta) * axis, a_i, a_j);
  PairForce f;
  const NormalContact c = law.apply(g, RelativeMotion{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}, f, h);
  return c.active ? c.force + f.total_on_j().dot(g.n) : 0.0;  // the Hertz part, and the adhesion it wrote
}

struct Sweep {
  double bond_force = 0.0, min_force = 0.0, last_bonded = 0.0, force_before_snap = 0.0;
};

// Approach from a gap to delta_max, then retract until the bond snaps, in steps of `step`.
Sweep pull_off(const JkrAdhesion& law, double a_i, double a_j, double step) {
  Sweep s;
  PairHistory h;
  double delta = -0.01;
  for (; delta < 0.0; delta += step) EXPECT_EQ(normal_force(law, delta, a_i, a_j, h), 0.0) << delta;
  s.bond_force = normal_force(law, 0.0, a_i, a_j, h);
  for (delta = 0.0; delta < 2e-3; delta += step) normal_force(law, delta, a_i, a_j, h);
  for (; delta > -0.02; delta -= step) {
    const double f = normal_force(law, delta, a_i, a_j, h);
    if (!(h.normal_state > 0.0)) break;
    s.min_force = std::min(s.min_force, f);
    s.last_bonded = delta;
    s.force_before_snap = f;
  }
  // Re-approach: nothing until touching.
  for (delta -= step; delta < -step; delta += step) EXPECT_EQ(normal_force(law, delta, a_i, a_j, h), 0.0) << delta;
  return s;
}
}  // namespace

TEST(ContactJkr, PullOffForceAndSeparationAreJohnsonKendallRoberts) {
  const double e = 1.0e4, w = 2.0, step = 1e-7;
  const JkrAdhesion law(JkrParams{e, w});
  for (const auto& [a_i, a_j] : {std::pair{1.0, 1.0}, std::pair{1.0, 1.4}}) {
    const double r = a_i * a_j / (a_i + a_j);
    const double delta_c = -0.75 * std::cbrt(pi * pi * w * w * r / (e * e));
    const Sweep s = pull_off(law, a_i, a_j, step);
    std::cout << "R* " << r << ": bond " << s.bond_force << ", pull-off " << -s.min_force << " (JKR "
              << 1.5 * pi * w * r << "), snap at delta " << s.last_bonded << " (JKR " << delta_c << ")\n";
    EXPECT_NEAR(s.bond_force, -4.0 / 3.0 * pi * w * r, 1e-9 * pi * w * r);
    EXPECT_NEAR(-s.min_force, 1.5 * pi * w * r, 1e-6 * pi * w * r);
    EXPECT_NEAR(s.last_bonded, delta_c, step * 1.0001);
    EXPECT_NEAR(law.snap_overlap(r), delta_c, 1e-15);
    // The force-separation curve is vertical at the snap: within one step of it, F is within 1% of -(5/6) pi W R*.
    EXPECT_NEAR(s.force_before_snap, -5.0 / 6.0 * pi * w * r, 0.01 * pi * w * r);
  }
}

TEST(ContactJkr, ForceIsTheDerivativeOfTheBranchEnergyAndWithoutAdhesionIsHertz) {
  const JkrAdhesion law(JkrParams{1.0e4, 2.0});
  for (double delta : {-3e-3, -1e-3, 0.0, 2e-3, 1e-2}) {
    PairHistory bonded{Vec3::Zero(), Vec3::Zero(), true, 1.0};
    const double f = normal_force(law, delta, 1.0, 1.4, bonded);
    const double fe = numerical_normal_force(law, 2.4 - delta, 1.0, 1.4, 1e-8);
    EXPECT_NEAR(f, fe, 1e-5 * std::max(1.0, std::abs(f))) << delta;
    // (the overlap the geometry gives differs from delta in the last digits)
    EXPECT_NEAR(bonded.normal_state, law.contact_radius(delta, 1.4 / 2.4), 1e-12 * bonded.normal_state);
  }
  const JkrAdhesion hertz(JkrParams{1.0e4, 0.0});
  for (double delta : {1e-4, 1e-3, 1e-2}) {
    PairHistory h;
    const double r = 0.5;
    EXPECT_NEAR(normal_force(hertz, delta, 1.0, 1.0, h), 4.0 / 3.0 * 1.0e4 * std::sqrt(r) * std::pow(delta, 1.5),
                1e-10 * 1.0e4 * std::pow(delta, 1.5));
    EXPECT_EQ(normal_force(hertz, -1e-6, 1.0, 1.0, h), 0.0);  // no adhesion, no neck
  }
}

TEST(ContactJkr, TheComposedModelKeepsTheBondInThePairHistory) {
  ContactModel<JkrAdhesion> model{JkrAdhesion(JkrParams{1.0e4, 2.0})};
  static_assert(ContactModel<JkrAdhesion>::has_history);
  PairHistory h;
  auto at = [&](double gap) {
    const PairGeometry g = PairGeometry::from((2.0 + gap) * axis, 1.0, 1.0);
    return model(g, RelativeMotion{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}, 1e-3, h).total_on_j().dot(g.n);
  };
  EXPECT_EQ(at(1e-3), 0.0);  // apart
  EXPECT_LT(at(-1e-4), 0.0);  // touched: bonded, in tension at small overlap
  EXPECT_TRUE(h.in_contact);
  EXPECT_GT(h.normal_state, 0.0);
  EXPECT_LT(at(2e-3), 0.0);  // a neck at a positive gap holds
  EXPECT_TRUE(h.in_contact);
  EXPECT_EQ(at(5e-3), 0.0);  // past -delta_c = 4.4e-3: snapped, history released
  EXPECT_FALSE(h.in_contact);
  EXPECT_EQ(at(2e-3), 0.0);  // and no force at that gap any more
  EXPECT_THROW(JkrAdhesion(JkrParams{-1.0, 1.0}), InputError);
}

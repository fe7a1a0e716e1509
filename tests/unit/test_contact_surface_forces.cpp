// Electrostatic repulsion (paper 000 eq. 6) and van der Waals attraction (eq. 7): analytic values with the
// harmonic radius, plateau through overlap, cutoffs, energy gradients, contribution bookkeeping, and the paper 000
// table 3 ratio F^R/F^A = 19 at contact that our defaults encode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact_test_support.hpp"
#include "dem/contact/electrostatic_repulsion.hpp"
#include "dem/contact/surface_forces.hpp"
#include "dem/contact/van_der_waals.hpp"

using namespace suspend;
using namespace suspend::test;

namespace {
const double a_bar = 2.0 * 1.0 * 1.4 / 2.4;
PairGeometry at_gap(double h) { return PairGeometry::from(Vec3(0.0, 0.0, 2.4 + h), 1.0, 1.4); }
}  // namespace

TEST(Electrostatic, ScreenedRepulsionWithHarmonicRadius) {
  const ElectrostaticRepulsion e{{3.0, 0.02, 20.0}};
  const PairForce f = e(at_gap(0.02));
  EXPECT_NEAR(f[Contribution::repulsion].z(), 3.0 * a_bar * std::exp(-1.0), 1e-12);
  EXPECT_EQ(f.total_on_j().norm(), f[Contribution::repulsion].norm());  // nothing else, no torque
  EXPECT_EQ(f.torque_i.norm(), 0.0);
  EXPECT_NEAR(e(at_gap(-0.01))[Contribution::repulsion].z(), 3.0 * a_bar, 1e-12);  // eq. 6a, d < 0
  EXPECT_GT(e(at_gap(0.399))[Contribution::repulsion].z(), 0.0);
  EXPECT_EQ(e(at_gap(0.4001))[Contribution::repulsion].z(), 0.0);  // cut at 20 lambda_D
}

TEST(Electrostatic, ForceIsMinusEnergyGradient) {
  const ElectrostaticRepulsion e{{3.0, 0.02, 20.0}};
  for (double h : {-0.01, 0.001, 0.01, 0.05, 0.2}) {
    const double r = 2.4 + h;
    const Vec3 n(0.3, -0.4, std::sqrt(0.75));
    const double fn = e(PairGeometry::from(r * n, 1.0, 1.4))[Contribution::repulsion].dot(n);
    EXPECT_NEAR(fn, numerical_normal_force(e, r, 1.0, 1.4, 1e-7), 1e-6 * fn) << h;
  }
}

TEST(VanDerWaals, RegularisedAttractionWithHarmonicRadius) {
  const VanDerWaals v{{0.5, 0.01, 4.0}};
  const double eps = 0.01 * a_bar;
  EXPECT_NEAR(v(at_gap(0.0))[Contribution::adhesion].z(), -0.5 * a_bar / (12.0 * eps * eps), 1e-9);
  EXPECT_NEAR(v(at_gap(eps))[Contribution::adhesion].z(), -0.5 * a_bar / (24.0 * eps * eps), 1e-9);
  EXPECT_NEAR(v(at_gap(-0.1))[Contribution::adhesion].z(), -0.5 * a_bar / (12.0 * eps * eps), 1e-9);
  EXPECT_NEAR(v(at_gap(1.0))[Contribution::adhesion].z(), -0.5 * a_bar / (12.0 * (1.0 + eps * eps)), 1e-12);
  EXPECT_EQ(v(at_gap(4.001))[Contribution::adhesion].z(), 0.0);
  EXPECT_EQ(v(at_gap(1.0))[Contribution::repulsion].norm(), 0.0);
}

TEST(VanDerWaals, ForceIsMinusEnergyGradient) {
  const VanDerWaals v{{0.5, 0.01, 4.0}};
  for (double h : {-0.05, 0.0005, 0.005, 0.05, 1.0, 3.0}) {
    const double r = 2.4 + h;
    const Vec3 n(0.3, -0.4, std::sqrt(0.75));
    const double fn = v(PairGeometry::from(r * n, 1.0, 1.4))[Contribution::adhesion].dot(n);
    const double step = std::max(1e-8, 1e-4 * h);  // keep round-off of E(r +- step) below the tolerance
    EXPECT_NEAR(fn, numerical_normal_force(v, r, 1.0, 1.4, step), 1e-6 * std::abs(fn)) << h;
  }
}

TEST(SurfaceForces, DefaultsReproducePaper000RatioAtContact) {
  // Table 3: F^R / F^A = 19 for a pair at contact (equal unit spheres, a-bar = 1).
  const ElectrostaticRepulsion e;
  const VanDerWaals v;
  EXPECT_NEAR(e.magnitude(0.0, 1.0) / v.magnitude(0.0, 1.0), 19.0, 1e-12);
  EXPECT_DOUBLE_EQ(e.range(), 0.4);  // 20 lambda_D, paper 000 Fig. 3
}

TEST(SurfaceForces, SumOfOptionalPartsGoesToItsContributions) {
  SurfaceForces s;
  PairForce f;
  s.add_to(at_gap(0.01), f);
  EXPECT_EQ(f.total_on_j().norm(), 0.0);
  EXPECT_EQ(s.range(), 0.0);
  s.repulsion = ElectrostaticRepulsion{{2.0, 0.05, 20.0}};
  s.attraction = VanDerWaals{{0.1, 0.01, 4.0}};
  s.validate();
  const double h = at_gap(0.01).gap();
  s.add_to(at_gap(0.01), f);
  EXPECT_DOUBLE_EQ(f[Contribution::repulsion].z(), s.repulsion->magnitude(h, a_bar));
  EXPECT_DOUBLE_EQ(f[Contribution::adhesion].z(), -s.attraction->magnitude(h, a_bar));
  EXPECT_DOUBLE_EQ(s.range(), 4.0);
  // Stresslet of the repulsion: S = -sym(d F^T); a repulsive force gives a positive pressure -tr(S)/3 > 0.
  const Mat3 S = pair_stresslet(at_gap(0.01), f, Contribution::repulsion);
  EXPECT_NEAR(S(2, 2), -2.41 * f[Contribution::repulsion].z(), 1e-12);
  EXPECT_GT(-S.trace() / 3.0, 0.0);
}

TEST(SurfaceForces, RejectBadParameters) {
  EXPECT_THROW((ElectrostaticRepulsionParams{1.0, 0.0, 20.0}.validate()), InputError);
  EXPECT_THROW((VanDerWaalsParams{1.0, 0.0, 4.0}.validate()), InputError);
}

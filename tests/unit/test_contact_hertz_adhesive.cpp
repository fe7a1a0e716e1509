// Hertz + constant adhesion at a roughness height (paper 004 eqs. 14-18): analytic forces, zero-force compression
// delta_0 = (F_adh/k_n)^(2/3), pull-off force F_adh, eq. 18 stiffness, the slip threshold mu_s (F_n + F_adh)
// (= mu_s F_adh at zero load, paper 004 after eq. 16), energy gradient, third law, frame invariance, and the
// typical adhesive compression 4.6e-2 h_r quoted in paper 004 section II E 2 for Gamma-bar x G_adh = 0.9.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "contact_test_support.hpp"
#include "dem/contact/contact_model.hpp"

using namespace suspend;
using namespace suspend::test;

namespace {
constexpr double kPi = std::numbers::pi;
HertzAdhesiveParams simple() { return test::round_hertz_adhesive(); }
// Paper 004's contact: Hertz with constant adhesion F_adh and Coulomb friction mu_s = 0.5 (eq. 16).
HertzAdhesiveCoulomb hertz(const HertzAdhesiveParams& p, double f_adh = 2.0) {
  return {HertzAdhesive(p), {{0.5}}, {}, Adhesion::constant(f_adh)};
}
RelativeMotion at_rest() { return {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()}; }
// Equal unit spheres on the y axis at surface gap h.
PairGeometry at_gap(double h) { return PairGeometry::from(Vec3(0.0, 2.0 + h, 0.0), 1.0, 1.0); }
double normal_force(const HertzAdhesiveCoulomb& law, double h) {
  PairHistory hist;
  const PairForce f = law(at_gap(h), at_rest(), 1e-3, hist);
  return f.total_on_j().y();  // positive = repulsive
}
}  // namespace

TEST(HertzAdhesive, ContactStartsBelowTheRoughnessHeight) {
  const HertzAdhesiveCoulomb law = hertz(simple());
  PairHistory h;
  EXPECT_EQ(law(at_gap(0.0100001), at_rest(), 1e-3, h).total_on_j().norm(), 0.0);
  EXPECT_FALSE(h.in_contact);
  const PairForce f = law(at_gap(0.006), at_rest(), 1e-3, h);  // delta = 0.004
  EXPECT_TRUE(h.in_contact);
  EXPECT_NEAR(f[Contribution::contact_normal].y(), 1.0e5 * std::pow(0.004, 1.5), 1e-10);
  EXPECT_DOUBLE_EQ(f[Contribution::adhesion].y(), -2.0);
}

TEST(HertzAdhesive, ZeroForceCompressionAndPullOff) {
  const HertzAdhesiveCoulomb law = hertz(simple());
  const double delta0 = std::pow(2.0 / 1.0e5, 2.0 / 3.0);
  EXPECT_NEAR(law.normal.zero_force_compression(2.0), delta0, 1e-15);
  EXPECT_NEAR(normal_force(law, 0.01 - delta0), 0.0, 1e-12);
  EXPECT_LT(normal_force(law, 0.01 - 0.99 * delta0), 0.0);  // attractive below delta_0
  EXPECT_GT(normal_force(law, 0.01 - 1.01 * delta0), 0.0);
  // Pull-off: the largest tension the contact sustains is F_adh, reached as delta -> 0+.
  EXPECT_DOUBLE_EQ(law.adhesion.force(at_gap(0.0)), 2.0);
  double max_tension = 0.0;
  for (int k = 1; k <= 1000; ++k) max_tension = std::max(max_tension, -normal_force(law, 0.01 - k * 1e-8));
  EXPECT_NEAR(max_tension, 2.0, 1e-6);
  EXPECT_LE(max_tension, 2.0);
}

TEST(HertzAdhesive, TangentialStiffnessFollowsEq18) {
  const HertzAdhesiveCoulomb law = hertz(simple());
  EXPECT_NEAR(law.tangential_stiffness(), 2.0 / 7.0 * 1.0e5 * std::sqrt(0.05 * 0.01), 1e-9);
}

TEST(HertzAdhesive, SlipThresholdIsMuSTimesElasticForce) {
  const HertzAdhesiveCoulomb law = hertz(simple());
  const double delta0 = law.normal.zero_force_compression(2.0);
  const PairGeometry g = at_gap(0.01 - delta0);  // zero load: the paper's finite resistance mu_s F_adh
  const RelativeMotion m{Vec3::Zero(), Vec3(3.0, 0.0, 0.0), Vec3::Zero(), Vec3::Zero()};
  PairHistory h;
  PairForce f;
  for (int s = 0; s < 200; ++s) f = law(g, m, 1e-3, h);  // k_t V t = 3.8e3 * 0.6 >> 1
  EXPECT_NEAR(f[Contribution::contact_tangential].x(), -0.5 * 2.0, 1e-10);
  // Sticking: F_t = -k_t Y with Y the accumulated slip (eq. 15).
  PairHistory h2;
  const PairForce f2 = law(at_gap(0.005), m, 1e-6, h2);
  EXPECT_NEAR(f2[Contribution::contact_tangential].x(), -law.tangential_stiffness() * 3e-6, 1e-12);
}

TEST(HertzAdhesive, ForceIsMinusGradientOfEnergyIncludingTheSupplementaryRepulsion) {
  const HertzAdhesiveCoulomb law = hertz(simple());  // supplementary repulsion below h_s = 0.001
  for (double h : {0.009, 0.006, 0.002, 0.0008, 0.0002, -0.0005}) {
    const double r = 2.4 + h;
    const Vec3 n(0.3, -0.4, std::sqrt(0.75));
    PairHistory hist;
    const PairForce f = law(PairGeometry::from(r * n, 1.0, 1.4), at_rest(), 1e-3, hist);
    const double fn = f.total_on_j().dot(n);
    EXPECT_NEAR(fn, numerical_normal_force(law, r, 1.0, 1.4, 1e-8), 1e-5 * (1.0 + std::abs(fn))) << "gap " << h;
  }
}

TEST(HertzAdhesive, SupplementaryRepulsionActsOnlyNearHydrodynamicContact) {
  HertzAdhesiveParams p = simple();
  const HertzAdhesiveCoulomb law = hertz(p);
  p.repulsion_stiffness = 0.0;
  const HertzAdhesiveCoulomb plain = hertz(p);
  EXPECT_DOUBLE_EQ(normal_force(law, 0.0011), normal_force(plain, 0.0011));
  // At h = 0: k_s (h_s)^(3/2) extra, with k_s = 100 k_n and h_s = 0.1 h_r.
  EXPECT_NEAR(normal_force(law, 0.0) - normal_force(plain, 0.0), 100.0 * 1.0e5 * std::pow(0.001, 1.5), 1e-9);
}

TEST(HertzAdhesive, ForceOnIIsMinusForceOnJAndTorquesBalance) {
  const HertzAdhesiveCoulomb law = hertz(simple());
  std::mt19937_64 rng(41);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 n = random_vector(rng).normalized();
    const double r = 2.4 + 0.004;
    const PairGeometry g = PairGeometry::from(r * n, 1.0, 1.4);
    const PairGeometry g_swapped = PairGeometry::from(-r * n, 1.4, 1.0);
    const RelativeMotion m{random_vector(rng), random_vector(rng), random_vector(rng), random_vector(rng)};
    const RelativeMotion m_swapped{m.u_j, m.u_i, m.omega_j, m.omega_i};
    PairHistory h{random_vector(rng, 1e-4), Vec3::Zero(), true};
    PairHistory h_swapped = h.swapped();
    const PairForce f = law(g, m, 1e-4, h);
    const PairForce f_swapped = law(g_swapped, m_swapped, 1e-4, h_swapped);
    for (std::size_t c = 0; c < contribution_count; ++c)
      EXPECT_LT((f.on_j[c] + f_swapped.on_j[c]).norm(), 1e-9 * (1.0 + f.on_j[c].norm()));
    EXPECT_LT((f.torque_i - f_swapped.torque_j).norm(), 1e-9);
    EXPECT_LT(angular_momentum_residual(g, f).norm(), 1e-11);
  }
}

TEST(HertzAdhesive, RotatingThePairConfigurationRotatesTheResult) {
  const HertzAdhesiveCoulomb law = hertz(simple());
  std::mt19937_64 rng(42);
  for (int trial = 0; trial < 30; ++trial) {
    const Mat3 R = random_rotation(rng);
    const Vec3 d = 2.405 * random_vector(rng).normalized();
    const RelativeMotion m{random_vector(rng), random_vector(rng), random_vector(rng), random_vector(rng)};
    PairHistory h{random_vector(rng, 1e-4), Vec3::Zero(), true};
    PairHistory h_rot = rotated(R, h);
    const PairForce f = law(PairGeometry::from(d, 1.0, 1.4), m, 1e-4, h);
    const PairForce f_rot = law(PairGeometry::from(R * d, 1.0, 1.4), rotated(R, m), 1e-4, h_rot);
    for (std::size_t c = 0; c < contribution_count; ++c) EXPECT_LT((R * f.on_j[c] - f_rot.on_j[c]).norm(), 1e-9);
    EXPECT_LT((R * f.torque_j - f_rot.torque_j).norm(), 1e-9);
    EXPECT_LT((R * h.tangential_stretch - h_rot.tangential_stretch).norm(), 1e-14);
  }
}

TEST(HertzAdhesive, PaperGroupsGiveTheQuotedAdhesiveCompression) {
  // Paper 004 section II E 2: Gamma-bar x G_adh = 0.9 "implies that the typical asperity compression due to the
  // adhesive force alone is delta/h_r ~ 0.9 eps_bar ~ 4.6e-2" (exactly 0.9^(2/3) eps_bar = 4.66e-2).
  const HertzAdhesiveParams p = hertz_from_groups(0.09, 0.05, 5e-3);
  EXPECT_NEAR(p.kn, 6.0 * kPi / (0.09 * std::pow(0.05 * 5e-3, 1.5)), 1e-6 * p.kn);
  const Adhesion adhesion = Adhesion::constant_group(10.0);
  EXPECT_NEAR(adhesion.scale(), 60.0 * kPi, 1e-12);
  const HertzAdhesiveCoulomb law = hertz(p, adhesion.scale());
  EXPECT_NEAR(law.normal.zero_force_compression(adhesion.scale()) / 5e-3, 4.6e-2, 0.1e-2);
  EXPECT_NEAR(law.normal.zero_force_compression(adhesion.scale()) / 5e-3, std::pow(0.9, 2.0 / 3.0) * 0.05, 1e-12);
  EXPECT_NEAR(normal_force(law, 5e-3 - law.normal.zero_force_compression(adhesion.scale())), 0.0, 1e-9);
  // Defaults are the paper's set-up: Gamma-bar = 1, and this law's adhesion G_adh = 0.9.
  const HertzAdhesiveParams d;
  EXPECT_NEAR(6.0 * kPi / (d.kn * std::pow(d.eps_bar * d.roughness, 1.5)), 1.0, 1e-12);
  EXPECT_EQ(HertzAdhesive::default_adhesion, "constant");
  EXPECT_DOUBLE_EQ(HertzAdhesive::default_g_adh, 0.9);
}

TEST(HertzAdhesive, RejectsBadParameters) {
  HertzAdhesiveParams p = simple();
  p.roughness = 0.0;
  EXPECT_THROW(HertzAdhesive{p}, InputError);
  p = simple();
  p.repulsion_onset = 1.5;
  EXPECT_THROW(HertzAdhesive{p}, InputError);
  EXPECT_THROW(hertz_from_groups(0.0, 0.05, 5e-3), InputError);
}

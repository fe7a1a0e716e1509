// The sub-models that compose with every normal law (issue 38): damping, adhesion and twisting resistance, each
// against its exact or published form. Damping: the restitution coefficient of a linear spring-dashpot collision,
// e = exp(-pi zeta / sqrt(1 - zeta^2)) (the damped oscillator; Luding 2008 eq. 5), reached by the viscous model and
// by the viscoelastic one (Brilliantov et al. 1996, whose Hertz form -(3/2) A k_n sqrt(delta) v_n is checked too).
// Adhesion: the DMT pull-off force 2 pi W R* (Derjaguin, Muller & Toporov 1975), 4/3 of JKR's (3/2) pi W R* at the
// same W and R*, and the constant adhesion's zero-force overlap on a linear spring. Twisting: Luding 2008's torsion
// spring, its stick and slide, objectivity and the swap.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact_test_support.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact/jkr_adhesion.hpp"

using namespace suspend;
using std::numbers::pi;

namespace {
const Vec3 axis = Vec3(0.3, -0.4, std::sqrt(0.75));
PairGeometry at_overlap(double delta, double a_i = 1.0, double a_j = 1.0) {
  return PairGeometry::from((a_i + a_j - delta) * axis, a_i, a_j);
}
RelativeMotion separating(double v) { return {Vec3::Zero(), v * axis, Vec3::Zero(), Vec3::Zero()}; }
RelativeMotion spinning(const Vec3& omega_i, const Vec3& omega_j) {
  return {Vec3::Zero(), Vec3::Zero(), omega_i, omega_j};
}

// A head-on collision of a pair of reduced mass m at approach speed 1, integrated (RK4) with the law's normal force
// until the overlap returns to zero: the speed ratio out/in.
template <class Law>
double restitution(const Law& law, double m, double dt) {
  double delta = 0.0, rate = 1.0;  // d delta / dt = -v_n
  auto accel = [&](double d, double r) {
    PairHistory h;
    return -law(at_overlap(d), separating(-r), dt, h).total_on_j().dot(axis) / m;  // d rate / dt
  };
  for (int s = 0; s < 10000000; ++s) {
    const double k1d = rate, k1r = accel(delta, rate);
    const double k2d = rate + 0.5 * dt * k1r, k2r = accel(delta + 0.5 * dt * k1d, rate + 0.5 * dt * k1r);
    const double k3d = rate + 0.5 * dt * k2r, k3r = accel(delta + 0.5 * dt * k2d, rate + 0.5 * dt * k2r);
    const double k4d = rate + dt * k3r, k4r = accel(delta + dt * k3d, rate + dt * k3r);
    const double next = delta + dt / 6.0 * (k1d + 2 * k2d + 2 * k3d + k4d);
    const double next_rate = rate + dt / 6.0 * (k1r + 2 * k2r + 2 * k3r + k4r);
    if (s > 0 && next <= 0.0) {  // crossed zero within the step: interpolate the speed there
      const double w = delta / (delta - next);
      return -((1.0 - w) * rate + w * next_rate);
    }
    delta = next;
    rate = next_rate;
  }
  return NAN;
}
}  // namespace

TEST(NormalDamping, ViscousAndViscoelasticDashpotsGiveTheDampedOscillatorsRestitution) {
  const double kn = 1.0e4, m = 1.0, gamma = 40.0;  // zeta = gamma / (2 sqrt(m k)) = 0.2
  const double zeta = gamma / (2.0 * std::sqrt(m * kn)), exact = std::exp(-pi * zeta / std::sqrt(1.0 - zeta * zeta));
  ContactModel<SoftRepulsion> viscous{SoftRepulsion{{kn}}};
  viscous.damping = NormalDamping::viscous(gamma);
  ContactModel<SoftRepulsion> viscoelastic{SoftRepulsion{{kn}}};
  viscoelastic.damping = NormalDamping::viscoelastic(gamma / kn);  // A k_n = gamma_n on a linear spring
  const double period = pi / std::sqrt(kn / m);
  // The first and last steps straddle the contact's ends, where the force jumps by gamma v: an O(dt) error.
  EXPECT_NEAR(restitution(viscous, m, period * 1e-5), exact, 3e-6);
  EXPECT_NEAR(restitution(viscoelastic, m, period * 1e-5), exact, 3e-6);
  EXPECT_NEAR(exact, 0.52662, 1e-5);
  const ContactModel<SoftRepulsion> elastic{SoftRepulsion{{kn}}};
  EXPECT_NEAR(restitution(elastic, m, period * 1e-5), 1.0, 1e-9);
}

TEST(NormalDamping, ViscoelasticHertzIsBrilliantovsForm) {
  HertzAdhesiveParams p = test::round_hertz_adhesive();
  p.repulsion_stiffness = 0.0;
  ContactModel<HertzAdhesive> law{HertzAdhesive(p)};
  const double time = 2e-3, v = 0.3, gap = 0.004, delta = p.roughness - gap;
  law.damping = NormalDamping::viscoelastic(time);
  PairHistory h;
  const PairForce f = law(at_overlap(-gap), separating(v), 1e-3, h);
  const double elastic = p.kn * std::pow(delta, 1.5), damping = 1.5 * time * p.kn * std::sqrt(delta) * v;
  EXPECT_NEAR(f[Contribution::contact_normal].dot(axis), elastic - damping, 1e-12 * elastic);
  // It only dissipates, and the load friction sees carries it (paper 000: spring + dashpot).
  EXPECT_LT(f[Contribution::contact_normal].dot(axis) * v, elastic * v);
}

TEST(NormalDamping, TheLoadOfFrictionIncludesTheDashpot) {
  ContactModel<SoftRepulsion, CoulombFriction> law{SoftRepulsion{{1.0e4}}, {{0.5}}};
  law.damping = NormalDamping::viscous(50.0);
  const double delta = 0.01, v_n = -0.4;  // approaching: the dashpot adds to the spring
  const RelativeMotion m{Vec3::Zero(), v_n * axis + Vec3(0.4, 0.3, 0.0).cross(axis), Vec3::Zero(), Vec3::Zero()};
  PairHistory h;
  PairForce f;
  for (int s = 0; s < 2000; ++s) f = law(at_overlap(delta), m, 1e-2, h);
  EXPECT_TRUE(f.sliding);
  EXPECT_NEAR(f[Contribution::contact_tangential].norm(), 0.5 * (1.0e4 * delta - 50.0 * v_n), 1e-9);
}

TEST(Adhesion, DmtPullOffIsTwoPiWRStarAndFourThirdsOfJkrs) {
  const double w = 0.8, a_i = 1.0, a_j = 1.4, r_star = a_i * a_j / (a_i + a_j);
  ContactModel<SoftRepulsion> dmt{SoftRepulsion{{1.0e4}}};
  dmt.adhesion = Adhesion::dmt(w);
  double tension = 0.0;  // the largest tension along a retraction to contact's end
  for (int k = 1000; k >= 1; --k) {
    PairHistory h;
    tension = std::max(tension, -dmt(at_overlap(k * 1e-6, a_i, a_j), separating(0.0), 1e-3, h).total_on_j().dot(axis));
  }
  EXPECT_NEAR(tension, 2.0 * pi * w * r_star - 1.0e4 * 1e-6, 1e-9);  // less the spring at the last overlap
  // JKR's pull-off at the same W and R* is (3/2) pi W R*: DMT / JKR = 4/3.
  const JkrAdhesion jkr(JkrParams{1.0e4, w});
  EXPECT_NEAR(2.0 * pi * w * r_star / jkr.pull_off_force(r_star), 4.0 / 3.0, 1e-15);
  // sigma* is scaled by F_adh of the a_1 pair (R* = 1/2): pi W.
  EXPECT_DOUBLE_EQ(dmt.adhesion_force(), pi * w);
  // Out of contact it does nothing.
  PairHistory h;
  EXPECT_EQ(dmt(at_overlap(-1e-6, a_i, a_j), separating(0.0), 1e-3, h).total_on_j().norm(), 0.0);
}

TEST(Adhesion, ConstantAdhesionOnALinearSpringBalancesAtFadhOverKn) {
  const double kn = 1.0e4, f_adh = 3.0;
  ContactModel<LinearSpringDashpot> law{LinearSpringDashpot{{kn}}};
  law.adhesion = Adhesion::constant(f_adh);
  PairHistory h;
  const PairForce f = law(at_overlap(f_adh / kn), separating(0.0), 1e-3, h);
  EXPECT_NEAR(f.total_on_j().dot(axis), 0.0, 1e-10);  // k_n times the overlap's rounding from the positions
  EXPECT_NEAR(f[Contribution::adhesion].dot(axis), -f_adh, 1e-15);
  // Its potential -F_adh delta: the force is minus its gradient.
  const double delta = 2e-4, e = 1e-8;
  const double de = law.energy(at_overlap(delta + e)) - law.energy(at_overlap(delta - e));
  EXPECT_NEAR(law(at_overlap(delta), separating(0.0), 1e-3, h).total_on_j().dot(axis), de / (2 * e), 1e-5);
}

TEST(TwistingResistance, TheSpringOpposesTheRelativeSpinAndSlidesAtMuTimesTheLoad) {
  const double kn = 1.0e4, k_o = 100.0, mu_o = 0.1, w = 0.2, dt = 1e-3, delta = 0.01;
  ContactModel<SoftRepulsion> law{SoftRepulsion{{kn}}};
  law.twisting = {true, k_o, mu_o};
  PairHistory h;
  const PairForce f = law(at_overlap(delta), spinning(Vec3::Zero(), w * axis), dt, h);
  // u_o = a_ij (omega_i - omega_j) . n = -w (a_ij = 1); T_i = a_ij (-k_o xi_o) n with xi_o = -w dt: along +n.
  EXPECT_NEAR(h.twisting_stretch, -w * dt, 1e-18);
  EXPECT_NEAR(f.torque_i.dot(axis), k_o * w * dt, 1e-15);
  EXPECT_NEAR((f.torque_i + f.torque_j).norm(), 0.0, 1e-18);
  EXPECT_NEAR(f.torque_i.cross(axis).norm(), 0.0, 1e-15);  // about the normal only
  EXPECT_EQ(f.total_on_j(), law(at_overlap(delta), spinning(Vec3::Zero(), Vec3::Zero()), dt, h).total_on_j());
  // Sliding: the torque saturates at a_ij mu_o |L|.
  PairHistory g;
  PairForce s;
  for (int k = 0; k < 1000; ++k) s = law(at_overlap(delta), spinning(Vec3::Zero(), w * axis), dt, g);
  EXPECT_NEAR(s.torque_i.dot(axis), mu_o * kn * delta, 1e-12);
  // A rigid rotation of the pair (omega_i = omega_j) loads nothing.
  PairHistory r;
  const Vec3 rigid = Vec3(0.3, 2.0, -1.0);
  EXPECT_EQ(law(at_overlap(delta), spinning(rigid, rigid), dt, r).torque_i.norm(), 0.0);
}

TEST(TwistingResistance, ThePairSeenTheOtherWayFeelsTheSameTorques) {
  ContactModel<SoftRepulsion> law{SoftRepulsion{{1.0e4}}};
  law.twisting = {true, 100.0, 0.1};
  const Vec3 omega_i(0.1, -0.3, 0.2), omega_j(-0.4, 0.2, 0.5);
  const PairGeometry g = at_overlap(0.01, 1.0, 1.4);
  const PairGeometry swapped = PairGeometry::from(-g.d, 1.4, 1.0);
  PairHistory h, hs;
  PairForce f, fs;
  for (int k = 0; k < 5; ++k) {
    f = law(g, spinning(omega_i, omega_j), 1e-3, h);
    fs = law(swapped, spinning(omega_j, omega_i), 1e-3, hs);
  }
  EXPECT_EQ(h.twisting_stretch, hs.twisting_stretch);  // a scalar of the pair, unchanged by the swap
  EXPECT_NEAR((f.torque_i - fs.torque_j).norm(), 0.0, 1e-15);
  EXPECT_NEAR((f.torque_j - fs.torque_i).norm(), 0.0, 1e-15);
}

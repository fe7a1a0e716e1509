// The finite-Stokes-number integrator: modified velocity-Verlet of paper 000 eq. 15, checked against the exact
// solutions of the equations of motion it integrates (m du/dt = F_contact - 6 pi a (u - U_inf)).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dem/simulation.hpp"
#include "tests/simulation_state.hpp"

using namespace suspend;
using suspend::test_support::state_of;
using std::numbers::pi;

namespace {

SimulationParams inertial(double stokes_number, double kn, double dt, NormalDamping damping = {}) {
  SimulationParams params;
  params.integrator = Integrator::inertial;
  params.stokes_number = stokes_number;
  ContactModel<SoftRepulsion> contact{SoftRepulsion{{kn}}};
  contact.damping = damping;
  params.contact = ComposedLaw<ContactModel<SoftRepulsion>>{contact, {}};
  params.time_step.mode = TimeStepParams::Mode::fixed;
  params.time_step.fixed = dt;
  params.max_overlap = 0.5;
  return params;
}

// Largest deviation from the exact ring-down over t <= 0.2 (or until the spheres part), over delta0.
double ring_down_error(double dt, NormalDamping damping = {}) {
  // Two unit spheres overlapping by delta, side by side in z (same y, so the shear does not separate them), with a
  // contact dashpot gamma (the damping sub-model: gamma_n, or A k_n for the viscoelastic one on a linear spring):
  //   m delta'' = -2 k delta - (6 pi + 2 gamma) delta'   (each sphere: m z'' = k delta + gamma delta' - 6 pi z',
  //   delta = 2 - separation); from rest: delta = delta0 e^{-ct/2} (cos wd t + c/(2 wd) sin wd t),
  //   c = (6 pi + 2 gamma) / m, wd^2 = 2k/m - c^2/4.
  const double st = 1.0, kn = 100.0, delta0 = 0.05;
  const double gamma = damping.model == NormalDamping::Model::viscoelastic ? damping.coefficient * kn
                                                                           : damping.coefficient;
  const double m = st * 4.0 / 3.0 * pi, c = (6 * pi + 2 * gamma) / m, wd = std::sqrt(2 * kn / m - c * c / 4);
  Simulation sim(state_of({{10, 10, 10}, {10, 10, 12 - delta0}}, {1.0, 1.0}), Box(20, 20, 20),
                         inertial(st, kn, dt, damping));
  double worst = 0.0;
  for (int step = 1; step * dt <= 0.2; ++step) {
    sim.advance();
    const double t = step * dt;
    const Vec3& r0 = sim.state().particles.position[0];
    const Vec3& r1 = sim.state().particles.position[1];
    const double delta = 2.0 - (r1 - r0).norm();
    if (delta < 0) break;  // the spheres have parted: the contact law no longer acts
    const double exact = delta0 * std::exp(-c * t / 2) * (std::cos(wd * t) + c / (2 * wd) * std::sin(wd * t));
    worst = std::max(worst, std::abs(delta - exact));
  }
  return worst / delta0;
}
}  // namespace

TEST(Inertial, OverlappingPairRingsDownAsTheDampedOscillatorItObeys) {
  // Eq. 15 evaluates the velocity-dependent (drag) force at the half-step velocity, so with drag the scheme is
  // first order in dt (second order for position-only forces): the error halves with the step.
  const double coarse = ring_down_error(1e-4), fine = ring_down_error(5e-5);
  EXPECT_LT(coarse, 1e-4);
  EXPECT_NEAR(coarse / fine, 2.0, 0.1);
}

TEST(Inertial, TheContactDashpotAddsToTheDragAsTheDampedOscillatorSays) {
  // The damping sub-model in the engine: with gamma_n = 4 (and the viscoelastic model at A k_n = 4) the ring-down is
  // the damped oscillator's with c = (6 pi + 2 gamma) / m, to the scheme's first order in dt.
  for (const NormalDamping& d : {NormalDamping::viscous(4.0), NormalDamping::viscoelastic(4.0 / 100.0)}) {
    const double coarse = ring_down_error(1e-4, d), fine = ring_down_error(5e-5, d);
    EXPECT_LT(coarse, 2e-4) << d.name();
    EXPECT_NEAR(coarse / fine, 2.0, 0.15) << d.name();
  }
}

TEST(Inertial, SmallStokesNumberRecoversTheOverdampedSeparation) {
  // St -> 0: the pair separates at the Stokes velocity, delta = delta0 exp(-2 k t / (6 pi)).
  const double kn = 100.0, delta0 = 0.02, dt = 1e-6;  // dt below the drag relaxation time m / (6 pi) = 2.2e-6
  Simulation sim(state_of({{10, 10, 10}, {10, 10, 12 - delta0}}, {1.0, 1.0}), Box(20, 20, 20),
                         inertial(1e-5, kn, dt));
  for (int step = 0; step < 20000; ++step) sim.advance();
  const double t = sim.state().time;
  const double delta = 2.0 - (sim.state().particles.position[1] - sim.state().particles.position[0]).norm();
  EXPECT_NEAR(delta, delta0 * std::exp(-2 * kn * t / (6 * pi)), 2e-3 * delta0);
}

TEST(Inertial, SphereThrownAcrossTheShearedFaceRelaxesOntoTheLocalFlow) {
  // A lone sphere starts with the ambient velocity plus v0 in y. With lambda = 6 pi a / m:
  //   v_y = v0 e^{-lambda t};   w = u_x - gammadot y obeys w' = -lambda w - gammadot v_y, so w = -gammadot v0 t e^{-lambda t}.
  // It leaves through y = L_y; the Lees-Edwards remap (eq. 16) keeps w continuous.
  const double st = 0.1, v0 = 3.0, dt = 1e-4, rate = 2.0;
  const double m = st * 4.0 / 3.0 * pi, lambda = 6 * pi / m;
  auto s = state_of({{5, 9.97, 5}}, {1.0});
  s.verlet.assign(12, 0.0);
  s.verlet[0] = rate * 9.97;  // u^{1/2} with zero acceleration
  s.verlet[1] = v0;
  s.verlet[5] = -0.5 * rate;
  SimulationParams params = inertial(st, 1e3, dt);
  params.flow.shear_rate = rate;
  Simulation sim(s, Box(10, 10, 10), params);
  for (int step = 0; step < 3000; ++step) sim.advance();
  sim.evaluate();
  const double t = sim.state().time;
  const Particles& p = sim.state().particles;
  EXPECT_LT(p.position[0].y(), 1.0);  // wrapped through the top face
  EXPECT_NEAR(p.velocity[0].y(), v0 * std::exp(-lambda * t), 1e-5 * v0);
  EXPECT_NEAR(p.velocity[0].x() - rate * p.position[0].y(), -rate * v0 * t * std::exp(-lambda * t), 1e-5 * v0);
  EXPECT_NEAR(p.angular_velocity[0].z(), -0.5 * rate, 1e-12);
}

TEST(Inertial, LubricatedRunContinuesBitForBitFromItsState) {
  SimulationParams params = inertial(1e-2, 1e3, 0.0);
  params.time_step.mode = TimeStepParams::Mode::adaptive;
  params.lubrication = true;
  const auto start = state_of({{5, 5, 5}, {7.05, 5.3, 5}, {5, 7.39, 5.2}, {2, 9.2, 3}, {2.1, 1.2, 3.0}},
                              {1.0, 1.0, 1.4, 1.0, 1.0});
  const Box box(10, 10, 10);
  Simulation whole(start, box, params);
  for (int s = 0; s < 40; ++s) whole.advance();
  Simulation first(start, box, params);
  for (int s = 0; s < 20; ++s) first.advance();
  Simulation second(first.state_with_contacts(), box, params);
  for (int s = 0; s < 20; ++s) second.advance();
  for (std::size_t i = 0; i < start.particles.size(); ++i)
    EXPECT_EQ(second.state().particles.position[i], whole.state().particles.position[i]);
  EXPECT_EQ(second.state().time, whole.state().time);
  EXPECT_GT(whole.state().strain, 0.0);
}

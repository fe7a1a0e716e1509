// The FCM simulation (fcm_simulation: FCM + sub-grid lubrication + the shared contact module) against exact values:
//  * two overlapping equal spheres pushed apart by a soft repulsion separate at the rate the exact resistance
//    gives, (u_j - u_i).n = 2 F / (6 pi a (X11A - X12A)) at the saturated gap xi = h_in/a = 1e-3 (table value,
//    tests/data/two_sphere_resistance_table.txt, s' = 2.001);
//  * a dilute random suspension without contacts has eta_r = 1 + 2.5 phi (Einstein; the O(phi^2) term, 5 phi^2
//    with full hydrodynamics, is 2% of the increment at phi = 0.008 and is inside the tolerance);
//  * a short sheared run of 50 spheres is deterministic (two runs agree bit for bit) and finite, and a run
//    restarted from a checkpoint (state_with_contacts, warm start included) repeats the uninterrupted one.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

#include "core/rng.hpp"
#include "coupling/fcm_model.hpp"
#include "tests/simulation_state.hpp"

using namespace suspend;
using suspend::test_support::state_of;
using std::numbers::pi;

namespace {

FcmParams fcm_params() {
  FcmParams f;
  f.cache_dir = "coupling_cache";
  f.krylov_tolerance = 1e-6;
  return f;
}

}  // namespace

TEST(CouplingSimulation, OverlappingPairSeparatesAtTheExactRate) {
  const Box box(24, 24, 24);
  const double overlap = 0.01;
  const auto st = state_of({{11, 12.2, 12.7}, {13 - overlap, 12.2, 12.7}}, {1.0, 1.0});
  SimulationParams params;
  params.flow.shear_rate = 0.0;
  Simulation sim = fcm_simulation(st, box, params, fcm_params());
  sim.evaluate();
  const double f = std::get<ComposedLaw<ContactModel<SoftRepulsion>>>(params.contact).contact.normal.p.kn * overlap;
  // Exact X11A and X12A at s' = 2.001 (xi = 1e-3, the inner cutoff h_in = 1e-3 a).
  const double x11a = 252.549849, x12a = -251.904583;
  const Particles& p = sim.state().particles;
  const double rel = p.velocity[1].x() - p.velocity[0].x();
  const double want = 2.0 * f / (6.0 * pi * (x11a - x12a));
  std::cout << "separation rate " << rel << ", exact " << want << ", " << sim.solver_iterations()
            << " GMRES iterations\n";
  EXPECT_NEAR(rel / want, 1.0, 0.02);
  EXPECT_EQ(sim.contact_count(), 1u);
  EXPECT_EQ(fcm_model(sim).corrected_pairs(), 1u);
}

TEST(CouplingSimulation, DiluteSuspensionHasTheEinsteinViscosity) {
  const Box box(16, 16, 16);
  Rng rng(20261122);
  std::uniform_real_distribution<double> u(0.0, 16.0);
  double sum = 0.0;
  const int configurations = 3;
  for (int c = 0; c < configurations; ++c) {
    std::vector<Vec3> pos;
    while (pos.size() < 8) {
      const Vec3 x(u(rng), u(rng), u(rng));
      bool ok = true;
      for (const Vec3& y : pos) ok = ok && box.minimum_image(x, y).d.norm() > 2.2;
      if (ok) pos.push_back(x);
    }
    SimulationParams params;
    Simulation sim = fcm_simulation(state_of(pos, std::vector<double>(pos.size(), 1.0)), box, params, fcm_params());
    sim.evaluate();
    const double phi = sim.state().particles.volume() / box.volume();
    EXPECT_EQ(sim.contact_count(), 0u);
    const double k = (sim.stress().total()(0, 1) - 1.0) / phi;
    std::cout << "configuration " << c << ": (eta_r - 1)/phi = " << k << " at phi = " << phi << "\n";
    sum += k;
  }
  EXPECT_NEAR(sum / configurations / 2.5, 1.0, 0.03);
}

TEST(CouplingSimulation, ShortShearedRunIsDeterministicAndFinite) {
  const Box box(9, 9, 9);
  Rng rng(7);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<Vec3> pos;
  for (int i = 0; i < 4 && pos.size() < 50; ++i)
    for (int j = 0; j < 4 && pos.size() < 50; ++j)
      for (int k = 0; k < 4 && pos.size() < 50; ++k)
        pos.push_back(Vec3(1.125 + 2.25 * i + jitter(rng), 1.125 + 2.25 * j + jitter(rng), 1.125 + 2.25 * k + jitter(rng)));
  SimulationParams params;
  params.time_step.max = 0.01;
  auto run = [&] {
    Simulation sim = fcm_simulation(state_of(pos, std::vector<double>(pos.size(), 1.0)), box, params, fcm_params());
    for (int s = 0; s < 10; ++s) {
      sim.evaluate();
      EXPECT_TRUE(sim.stress().total().allFinite());
      sim.advance();
    }
    sim.evaluate();
    return std::make_pair(sim.state_with_contacts(), sim.stress().total());
  };
  const auto [a, sa] = run();
  const auto [b, sb] = run();
  ASSERT_EQ(a.particles.size(), 50u);
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    EXPECT_EQ(a.particles.position[i], b.particles.position[i]);
    EXPECT_TRUE(a.particles.position[i].allFinite());
  }
  EXPECT_EQ(sa, sb);
  const double phi = 50 * 4.0 / 3.0 * pi / box.volume();
  std::cout << "phi = " << phi << ", eta_r = " << sa(0, 1) << " after strain " << a.strain << "\n";
  EXPECT_GT(sa(0, 1), 1.0 + 2.5 * phi);  // interactions only add dissipation
}

namespace {

// Six steps straight through, and three steps, a checkpoint (state_with_contacts: warm starts included) and three
// more from it: the same positions bit for bit.
void expect_restart_repeats_the_uninterrupted_run(const SimulationParams& params) {
  const Box box(9, 9, 9);
  Rng rng(11);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<Vec3> pos;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        pos.push_back(Vec3(1.5 + 3.0 * i + jitter(rng), 1.5 + 3.0 * j + jitter(rng), 1.5 + 3.0 * k + jitter(rng)));
  Simulation whole = fcm_simulation(state_of(pos, std::vector<double>(pos.size(), 1.0)), box, params, fcm_params());
  SimulationState checkpoint;
  for (int s = 0; s < 6; ++s) {
    if (s == 3) checkpoint = whole.state_with_contacts();
    whole.evaluate();
    whole.advance();
  }
  Simulation resumed = fcm_simulation(checkpoint, box, params, fcm_params());
  for (int s = 3; s < 6; ++s) {
    resumed.evaluate();
    resumed.advance();
  }
  for (std::size_t i = 0; i < pos.size(); ++i)
    EXPECT_EQ(resumed.state().particles.position[i], whole.state().particles.position[i]) << i;
  EXPECT_EQ(resumed.shear_rate(), whole.shear_rate());
}

}  // namespace

TEST(CouplingSimulation, RestartFromACheckpointRepeatsTheUninterruptedRun) {
  SimulationParams params;
  params.time_step.max = 0.01;
  expect_restart_repeats_the_uninterrupted_run(params);
}

// Under imposed stress the shear and force parts keep their own warm starts; both go into the checkpoint.
TEST(CouplingSimulation, StressControlledRestartRepeatsTheUninterruptedRun) {
  SimulationParams params;
  params.time_step.max = 0.01;
  params.flow.control = FlowControl::stress;
  params.flow.shear_stress = 2.0;
  expect_restart_repeats_the_uninterrupted_run(params);
}

TEST(CouplingSimulation, ImplicitContactsRelaxAnOverlapAsBackwardEulerWithTheExactResistance) {
  // The overlapping pair of the first test, frictionless linear spring k, fixed step, implicit contacts. With the
  // end-of-step spring force, 6 pi a (X11A - X12A) U_j = k (delta_n - 2 U_j dt), so each step divides the overlap by
  // 1 + lambda dt, lambda = 2 k / (6 pi (X11A - X12A)) (exact X11A, X12A at s' = 2.001: FCM + correction), for any
  // dt: here lambda dt = 5, where the explicit step would diverge.
  const Box box(24, 24, 24);
  const double overlap = 0.01, k = 1.0e3;
  const double x11a = 252.549849, x12a = -251.904583;
  const double lambda = 2.0 * k / (6.0 * pi * (x11a - x12a));
  SimulationParams params;
  params.flow.shear_rate = 0.0;
  params.contact = ComposedLaw<ContactModel<SoftRepulsion>>{{SoftRepulsion{{k}}}, {}};
  params.time_step.implicit_contacts = true;
  params.time_step.mode = TimeStepParams::Mode::fixed;
  params.time_step.fixed = 5.0 / lambda;
  Simulation sim = fcm_simulation(state_of({{11, 12.2, 12.7}, {13 - overlap, 12.2, 12.7}}, {1.0, 1.0}), box, params, fcm_params());
  double delta = overlap;
  for (int s = 0; s < 3; ++s) {
    sim.advance();
    const auto& x = sim.state().particles.position;
    const double next = 2.0 - (x[1] - x[0]).norm();
    std::cout << "step " << s << ": overlap ratio " << next / delta << ", backward Euler " << 1.0 / 6.0 << "\n";
    EXPECT_NEAR(next / delta * 6.0, 1.0, 2e-3);
    delta = next;
  }
}

TEST(CouplingSimulation, StressControlHitsTheTargetAndEqualsTheRateControlledStep) {
  // Velocities and stress are linear in (gammadot, F_contact): the rate chosen for a target Sigma_xy, imposed
  // instead, gives the same velocities (to the GMRES tolerance) and the same stress.
  const Box box(9, 9, 9);
  Rng rng(5);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  std::vector<Vec3> pos;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        pos.push_back(Vec3(1.5 + 2.9 * i + jitter(rng), 1.5 + 2.9 * j + jitter(rng), 1.5 + 2.05 * k + jitter(rng)));
  SimulationParams params;
  params.flow.control = FlowControl::stress;
  params.flow.shear_stress = 3.0;
  params.time_step.implicit_contacts = true;
  FcmParams f = fcm_params();
  f.krylov_tolerance = 1e-9;
  f.far_field_every = 1;  // the full solve's linearity (a lagged step is checked in test_coupling_lagged_far_field)
  auto st = state_of(pos, std::vector<double>(pos.size(), 1.0));
  Simulation stress = fcm_simulation(st, box, params, f);
  for (int s = 0; s < 3; ++s) stress.advance();
  stress.evaluate();
  EXPECT_GT(stress.contact_count(), 0u);
  EXPECT_NEAR(stress.stress().total()(0, 1), 3.0, 1e-9);

  SimulationState same = stress.state_with_contacts();
  params.flow.control = FlowControl::rate;
  params.flow.shear_rate = stress.shear_rate();
  Simulation rate = fcm_simulation(same, box, params, f);
  rate.evaluate();
  std::cout << "stress control: rate " << stress.shear_rate() << ", Sigma_xy at that rate "
            << rate.stress().total()(0, 1) << "\n";
  EXPECT_NEAR(rate.stress().total()(0, 1), 3.0, 1e-5);
  for (std::size_t i = 0; i < pos.size(); ++i)
    EXPECT_LT((rate.state().particles.velocity[i] - stress.state().particles.velocity[i]).norm(), 1e-5) << i;
}

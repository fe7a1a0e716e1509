// Multi-rate stepping of the FCM engine (fcm.far_field_every, coupled_mobility.hpp "Lagged far field") against
// the every-step solution:
//  * at the configuration of the last full solve the lagged solve IS the full solution (g exact there);
//  * over a lag of k steps the velocities and the stress drift from the every-step solution by an amount that
//    grows with the lag and is measured here on a dense, contact-carrying cluster (implicit contacts);
//  * an isolated squeezed pair keeps its exact separation rate on lagged steps (the near field is solved every step);
//  * a restart from a checkpoint taken between full solves repeats the uninterrupted run bit for bit (rate and stress
//    control: the defects go into the checkpoint);
//  * fcm.predictor = lagged_far_field (the full solve started from the lagged step's velocities) is as accurate as
//    the extrapolated start from fewer Stokes solves, and restarts exactly too.
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

FcmParams fcm_params(int every, bool lagged_predictor = false) {
  FcmParams f;
  f.cache_dir = "coupling_cache";
  f.krylov_tolerance = 1e-8;
  f.far_field_every = every;
  f.lagged_predictor = lagged_predictor;
  return f;
}

// 27 spheres in a 9^3 box, close along z (s' ~ 2.05: lubrication, contacts), ~0.15 volume fraction.
SimulationState cluster(std::uint64_t seed) {
  Rng rng(seed);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  std::vector<Vec3> pos;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        pos.push_back(Vec3(1.5 + 2.9 * i + jitter(rng), 1.5 + 2.9 * j + jitter(rng), 1.5 + 2.02 * k + jitter(rng)));
  return state_of(pos, std::vector<double>(pos.size(), 1.0));
}

SimulationParams cluster_params() {
  SimulationParams params;
  params.time_step.implicit_contacts = true;
  params.time_step.mode = TimeStepParams::Mode::fixed;
  params.time_step.fixed = 2e-3;
  return params;
}

// RMS over particles of |U_a - U_b| (disturbance = lab difference here: same positions and rate), over the RMS of
// the disturbance velocities of b.
double velocity_error(const Simulation& a, const Simulation& b) {
  const Particles& pa = a.state().particles;
  const Particles& pb = b.state().particles;
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    num += (pa.velocity[i] - pb.velocity[i]).squaredNorm();
    den += (pb.velocity[i] - Vec3(b.shear_rate() * pb.position[i].y(), 0.0, 0.0)).squaredNorm();
  }
  return std::sqrt(num / den);
}

}  // namespace

TEST(LaggedFarField, AtTheLastFullSolveItIsTheFullSolution) {
  const Box box(9, 9, 9);
  const SimulationParams params = cluster_params();
  Simulation full = fcm_simulation(cluster(3), box, params, fcm_params(2));
  full.advance();  // step 0: full
  full.advance();  // step 1: lagged
  full.evaluate();  // step 2: full, its defect kept
  EXPECT_GT(fcm_model(full).stokes_solves(), 0);
  SimulationState same = full.state_with_contacts();
  same.step = 3;  // the schedule now asks for a lagged step, at the configuration of the full solve
  Simulation lagged = fcm_simulation(same, box, params, fcm_params(2));
  lagged.evaluate();
  EXPECT_EQ(fcm_model(lagged).stokes_solves(), 0);
  EXPECT_GT(lagged.contact_count(), 0u);
  const double err = velocity_error(lagged, full);
  const double stress_err = (lagged.stress().total() - full.stress().total()).norm() / full.stress().total().norm();
  std::cout << "lag 0: velocity error " << err << ", stress error " << stress_err << "\n";
  EXPECT_LT(err, 1e-5);
  EXPECT_LT(stress_err, 1e-6);
}

TEST(LaggedFarField, ErrorAgainstTheEveryStepSolutionGrowsWithTheLag) {
  const Box box(9, 9, 9);
  const SimulationParams params = cluster_params();
  const int k = 16;
  Simulation every = fcm_simulation(cluster(5), box, params, fcm_params(1));
  Simulation lagged = fcm_simulation(cluster(5), box, params, fcm_params(k));
  std::vector<double> err, stress_err;
  for (int s = 0; s < k; ++s) {
    every.evaluate();
    lagged.evaluate();
    err.push_back(velocity_error(lagged, every));
    stress_err.push_back((lagged.stress().total()(0, 1) - every.stress().total()(0, 1)) / every.stress().total()(0, 1));
    std::cout << "lag " << s << ": velocity error " << err.back() << ", Sigma_xy error " << stress_err.back()
              << ", contacts " << every.contact_count() << "\n";
    every.advance();
    lagged.advance();
  }
  // Step 0 is a full solve in both; then the error is the drift of g, growing steadily with the lag (measured:
  // 0.14% of the disturbance velocities per step of strain 2e-3, 2.1% at lag 15; Sigma_xy 5e-4 at lag 15).
  EXPECT_EQ(err[0], 0.0);
  for (int s = 1; s < k; ++s) EXPECT_GT(err[s], err[s - 1]) << s;
  EXPECT_LT(err[k - 1], 0.03);
  EXPECT_LT(std::abs(stress_err[k - 1]), 1e-3);
}

TEST(LaggedFarField, SqueezedPairSeparatesAtTheExactRateOnLaggedSteps) {
  // The overlapping pair of test_coupling_simulation pushed apart by a soft repulsion: while it overlaps, its gap
  // stays saturated at xi = 1e-3 and the exact X11A, X12A at s' = 2.001 give the separation rate for the present
  // force on every step, full (step 0) or lagged (1-7).
  const Box box(24, 24, 24);
  SimulationParams params;
  params.flow.shear_rate = 0.0;
  params.time_step.mode = TimeStepParams::Mode::fixed;
  params.time_step.fixed = 2e-4;
  const double kn = std::get<ComposedLaw<ContactModel<SoftRepulsion>>>(params.contact).contact.normal.p.kn;
  const double x11a = 252.549849, x12a = -251.904583;  // tests/data/two_sphere_resistance_table.txt, xi = 1e-3
  Simulation sim = fcm_simulation(state_of({{11, 12.2, 12.7}, {13 - 0.01, 12.2, 12.7}}, {1.0, 1.0}), box, params, fcm_params(100));
  for (int s = 0; s < 8; ++s) {
    sim.evaluate();
    const auto& x = sim.state().particles.position;
    const double overlap = 2.0 - (x[1] - x[0]).norm();
    ASSERT_GT(overlap, 0.0);
    const Particles& p = sim.state().particles;
    const double rel = p.velocity[1].x() - p.velocity[0].x();
    const double want = 2.0 * kn * overlap / (6.0 * pi * (x11a - x12a));
    std::cout << "step " << s << (fcm_model(sim).stokes_solves() > 0 ? " (full)" : " (lagged)") << ": separation rate " << rel
              << ", exact " << want << "\n";
    EXPECT_EQ(fcm_model(sim).stokes_solves() > 0, s == 0);
    EXPECT_NEAR(rel / want, 1.0, 1e-3);
    sim.advance();
  }
}

namespace {

// Seven steps straight through, and four steps, a checkpoint (the defects g included) and three more from it, with
// the far field refreshed every `every` steps: the same positions bit for bit.
void expect_restart_repeats_the_uninterrupted_run(const SimulationParams& params, int every = 3,
                                                  bool lagged_predictor = false) {
  const Box box(9, 9, 9);
  Simulation whole = fcm_simulation(cluster(11), box, params, fcm_params(every, lagged_predictor));
  SimulationState checkpoint;
  for (int s = 0; s < 7; ++s) {
    if (s == 4) checkpoint = whole.state_with_contacts();
    whole.evaluate();
    whole.advance();
  }
  Simulation resumed = fcm_simulation(checkpoint, box, params, fcm_params(every, lagged_predictor));
  for (int s = 4; s < 7; ++s) {
    resumed.evaluate();
    EXPECT_EQ(fcm_model(resumed).stokes_solves() > 0, s % every == 0) << s;
    resumed.advance();
  }
  for (std::size_t i = 0; i < whole.state().particles.size(); ++i)
    EXPECT_EQ(resumed.state().particles.position[i], whole.state().particles.position[i]) << i;
  EXPECT_EQ(resumed.shear_rate(), whole.shear_rate());
}

}  // namespace

TEST(LaggedFarField, RestartBetweenFullSolvesRepeatsTheUninterruptedRun) {
  expect_restart_repeats_the_uninterrupted_run(cluster_params());
}

TEST(LaggedFarField, StressControlledRestartBetweenFullSolvesRepeatsTheUninterruptedRun) {
  SimulationParams params = cluster_params();
  params.flow.control = FlowControl::stress;
  params.flow.shear_stress = 2.0;
  expect_restart_repeats_the_uninterrupted_run(params);
}

// With the lagged predictor every step's start depends on the defect of the step before: in the checkpoint too.
TEST(LaggedPredictor, RestartRepeatsTheUninterruptedRun) {
  SimulationParams params = cluster_params();
  expect_restart_repeats_the_uninterrupted_run(params, 1, true);
  params.flow.control = FlowControl::stress;
  params.flow.shear_stress = 2.0;
  expect_restart_repeats_the_uninterrupted_run(params, 1, true);
  expect_restart_repeats_the_uninterrupted_run(params, 3, true);
}

// fcm.predictor = lagged_far_field: every step a full solve to the tolerance, started from the lagged-far-field
// velocities (this step's contacts and close pairs, the last solve's far field) instead of the extrapolated ones.
// Against the solution at tolerance 1e-8, twelve steps of a cluster whose implicit contacts change the forces
// from step to step: at the default tolerance 1e-4 the predicted start is as accurate as the extrapolated one,
// from fewer GMRES iterations.
TEST(LaggedPredictor, AsAccurateAsTheExtrapolatedStartFromFewerStokesSolves) {
  const Box box(9, 9, 9);
  const SimulationParams params = cluster_params();
  FcmParams plain = fcm_params(1), lagged = fcm_params(1, true);
  plain.krylov_tolerance = lagged.krylov_tolerance = 1e-4;
  Simulation reference = fcm_simulation(cluster(5), box, params, fcm_params(1));
  Simulation extrapolated = fcm_simulation(cluster(5), box, params, plain);
  Simulation predicted = fcm_simulation(cluster(5), box, params, lagged);
  double err_extrapolated = 0.0, err_predicted = 0.0;
  for (int s = 0; s < 12; ++s) {
    for (Simulation* sim : {&reference, &extrapolated, &predicted}) sim->evaluate();
    err_extrapolated = std::max(err_extrapolated, velocity_error(extrapolated, reference));
    err_predicted = std::max(err_predicted, velocity_error(predicted, reference));
    for (Simulation* sim : {&reference, &extrapolated, &predicted}) sim->advance();
  }
  const auto solves_extrapolated = fcm_model(extrapolated).total_stokes_solves();
  const auto solves_predicted = fcm_model(predicted).total_stokes_solves();
  std::cout << "12 steps at tolerance 1e-4: " << solves_extrapolated << " Stokes solves from the extrapolation "
            << "(largest velocity error " << err_extrapolated << "), " << solves_predicted
            << " from the lagged predictor (" << err_predicted << ")\n";
  EXPECT_GT(predicted.contact_count(), 0u);
  EXPECT_LT(solves_predicted, solves_extrapolated);
  EXPECT_LT(err_predicted, 1.5 * err_extrapolated);
}

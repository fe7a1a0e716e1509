// The pair-form storage of the resistance matrix's coupling blocks (linalg/pair_form_block.hpp,
// hydrodynamics.solver.storage = pair_form): every block the solver builds is of that form (lubrication, singular and
// exact; backward-Euler contacts, sticking and sliding), a block that is not is refused, and a solve in pair form
// gives the dense storage's velocities and stresses to the solver's tolerance.
#include <gtest/gtest.h>
#include <omp.h>

#include <random>

#include "core/error.hpp"
#include "dem/integrate/implicit_contacts.hpp"
#include "dem/integrate/resistance_solver.hpp"
#include "dem/neighbour_search.hpp"
#include "dem/packing.hpp"
#include "dem/simulation.hpp"
#include "linalg/pair_form_block.hpp"
#include "tests/dense_suspension.hpp"
#include "tests/simulation_state.hpp"

using namespace suspend;

namespace {

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return Vec3(g(rng), g(rng), g(rng)).normalized();
}

Vector6 random_vector6(std::mt19937& rng) {
  std::normal_distribution<double> g;
  Vector6 v;
  for (int k = 0; k < 6; ++k) v[k] = g(rng);
  return v;
}

// Compresses m along n (and t), and checks the expansion and both products against the dense block.
void expect_pair_form(const Matrix6& m, const Vec3& n, const Vec3& t, std::mt19937& rng) {
  PairFormBlock k;
  SlipForm s;
  ASSERT_TRUE(compress(m, n, t, k, s));
  const SlipForm* slip = t.squaredNorm() > 0.0 ? &s : nullptr;
  const double scale = m.cwiseAbs().maxCoeff();
  EXPECT_LE((expand(k, slip) - m).cwiseAbs().maxCoeff(), 1e-13 * scale);
  const Vector6 x = random_vector6(rng);
  EXPECT_LE((times(k, slip, x) - m * x).norm(), 1e-13 * scale * x.norm());
  EXPECT_LE((transpose_times(k, slip, x) - m.transpose() * x).norm(), 1e-13 * scale * x.norm());
}

}  // namespace

TEST(PairFormBlock, LubricationBlocksAreOfThePairForm) {
  std::mt19937 rng(3);
  for (const bool exact : {false, true}) {
    hydro::LubricationParams lp;
    lp.exact_relative = exact;
    for (const double a_j : {1.0, 1.4}) {
      const hydro::PairLubrication law(1.0, a_j, lp);
      for (const double gap : {2e-4, 0.01, 0.1, 0.24}) {
        const Vec3 n = random_unit(rng);
        const hydro::Matrix12 r = law.resistance(n, gap);
        expect_pair_form(r.block<6, 6>(0, 6), n, Vec3::Zero(), rng);  // coupling
        expect_pair_form(r.block<6, 6>(0, 0), n, Vec3::Zero(), rng);  // i's self block
        expect_pair_form(r.block<6, 6>(6, 6), n, Vec3::Zero(), rng);  // j's self block
      }
    }
  }
}

TEST(PairFormBlock, ContactBlocksNeedTheSlipDirectionOnlyWhenSliding) {
  std::mt19937 rng(5);
  const Vec3 n = random_unit(rng);
  const PairGeometry g = PairGeometry::from(2.39 * n, 1.0, 1.4);  // overlapping 1 : 1.4 pair
  const AmbientFlow flow = AmbientFlow::simple_shear(1.0);
  Vec3 t = random_unit(rng);
  t = (t - t.dot(n) * n).normalized();
  const hydro::Matrix12 sticking = contact_step(g, Vec3(1, 2, 3), {1e4, 3e3, Vec3::Zero()}, 1e-3, flow).resistance();
  const hydro::Matrix12 sliding = contact_step(g, Vec3(1, 2, 3), {1e4, 3e3, t}, 1e-3, flow).resistance();
  for (const auto& [row, col] : {std::pair{0, 6}, std::pair{0, 0}, std::pair{6, 6}}) {
    expect_pair_form(sticking.block<6, 6>(row, col), n, Vec3::Zero(), rng);
    expect_pair_form(sliding.block<6, 6>(row, col), n, t, rng);
    PairFormBlock k;
    SlipForm s;
    EXPECT_FALSE(compress(sliding.block<6, 6>(row, col), n, Vec3::Zero(), k, s));  // the t t terms are not lost
  }
  PairFormBlock k;
  SlipForm s;
  Matrix6 m;
  for (int r = 0; r < 6; ++r) m.row(r) = random_vector6(rng).transpose();
  EXPECT_FALSE(compress(m, n, Vec3::Zero(), k, s));
  EXPECT_FALSE(compress(m, n, t, k, s));
}

namespace {
// 200 bidisperse spheres (1 : 1.4) at phi = 0.5 with their pairs within a gap of 0.3, random forces and torques.
test_support::DenseSuspension dense_configuration() { return test_support::dense_suspension(200, 0.3); }
}  // namespace

TEST(PairFormStorage, SolveGivesTheDenseSolutionAndStress) {
  const test_support::DenseSuspension d = dense_configuration();
  const AmbientFlow flow = AmbientFlow::wavy_shear(1.0, 0.5, 1, d.box.length().y());
  for (const Preconditioner pre : {Preconditioner::symmetric_gauss_seidel, Preconditioner::block_jacobi}) {
    ResistanceSolverParams params;
    params.tolerance = 1e-12;
    params.preconditioner = pre;
    ResistanceSolver dense(d.radii, params);
    params.storage = CouplingStorage::pair_form;
    ResistanceSolver compact(d.radii, params);
    SolveResult a, b;
    dense.solve(d.p, d.pairs, flow, d.force, d.torque, a);
    compact.solve(d.p, d.pairs, flow, d.force, d.torque, b);
    EXPECT_GT(b.lubricated_pairs, 200u);
    EXPECT_LT(b.residual, 1e-12);
    EXPECT_LT((compact.disturbance() - dense.disturbance()).norm(), 1e-10 * dense.disturbance().norm());
    for (const Contribution c : {Contribution::lubrication, Contribution::hydrodynamic})
      EXPECT_LT((b.stress[c] - a.stress[c]).norm(), 1e-10 * a.stress[c].norm());
    EXPECT_TRUE(b.lubrication_force_on_j.empty());  // formed again for the stress, not kept
    // The same matrix, and the reported residual is the true one.
    const Eigen::MatrixXd ma = dense.matrix().dense(), mb = compact.matrix().dense();
    EXPECT_LT((ma - mb).cwiseAbs().maxCoeff(), 1e-12 * ma.cwiseAbs().maxCoeff());
    Eigen::VectorXd x, ax;
    compact.to_rows(compact.disturbance(), x);
    compact.matrix().multiply(x, ax);
    EXPECT_NEAR((compact.right_hand_side() - ax).norm() / compact.right_hand_side().norm(), b.residual, 1e-15);
  }
}

TEST(PairFormStorage, ResultIsBitIdenticalForAnyThreadCount) {
  const test_support::DenseSuspension d = dense_configuration();
  const AmbientFlow flow = AmbientFlow::simple_shear(1.0);
  ResistanceSolverParams params;
  params.storage = CouplingStorage::pair_form;
  const int threads = omp_get_max_threads();
  SolveResult one, two;
  ResistanceSolver a(d.radii, params), b(d.radii, params);
  omp_set_num_threads(1);
  a.solve(d.p, d.pairs, flow, d.force, d.torque, one);
  omp_set_num_threads(2);
  b.solve(d.p, d.pairs, flow, d.force, d.torque, two);
  omp_set_num_threads(threads);
  EXPECT_EQ(a.disturbance(), b.disturbance());
  EXPECT_EQ(one.stress[Contribution::lubrication], two.stress[Contribution::lubrication]);
}

TEST(PairFormStorage, ImplicitSlidingContactsStepAsWithDenseBlocks) {
  // A sheared cluster with implicit frictional springs, the two contacts sliding from the first steps (mu 0.005:
  // their tangential force would level off near 0.01 of the normal one): twenty steps in each storage.
  const Box box(10, 10, 10);
  auto run = [&](CouplingStorage storage, std::size_t& sliding) {
    SimulationParams params;
    params.lubrication = true;
    params.resistance.tolerance = 1e-12;
    params.resistance.storage = storage;
    LinearSpringCoulomb law;
    law.normal.p.kn = 2.0e4;
    law.friction.p.mu = 0.005;
    params.contact = ComposedLaw<LinearSpringCoulomb>{law, {}};
    params.time_step.implicit_contacts = true;
    params.time_step.mode = TimeStepParams::Mode::fixed;
    params.time_step.fixed = 2e-3;
    auto st = test_support::state_of(
        {{5, 5, 5}, {7.01, 5.3, 5}, {5, 7.36, 5.2}, {2, 9.2, 3}, {2.1, 1.2, 3.0}, {8, 2, 8}, {5, 3.05, 5}},
        {1.0, 1.0, 1.4, 1.0, 1.0, 1.4, 1.0});
    Simulation sim(st, box, params);
    sliding = 0;
    for (int s = 0; s < 20; ++s) {
      sim.advance();
      for (std::size_t k = 0; k < sim.active_pairs().size(); ++k) sliding += sim.contact_records()[k].sliding;
    }
    return sim.state().particles;
  };
  std::size_t sliding_dense = 0, sliding_compact = 0;
  const Particles a = run(CouplingStorage::dense, sliding_dense);
  const Particles b = run(CouplingStorage::pair_form, sliding_compact);
  EXPECT_GT(sliding_compact, 0u);
  EXPECT_EQ(sliding_dense, sliding_compact);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_LT((a.position[i] - b.position[i]).norm(), 1e-10) << i;
    EXPECT_LT((a.velocity[i] - b.velocity[i]).norm(), 1e-8 * (1.0 + a.velocity[i].norm())) << i;
    EXPECT_LT((a.angular_velocity[i] - b.angular_velocity[i]).norm(), 1e-8 * (1.0 + a.angular_velocity[i].norm()))
        << i;
  }
}

TEST(PairFormStorage, NeedsTheConjugateGradient) {
  ResistanceSolverParams params;
  params.storage = CouplingStorage::pair_form;
  params.solver = LinearSolver::cholesky;
  EXPECT_THROW(params.validate(), InputError);
}

TEST(PairFormStorage, AutomaticFromSixteenThousandSpheresWithTheConjugateGradient) {
  ResistanceSolverParams params;  // storage unset: auto
  EXPECT_EQ(params.storage_for(16383), CouplingStorage::dense);
  EXPECT_EQ(params.storage_for(16384), CouplingStorage::pair_form);
  params.solver = LinearSolver::cholesky;
  EXPECT_EQ(params.storage_for(100000), CouplingStorage::dense);
  params.solver = LinearSolver::conjugate_gradient;
  params.storage = CouplingStorage::dense;
  EXPECT_EQ(params.storage_for(100000), CouplingStorage::dense);
  params.storage = CouplingStorage::pair_form;
  EXPECT_EQ(params.storage_for(10), CouplingStorage::pair_form);
}

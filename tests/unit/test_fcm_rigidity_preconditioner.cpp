// Near-field preconditioner of the FCM rigidity solve (fcm/rigidity_preconditioner.hpp):
//  - a pair block at zero separation is the isolated-sphere stresslet mobility 1 / ((20/3) pi a^3) (Lomholt &
//    Maxey 2003: S = (20/3) pi eta a^3 E for the dipole envelope), i.e. two coincident envelopes act as one;
//  - at finite separation it equals the free-space direct sum (fcm/direct_sum.hpp, nested 4th-order differences);
//  - the rigid solution does not depend on the preconditioner: on a dense random suspension the near-field and the
//    Jacobi CG give the same stresslets, and an independent Stokes solve with those stresslets gives a particle
//    rate of strain that cancels E_inf (the rigidity condition) to the tolerance; the near-field CG needs fewer
//    than half the iterations;
//  - after a small step, the reused factor and the warm start give the solution of a fresh solver.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "fcm/direct_sum.hpp"
#include "fcm/envelope.hpp"
#include "fcm/rigidity_preconditioner.hpp"
#include "fcm/solver.hpp"

using namespace suspend;
using namespace suspend::fcm;

TEST(FcmRigidityPreconditioner, CoincidentPairBlockIsTheIsolatedSphereMobility) {
  for (double a : {1.0, 1.7}) {
    const auto k = stresslet_pair_block(Vec3::Zero(), a, a);
    const double self = 1.0 / (20.0 / 3.0 * std::numbers::pi * a * a * a);
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) EXPECT_NEAR(k[i][j], i == j ? self : 0.0, 1e-4 * self) << i << " " << j;
  }
}

TEST(FcmRigidityPreconditioner, PairBlockEqualsTheFreeSpaceDirectSum) {
  const std::vector<Vec3> pos{Vec3(0.0, 0.0, 0.0), Vec3(1.3, -0.7, 0.45)};
  const std::vector<double> rad{1.0, 1.4};
  const auto k = stresslet_pair_block(pos[0] - pos[1], rad[0], rad[1]);
  const double self = stresslet_self_mobility(1.0);
  for (int b = 0; b < 5; ++b) {
    std::array<double, 5> unit{};
    unit[b] = 1.0;
    const std::vector<Mat3> s{Mat3::Zero(), stresslet_from_coordinates(unit)};
    const Disturbance d = direct_sum(pos, rad, {}, {}, s);
    const auto e = stresslet_coordinates(d.strain_rates[0]);  // K S = -e'
    for (int a = 0; a < 5; ++a) EXPECT_NEAR(k[a][b], -e[a], 1e-5 * self) << a << " " << b;
  }
}

TEST(FcmRigidityPreconditioner, RigidSolutionIsIndependentOfThePreconditioner) {
  // phi = 0.35 random (overlapping) monodisperse spheres plus a few larger ones, L = 12 a, h = a/2, sheared box.
  const double l = 12.0;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, l), g(-1.0, 1.0);
  std::vector<Vec3> pos, force, torque;
  std::vector<double> rad;
  const int n = static_cast<int>(0.35 * l * l * l / (4.0 / 3.0 * std::numbers::pi));
  for (int i = 0; i < n; ++i) {
    pos.emplace_back(u(rng), u(rng), u(rng));
    rad.push_back(i % 10 == 0 ? 1.3 : 1.0);
    force.emplace_back(g(rng), g(rng), g(rng));
    torque.emplace_back(g(rng), g(rng), g(rng));
  }
  SolverOptions o;
  o.planning = FftPlanning::estimate;
  o.rigidity_tolerance = 1e-10;
  o.max_rigidity_iterations = 500;
  MobilityResult res[2];
  for (int k = 0; k < 2; ++k) {
    o.preconditioner = k == 0 ? RigidityPreconditioner::jacobi : RigidityPreconditioner::near_field;
    Solver solver(Vec3::Constant(l), {24, 24, 24}, o);
    const std::vector<Mat3> zero(pos.size(), Mat3::Zero());
    res[k] = solver.solve({pos, rad, force, torque, AmbientFlow::simple_shear(1.0), 3.7, zero});
  }
  std::cout << n << " spheres: Jacobi " << res[0].iterations << " iterations, near field " << res[1].iterations
            << "\n";
  EXPECT_LT(2 * res[1].iterations, res[0].iterations);
  // Same rigid solution: the stresslet scale is (20/3) pi a^3 E_inf ~ 10.5.
  double ds = 0.0, smax = 0.0;
  for (int i = 0; i < n; ++i) {
    ds = std::max(ds, (res[1].stresslets[i] - res[0].stresslets[i]).norm());
    smax = std::max(smax, res[0].stresslets[i].norm());
    EXPECT_NEAR((res[1].velocities[i] - res[0].velocities[i]).norm(), 0.0, 1e-7);
  }
  EXPECT_LT(ds, 1e-7 * smax);
  // Rigidity by an independent Stokes solve: E_inf + e'(F, T, S) = 0.
  Solver check(Vec3::Constant(l), {24, 24, 24}, o);
  const Disturbance d = check.apply(pos, rad, force, torque, res[1].stresslets, 3.7);
  Mat3 e_inf = Mat3::Zero();
  e_inf(0, 1) = e_inf(1, 0) = 0.5;
  double emax = 0.0;
  for (int i = 0; i < n; ++i) {
    Mat3 e = e_inf + d.strain_rates[i];
    e.diagonal().array() -= e.trace() / 3.0;
    emax = std::max(emax, e.norm());
  }
  EXPECT_LT(emax, 1e-7);
}

TEST(FcmRigidityPreconditioner, ReusedFactorAfterASmallStepGivesTheFreshSolution) {
  // A time step: every particle moves by 0.05 a (within near_field_reuse_displacement = 0.1), the offset by 0.02.
  // The reused factor and the warm start change the iteration count only: the stresslets equal those of a fresh
  // solver (factor rebuilt, zero guess) to the tolerance.
  const double l = 12.0;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0.0, l), g(-1.0, 1.0);
  std::normal_distribution<double> normal;
  std::vector<Vec3> pos, force;
  std::vector<double> rad;
  const int n = static_cast<int>(0.3 * l * l * l / (4.0 / 3.0 * std::numbers::pi));
  for (int i = 0; i < n; ++i) {
    pos.emplace_back(u(rng), u(rng), u(rng));
    rad.push_back(1.0);
    force.emplace_back(g(rng), g(rng), g(rng));
  }
  SolverOptions o;
  o.planning = FftPlanning::estimate;
  o.rigidity_tolerance = 1e-10;
  Solver stepping(Vec3::Constant(l), {24, 24, 24}, o);
  const MobilityResult first = stepping.solve({pos, rad, force, {}, AmbientFlow::simple_shear(1.0), 0.5, {}});
  for (Vec3& x : pos) x += 0.05 * Vec3(normal(rng), normal(rng), normal(rng)).normalized();
  const MobilityResult warm = stepping.solve({pos, rad, force, {}, AmbientFlow::simple_shear(1.0), 0.52, {}});
  o.near_field_reuse_displacement = 0.0;
  Solver fresh(Vec3::Constant(l), {24, 24, 24}, o);
  const std::vector<Mat3> zero(pos.size(), Mat3::Zero());
  const MobilityResult cold = fresh.solve({pos, rad, force, {}, AmbientFlow::simple_shear(1.0), 0.52, zero});
  std::cout << n << " spheres: first " << first.iterations << ", warm step with reused factor " << warm.iterations
            << ", fresh " << cold.iterations << " iterations\n";
  EXPECT_LT(warm.iterations, cold.iterations);
  double ds = 0.0, smax = 0.0;
  for (int i = 0; i < n; ++i) {
    ds = std::max(ds, (warm.stresslets[i] - cold.stresslets[i]).norm());
    smax = std::max(smax, cold.stresslets[i].norm());
  }
  EXPECT_LT(ds, 1e-7 * smax);
}

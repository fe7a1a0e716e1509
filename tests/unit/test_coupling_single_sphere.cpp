// The coupled solve (coupled_mobility.hpp) for one sphere against exact values: with a force, the drag of the
// periodic Gaussian sphere 6 pi a U / F = 1 - 2.837297 (a/L) + 4 (a/L)^3 (docs/references.md; Hasimoto
// 1959 at leading order); with a torque, Omega = T / (8 pi a^3) (1 - phi) (docs/fcm.md: the zero-mean flow lacks
// the k -> 0 vorticity); in shear, a force-free sphere moves with the flow, spins at -gammadot/2 and carries the
// Einstein stresslet (20/3) pi a^3 E (1 - 0.83 phi) in a cube (docs/fcm.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "coupling/coupled_mobility.hpp"

using namespace suspend;
using namespace suspend::coupling;

namespace {
constexpr double pi = std::numbers::pi;

fcm::SolverOptions options() {
  fcm::SolverOptions o;
  o.planning = fcm::FftPlanning::estimate;
  o.truncation_widths = 4.5;  // truncation error 1e-4 (4e-4 at the default 4): the drag is checked to 2e-4
  return o;
}

CoupledMobility make(double l) {
  const fcm::SolverOptions o = options();
  KrylovParams k;
  k.tolerance = 1e-8;
  const int n = static_cast<int>(l / 0.5);
  return CoupledMobility(Vec3::Constant(l), {n, n, n}, o, k);
}
}  // namespace

TEST(CouplingSingleSphere, DragTorqueAndStressletAreTheFcmValues) {
  const double l = 10.0;
  CoupledMobility m = make(l);
  const std::vector<Vec3> pos{Vec3(5.3, 6.1, 3.9)};
  const std::vector<double> rad{1.0};
  const std::vector<Vec3> f{Vec3(1.0, -0.5, 0.25)}, t{Vec3(0.3, 0.2, -0.4)};
  CoupledResult r;
  m.solve({.positions = pos, .radii = rad, .forces = f, .torques = t}, nullptr, r);
  const double drag = 1.0 - 2.837297 / l + 4.0 / (l * l * l);
  EXPECT_LT((r.velocities[0] * 6.0 * pi - drag * f[0]).norm(), 2e-4 * f[0].norm());
  const double phi = 4.0 * pi / (3.0 * l * l * l);
  EXPECT_LT((r.angular_velocities[0] * 8.0 * pi - (1.0 - phi) * t[0]).norm(), 4e-3 * t[0].norm());
  EXPECT_LE(r.stokes_solves, r.iterations + 1);

  CoupledMobility s = make(l);
  CoupledResult q;
  s.solve({.positions = pos, .radii = rad, .flow = AmbientFlow::simple_shear(2.0), .shear_offset = 3.0}, nullptr, q);
  // Tolerances as in test_fcm_lees_edwards: the dipole's grid-position error at h = a/2 (docs/fcm.md).
  EXPECT_NEAR(q.velocities[0].x(), 2.0 * pos[0].y(), 1e-3);
  EXPECT_NEAR(q.angular_velocities[0].z(), -1.0, 5e-3);
  // Without sub-grid pairs the one-space GMRES solves the same problem as the solver's nested rigidity CG.
  fcm::SolverOptions o = options();
  o.rigidity_tolerance = 1e-10;
  const int n = static_cast<int>(l / 0.5);
  fcm::Solver direct(Vec3::Constant(l), {n, n, n}, o);
  const fcm::MobilityResult d =
      direct.solve({.positions = pos, .radii = rad, .flow = AmbientFlow::simple_shear(2.0), .shear_offset = 3.0});
  EXPECT_LT((d.velocities[0] - q.velocities[0]).norm(), 1e-7);
  EXPECT_LT((d.angular_velocities[0] - q.angular_velocities[0]).norm(), 1e-7);
  EXPECT_LT((d.stresslets[0] - q.stresslets[0]).norm(), 1e-6 * d.stresslets[0].norm());
  const double einstein = 20.0 / 3.0 * pi * 1.0;  // (20/3) pi a^3 E_xy, E_xy = 1
  EXPECT_NEAR(q.stresslets[0](0, 1) / (einstein * (1.0 - 0.83 * phi)), 1.0, 1e-2);  // + O(phi^2) images at L = 10 a
}

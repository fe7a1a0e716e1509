// Lees-Edwards periodicity of the FCM solve (docs/fcm.md): the lattice with offset D is the lattice with
// offset D + m L_x, an LE image of a particle is the particle, and the flow near a pair across the sheared face is
// the flow near the same pair in the middle of an unsheared box (up to O((r/L)^2 a/L) lattice-shape terms).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "core/box.hpp"
#include "fcm/solver.hpp"

using namespace suspend;
using namespace suspend::fcm;

namespace {
SolverOptions fast_options() {
  SolverOptions o;
  o.planning = FftPlanning::estimate;
  o.rigidity_tolerance = 1e-10;
  return o;
}
struct Config {
  std::vector<Vec3> pos{Vec3(2.0, 1.0, 5.0), Vec3(4.5, 11.2, 6.0), Vec3(9.0, 6.0, 2.5)};
  std::vector<double> rad{1.0, 1.2, 0.9};
  std::vector<Vec3> force{Vec3(1.0, 0.5, -0.2), Vec3(-0.3, 1.0, 0.4), Vec3(0.0, -0.7, 0.9)};
  std::vector<Vec3> torque{Vec3(0.5, 0.0, 1.0), Vec3(0.0, -1.0, 0.2), Vec3(0.3, 0.3, 0.3)};
};
}  // namespace

TEST(FcmLeesEdwards, WholePeriodsOfTheOffsetGiveIdenticalVelocities) {
  Solver s(Vec3(12.0, 12.0, 12.0), {24, 24, 24}, fast_options());
  Config c;
  const double d = 2.3;
  std::vector<MobilityResult> res;
  for (int m : {0, 1, -2, 7}) {
    MobilityProblem pb{.positions = c.pos, .radii = c.rad, .forces = c.force, .torques = c.torque,
                       .flow = AmbientFlow::simple_shear(0.8), .shear_offset = d + m * 12.0};
    std::vector<Mat3> zero(3, Mat3::Zero());
    pb.stresslet_guess = zero;  // same starting point for every run
    res.push_back(s.solve(pb));
  }
  for (std::size_t k = 1; k < res.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR((res[k].velocities[i] - res[0].velocities[i]).norm(), 0.0, 1e-12);
      EXPECT_NEAR((res[k].angular_velocities[i] - res[0].angular_velocities[i]).norm(), 0.0, 1e-12);
      EXPECT_NEAR((res[k].stresslets[i] - res[0].stresslets[i]).norm(), 0.0, 1e-11);
    }
}

TEST(FcmLeesEdwards, ImageOfAParticleAcrossTheShearedFaceIsTheSameParticle) {
  Solver s(Vec3(12.0, 12.0, 12.0), {24, 24, 24}, fast_options());
  Config c;
  const double d = -4.1;
  const Disturbance a = s.apply(c.pos, c.rad, c.force, c.torque, {}, d);
  std::vector<Vec3> moved = c.pos;
  moved[1] += Vec3(-d, -12.0, 0.0);  // the image one period down is displaced by -D in x
  moved[2] += Vec3(12.0, 0.0, -12.0);
  const Disturbance b = s.apply(moved, c.rad, c.force, c.torque, {}, d);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR((a.velocities[i] - b.velocities[i]).norm(), 0.0, 1e-12);
    EXPECT_NEAR((a.angular_velocities[i] - b.angular_velocities[i]).norm(), 0.0, 1e-12);
  }
}

TEST(FcmLeesEdwards, PairAcrossTheShearedFaceFeelsTheSameFlowAsInTheMiddle) {
  // Equal and opposite forces: the lattice-shape constant (-2.837 a/L for the cube) cancels, the rest is
  // O((r/L)^2 a/L) ~ 1e-3. A solver that ignored the shear of the lattice would be off by O(1) here.
  const double l = 16.0;
  Solver s(Vec3::Constant(l), {32, 32, 32}, fast_options());
  const std::vector<double> rad{1.0, 1.0};
  const Vec3 sep(1.2, 2.6, -0.9);
  const std::vector<Vec3> f{Vec3(1.0, -0.4, 0.3), Vec3(-1.0, 0.4, -0.3)};
  const std::vector<Vec3> t{Vec3(0.0, 0.0, 0.0), Vec3(0.0, 0.0, 0.0)};
  const Vec3 mid(7.3, 7.6, 8.1);
  MobilityProblem centre{.positions = {}, .radii = rad, .forces = f, .torques = t};
  const std::vector<Vec3> p_mid{mid, mid + sep};
  centre.positions = p_mid;
  const MobilityResult ref = s.solve(centre);
  for (double d : {5.5, -7.9}) {
    Box box(l, l, l);
    box.set_shear_offset(d);
    Vec3 p1(3.0, l - 1.2, 4.0), p2 = p1 + sep;
    box.wrap(p2);  // p2 crosses the top face and re-enters at the bottom, shifted by -D
    const std::vector<Vec3> p{p1, p2};
    MobilityProblem across{.positions = p, .radii = rad, .forces = f, .torques = t, .shear_offset = d};
    const MobilityResult res = s.solve(across);
    for (int i = 0; i < 2; ++i) {
      const double err = (res.velocities[i] - ref.velocities[i]).norm() / ref.velocities[i].norm();
      std::cout << "offset " << d << " particle " << i << ": relative velocity difference " << err << "\n";
      EXPECT_LT(err, 0.01);
    }
  }
}

TEST(FcmLeesEdwards, LoneSphereTranslatesWithTheLocalFlowAndRotatesAtMinusHalfTheShearRate) {
  Solver s(Vec3::Constant(16.0), {32, 32, 32}, fast_options());
  const std::vector<double> rad{1.0};
  for (const Vec3& p : {Vec3(3.3, 1.7, 9.1), Vec3(12.2, 14.9, 0.4)}) {
    const std::vector<Vec3> pos{p};
    MobilityProblem pb{.positions = pos, .radii = rad, .flow = AmbientFlow::simple_shear(2.0), .shear_offset = 6.3};
    const MobilityResult r = s.solve(pb);
    EXPECT_NEAR(r.velocities[0].x(), 2.0 * p.y(), 1e-3);
    EXPECT_NEAR(r.velocities[0].y(), 0.0, 1e-3);
    EXPECT_NEAR(r.velocities[0].z(), 0.0, 1e-3);
    EXPECT_NEAR(r.angular_velocities[0].z(), -1.0, 5e-3);
    EXPECT_NEAR(r.angular_velocities[0].x(), 0.0, 1e-3);
    EXPECT_LT(r.strain_rates[0].norm(), 1e-6);
  }
}

// Spreading and interpolation are discrete adjoints: <S(F, G), u> dV = F.U + G:A for any field u, to round-off,
// on the plain and the sheared (Lees-Edwards) lattice. The FCM mobility is therefore symmetric.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "fcm/solver.hpp"
#include "fcm/spreading.hpp"

using namespace suspend;
using namespace suspend::fcm;

namespace {
Vec3 random_vec(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return {u(rng), u(rng), u(rng)};
}
Mat3 random_mat(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Mat3 m;
  for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = g(rng);
  return m;
}
}  // namespace

class SpreadInterpolate : public ::testing::TestWithParam<double> {};

TEST_P(SpreadInterpolate, AreAdjointToRoundOff) {
  std::mt19937_64 rng(7);
  ShearedGrid g;
  g.n = {16, 20, 12};
  g.length = Vec3(8.0, 10.0, 6.0);
  g.spacing = g.length.cwiseQuotient(Vec3(16, 20, 12));
  g.shear_fraction = GetParam();
  const int np = 6;
  std::vector<Envelope> env;
  std::vector<Vec3> f;
  std::vector<Mat3> dip;
  std::uniform_real_distribution<double> ar(0.8, 1.2);
  for (int i = 0; i < np; ++i) {
    // Some centres outside the primary cell: any periodic image must do.
    env.push_back(make_envelope(random_vec(rng, -3.0, 12.0), ar(rng), 4.0));
    f.push_back(random_vec(rng, -1.0, 1.0));
    dip.push_back(random_mat(rng));
  }
  const std::size_t stride = static_cast<std::size_t>(16 * 20 * 12);
  std::vector<double> field(3 * stride, 0.0), u(3 * stride);
  std::normal_distribution<double> gauss;
  for (double& x : u) x = gauss(rng);
  spread(g, env, f, dip, field.data(), stride);
  double lhs = 0.0;
  for (std::size_t i = 0; i < field.size(); ++i) lhs += field[i] * u[i];
  lhs *= g.cell_volume();
  std::vector<Vec3> uu(np);
  std::vector<Mat3> a(np);
  interpolate(g, env, u.data(), stride, uu, a);
  double rhs = 0.0;
  for (int i = 0; i < np; ++i) rhs += f[i].dot(uu[i]) + (dip[i].array() * a[i].array()).sum();
  EXPECT_NEAR(lhs, rhs, 1e-12 * std::abs(lhs) + 1e-12);
}

INSTANTIATE_TEST_SUITE_P(ShearFractions, SpreadInterpolate, ::testing::Values(0.0, 0.3, -0.5));

TEST(DipoleTensor, TorqueAndStrainRoundTrip) {
  // G = S + eps.T/2 and its moments: Omega_k = eps_kij A_ij / 2, E = -sym(A); with A = -grad u.
  // A rigid rotation u = Omega x r has grad u_ij = -eps_ijk Omega_k, so A = eps.Omega.
  const Vec3 om(0.3, -0.7, 1.1);
  Mat3 a = Mat3::Zero();
  a(0, 1) = om.z();
  a(1, 0) = -om.z();
  a(1, 2) = om.x();
  a(2, 1) = -om.x();
  a(2, 0) = om.y();
  a(0, 2) = -om.y();
  EXPECT_NEAR((angular_velocity_of(a) - om).norm(), 0.0, 1e-15);
  EXPECT_NEAR(strain_rate_of(a).norm(), 0.0, 1e-15);
  // Rate of work: G:A = T.Omega for a pure torque.
  const Vec3 t(2.0, 0.5, -1.0);
  EXPECT_NEAR((dipole_tensor(t, Mat3::Zero()).array() * a.array()).sum(), t.dot(om), 1e-14);
}

TEST(FcmSolver, MobilityIsSymmetricOnTheShearedLattice) {
  // <(F1,T1,S1), M (F2,T2,S2)> = <(F2,T2,S2), M (F1,T1,S1)> with the generalised velocity (U, Omega, -E).
  SolverOptions opt;
  opt.planning = FftPlanning::estimate;
  Solver solver(Vec3(12.0, 12.0, 12.0), {24, 24, 24}, opt);
  std::mt19937_64 rng(3);
  const int np = 4;
  std::vector<Vec3> pos, f1, f2, t1, t2;
  std::vector<double> rad;
  std::vector<Mat3> s1, s2;
  for (int i = 0; i < np; ++i) {
    pos.push_back(random_vec(rng, 0.0, 12.0));
    rad.push_back(1.0 + 0.1 * i);
    f1.push_back(random_vec(rng, -1, 1));
    f2.push_back(random_vec(rng, -1, 1));
    t1.push_back(random_vec(rng, -1, 1));
    t2.push_back(random_vec(rng, -1, 1));
    Mat3 m = random_mat(rng);
    s1.push_back(m + m.transpose());
    m = random_mat(rng);
    s2.push_back(m + m.transpose());
  }
  const double offset = 3.7;
  const Disturbance d1 = solver.apply(pos, rad, f1, t1, s1, offset);
  const Disturbance d2 = solver.apply(pos, rad, f2, t2, s2, offset);
  double w12 = 0.0, w21 = 0.0;
  for (int i = 0; i < np; ++i) {
    w12 += f1[i].dot(d2.velocities[i]) + t1[i].dot(d2.angular_velocities[i]) -
           (s1[i].array() * d2.strain_rates[i].array()).sum();
    w21 += f2[i].dot(d1.velocities[i]) + t2[i].dot(d1.angular_velocities[i]) -
           (s2[i].array() * d1.strain_rates[i].array()).sum();
  }
  EXPECT_NEAR(w12, w21, 1e-12 * std::abs(w12));
}

TEST(SpreadInterpolate, WideAndNarrowKernelsAgree) {
  // The 8-lane (AVX-512) and 4-lane row kernels do the same arithmetic in another order.
  if (!wide_kernels_available()) GTEST_SKIP() << "no AVX-512 on this CPU";
  std::mt19937_64 rng(13);
  ShearedGrid g;
  g.n = {24, 20, 16};
  g.length = Vec3(12.0, 10.0, 8.0);
  g.spacing = g.length.cwiseQuotient(Vec3(24, 20, 16));
  g.shear_fraction = 0.37;
  std::vector<Envelope> env;
  std::vector<Vec3> f;
  std::vector<Mat3> dip;
  std::uniform_real_distribution<double> ar(0.8, 1.3);
  for (int i = 0; i < 8; ++i) {
    env.push_back(make_envelope(random_vec(rng, -2.0, 13.0), ar(rng), 5.0));  // rows of up to 12 nodes
    f.push_back(random_vec(rng, -1.0, 1.0));
    dip.push_back(random_mat(rng));
  }
  const std::size_t stride = static_cast<std::size_t>(24 * 20 * 16);
  std::vector<double> wide(3 * stride, 0.0), narrow(3 * stride, 0.0), u(3 * stride);
  std::normal_distribution<double> gauss;
  for (double& x : u) x = gauss(rng);
  std::vector<Vec3> uw(8), un(8);
  std::vector<Mat3> aw(8), an(8);
  spread(g, env, f, dip, wide.data(), stride);
  interpolate(g, env, u.data(), stride, uw, aw);
  use_wide_kernels(false);
  spread(g, env, f, dip, narrow.data(), stride);
  interpolate(g, env, u.data(), stride, un, an);
  use_wide_kernels(true);
  double diff = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < wide.size(); ++i) {
    diff = std::max(diff, std::abs(wide[i] - narrow[i]));
    norm = std::max(norm, std::abs(narrow[i]));
  }
  EXPECT_LT(diff, 1e-13 * norm);
  for (int i = 0; i < 8; ++i) {
    EXPECT_LT((uw[i] - un[i]).norm(), 1e-13 * un[i].norm());
    EXPECT_LT((aw[i] - an[i]).norm(), 1e-13 * an[i].norm());
  }
}

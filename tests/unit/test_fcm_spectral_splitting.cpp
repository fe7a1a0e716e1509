// Spectral splitting (SolverOptions::split_dipole_width): the envelopes spread with tau^2 = sigma^2 - c^2 and the
// Green's function windowed by exp(-k^2 c^2) give the FCM operator of sigma_M, sigma_D up to the aliasing of the
// narrower Gaussians, keep the mobility symmetric to round-off and the Lees-Edwards invariance, and change nothing
// where sigma_D is already narrower than the requested width.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "fcm/envelope.hpp"
#include "fcm/solver.hpp"

using namespace suspend;
using namespace suspend::fcm;

namespace {
struct Loads {
  std::vector<Vec3> pos, f, t;
  std::vector<double> rad;
  std::vector<Mat3> s;
};

Loads random_loads(int np, double l, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, l), g(-1.0, 1.0);
  Loads x;
  for (int i = 0; i < np; ++i) {
    x.pos.emplace_back(u(rng), u(rng), u(rng));
    x.rad.push_back(1.0 + 0.1 * i);
    x.f.emplace_back(g(rng), g(rng), g(rng));
    x.t.emplace_back(g(rng), g(rng), g(rng));
    Mat3 m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = g(rng);
    x.s.push_back(m + m.transpose());
  }
  return x;
}

SolverOptions split_options(double split, double widths) {
  SolverOptions o;
  o.planning = FftPlanning::estimate;
  o.split_dipole_width = split;
  o.truncation_widths = widths;
  return o;
}

template <class T>
double relative_rms(const std::vector<T>& x, const std::vector<T>& ref) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    num += (x[i] - ref[i]).squaredNorm();
    den += ref[i].squaredNorm();
  }
  return std::sqrt(num / den);
}
}  // namespace

TEST(FcmSpectralSplitting, EqualsTheUnsplitOperatorOnAFineGrid) {
  // h = a/4: sigma_D = 1.82 h, split to tau_D = h (c = 0.38 a for a = 1); both cut at 5 widths of their own
  // monopole Gaussian.
  const double l = 12.0;
  const Loads x = random_loads(5, l, 11);
  Solver plain(Vec3::Constant(l), {48, 48, 48}, split_options(0.0, 5.0));
  Solver split(Vec3::Constant(l), {48, 48, 48}, split_options(1.0, 5.0));
  const Disturbance a = plain.apply(x.pos, x.rad, x.f, x.t, x.s, 2.1);
  const Disturbance b = split.apply(x.pos, x.rad, x.f, x.t, x.s, 2.1);
  EXPECT_NEAR(split.split_width(), std::sqrt(std::pow(dipole_width(1.0), 2) - 0.25 * 0.25), 1e-12);
  const double du = relative_rms(b.velocities, a.velocities), dw = relative_rms(b.angular_velocities, a.angular_velocities),
               de = relative_rms(b.strain_rates, a.strain_rates);
  std::cout << "split vs unsplit at h = a/4: U " << du << ", Omega " << dw << ", E " << de << "\n";
  EXPECT_LT(du, 2e-5);  // measured 3.5e-6, 4.5e-6, 1.1e-6
  EXPECT_LT(dw, 2e-5);
  EXPECT_LT(de, 1e-5);
}

TEST(FcmSpectralSplitting, MobilityStaysSymmetricAndLeesEdwardsInvariant) {
  const double l = 12.0;
  const Loads x = random_loads(4, l, 3), y = random_loads(4, l, 5);
  Solver solver(Vec3::Constant(l), {48, 48, 48}, split_options(1.0, 4.5));
  const Disturbance d1 = solver.apply(x.pos, x.rad, x.f, x.t, x.s, 3.7);
  const Disturbance d2 = solver.apply(x.pos, x.rad, y.f, y.t, y.s, 3.7);
  ASSERT_GT(solver.split_width(), 0.3);
  double w12 = 0.0, w21 = 0.0;
  for (std::size_t i = 0; i < x.pos.size(); ++i) {
    w12 += x.f[i].dot(d2.velocities[i]) + x.t[i].dot(d2.angular_velocities[i]) -
           (x.s[i].array() * d2.strain_rates[i].array()).sum();
    w21 += y.f[i].dot(d1.velocities[i]) + y.t[i].dot(d1.angular_velocities[i]) -
           (y.s[i].array() * d1.strain_rates[i].array()).sum();
  }
  EXPECT_NEAR(w12, w21, 1e-12 * std::abs(w12));
  // D and D + L_x are the same lattice.
  const Disturbance d3 = solver.apply(x.pos, x.rad, x.f, x.t, x.s, 3.7 + l);
  EXPECT_LT(relative_rms(d3.velocities, d1.velocities), 1e-12);
  EXPECT_LT(relative_rms(d3.strain_rates, d1.strain_rates), 1e-12);
}

TEST(FcmSpectralSplitting, NoSplitWhereTheDipoleIsNarrowerThanTheRequestedWidth) {
  // h = a/2: sigma_D = 0.91 h < 1.0 h, so c = 0 and the result is the unsplit one bit for bit.
  const double l = 12.0;
  const Loads x = random_loads(4, l, 7);
  Solver plain(Vec3::Constant(l), {24, 24, 24}, split_options(0.0, 4.5));
  Solver split(Vec3::Constant(l), {24, 24, 24}, split_options(1.0, 4.5));
  const Disturbance a = plain.apply(x.pos, x.rad, x.f, x.t, x.s, 1.3);
  const Disturbance b = split.apply(x.pos, x.rad, x.f, x.t, x.s, 1.3);
  EXPECT_EQ(split.split_width(), 0.0);
  for (std::size_t i = 0; i < x.pos.size(); ++i) {
    EXPECT_EQ(a.velocities[i], b.velocities[i]);
    EXPECT_EQ(a.strain_rates[i], b.strain_rates[i]);
  }
}

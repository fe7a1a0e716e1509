// The gradient profile against exact answers: the volume of a sphere between two planes (a cap, a half, the whole),
// phi(y) of one sphere straddling the periodic face and of a random gas (slabs sum to the box's phi exactly), and the
// velocity profile of affine shear (slope gammadot in every slab) and of a two-band flow (the slopes of its bands).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/gradient_profile.hpp"

using namespace suspend;
using namespace suspend::analysis;

namespace {

constexpr double pi = std::numbers::pi;

Configuration gas(std::size_t n, double l, std::uint64_t seed, double rate_low, double rate_high) {
  // centres uniform in the box, u_x = rate y below y = l/2 and continuous with slope rate_high above
  Configuration c;
  c.box = Box(l, l, l);
  c.box.set_shear_offset(0.25 * l);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, l);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 r(u(rng), u(rng), u(rng));
    c.position.push_back(r);
    const double y = r[1];
    const double ux = y < 0.5 * l ? rate_low * y : rate_low * 0.5 * l + rate_high * (y - 0.5 * l);
    c.velocity.emplace_back(ux, 0.1 * (u(rng) - 0.5 * l), 0.0);
    c.radius.push_back(i % 2 ? 1.4 : 1.0);
  }
  c.species.assign(n, 0);
  return c;
}

}  // namespace

TEST(SphereSlabVolume, CapHalfAndWhole) {
  const double a = 1.3, v = 4.0 / 3.0 * pi * a * a * a;
  EXPECT_NEAR(sphere_slab_volume(a, 0.0, -5.0, 5.0), v, 1e-13);
  EXPECT_NEAR(sphere_slab_volume(a, 2.0, 2.0, 9.0), 0.5 * v, 1e-13);
  const double h = 0.4;  // cap of height h: pi h^2 (3a - h) / 3
  EXPECT_NEAR(sphere_slab_volume(a, 0.0, a - h, 10.0), pi * h * h * (3.0 * a - h) / 3.0, 1e-13);
  EXPECT_EQ(sphere_slab_volume(a, 0.0, 2.0, 3.0), 0.0);
}

TEST(GradientProfile, SphereAcrossThePeriodicFace) {
  Configuration c;
  c.box = Box(10.0, 8.0, 10.0);
  c.box.set_shear_offset(3.0);
  c.position.emplace_back(5.0, 0.5, 5.0);  // reaches y = -0.5, i.e. 7.5 .. 8 through the face
  c.radius.push_back(1.0);
  c.species.push_back(0);
  const GradientProfile p = gradient_profile(c, 4);  // slabs of width 2
  const double slab = 2.0 * 10.0 * 10.0, cap = pi * 0.25 * (3.0 - 0.5) / 3.0;  // cap of height 0.5
  const double v = 4.0 / 3.0 * pi;
  EXPECT_NEAR(p.phi[0] * slab, v - cap, 1e-12);
  EXPECT_NEAR(p.phi[3] * slab, cap, 1e-12);
  EXPECT_EQ(p.phi[1], 0.0);
  EXPECT_EQ(p.count[0], 1u);
  EXPECT_TRUE(std::isnan(p.velocity[0]));  // no velocities given
  EXPECT_TRUE(std::isnan(p.shear_rate));
}

TEST(GradientProfile, AffineShearAndPhiOfAGas) {
  const double l = 20.0;
  const Configuration c = gas(2000, l, 7, 0.8, 0.8);
  double volume = 0.0;
  for (double a : c.radius) volume += 4.0 / 3.0 * pi * a * a * a;
  for (int bins : {1, 5, 16}) {
    const GradientProfile p = gradient_profile(c, bins);
    double sum = 0.0;
    std::size_t count = 0;
    for (int k = 0; k < bins; ++k) sum += p.phi[k] / bins, count += p.count[k];
    EXPECT_NEAR(sum, volume / (l * l * l), 1e-12) << bins;  // the slabs' mean is the box's phi
    EXPECT_EQ(count, c.size());
    EXPECT_NEAR(p.shear_rate, 0.8, 1e-12);
    for (double s : p.local_rate) EXPECT_NEAR(s, 0.8, 1e-12);  // affine: exact in every slab pair
  }
}

TEST(GradientProfile, TwoBandsShowInTheLocalRates) {
  const Configuration c = gas(4000, 16.0, 11, 0.2, 1.8);  // a slow band below y = 8, a fast one above
  const GradientProfile p = gradient_profile(c, 4);         // slab edges at 4, 8, 12
  EXPECT_NEAR(p.local_rate[0], 0.2, 1e-12);
  EXPECT_NEAR(p.local_rate[2], 1.8, 1e-12);
  EXPECT_GT(p.local_rate[1], 0.2);  // straddles the band edge
  EXPECT_LT(p.local_rate[1], 1.8);
  EXPECT_NEAR(p.shear_rate, 1.0, 0.1);  // the mean slope over the cell
}

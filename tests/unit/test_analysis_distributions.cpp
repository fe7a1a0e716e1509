// Distributions with known answers: forces normalised by their mean, the gaps of a lattice, g(r) of a lattice
// (coordination shells by counting) and of an ideal gas (g = 1), the shear-plane map of an ideal gas.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/distributions.hpp"

using namespace suspend;
using namespace suspend::analysis;

namespace {

Configuration cubic_lattice(int m, double s, double radius) {
  Configuration c;
  c.box = Box(m * s, m * s, m * s);
  for (int x = 0; x < m; ++x)
    for (int y = 0; y < m; ++y)
      for (int z = 0; z < m; ++z) c.position.emplace_back(s * (x + 0.5), s * (y + 0.5), s * (z + 0.5));
  c.radius.assign(c.position.size(), radius);
  c.species.assign(c.position.size(), 0);
  return c;
}

Configuration ideal_gas(std::size_t n, double l, std::uint64_t seed) {
  Configuration c;
  c.box = Box(l, l, l);
  c.box.set_shear_offset(0.3 * l);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, l);
  for (std::size_t i = 0; i < n; ++i) c.position.emplace_back(u(rng), u(rng), u(rng));
  c.radius.assign(n, 1.0);
  c.species.assign(n, 0);
  return c;
}

}  // namespace

TEST(Distributions, ForcesAreBinnedOverTheirMean) {
  Configuration c;
  for (double f : {1.0, 2.0, 3.0, -30.0, 44.0}) {  // mean 4
    Contact k;
    k.normal_force = f;
    k.tangential_force = Vec3(0, f, 0);
    c.contacts.push_back(k);
  }
  const ForceDistributions d = force_distributions(c);
  EXPECT_DOUBLE_EQ(d.normal.mean, 4.0);
  EXPECT_EQ(d.normal.total, 5u);
  EXPECT_EQ(d.normal.below, 1u);  // -30
  EXPECT_EQ(d.normal.above, 1u);  // 44 / 4 > 5
  ASSERT_EQ(d.normal.density.size(), 25u);
  const double w = 0.2, unit = 1.0 / (5 * w);
  for (int k = 0; k < 25; ++k) EXPECT_DOUBLE_EQ(d.normal.density[k], k >= 1 && k <= 3 ? unit : 0.0) << k;
  EXPECT_DOUBLE_EQ(d.tangential.mean, 16.0);  // magnitudes
  EXPECT_EQ(d.tangential.below, 0u);
}

TEST(Distributions, GapsOfACubicLatticeFallInTheirShells) {
  // Spacing 2.05 with unit spheres: 6 neighbours at gap 0.05 and 12 at 2.05 sqrt(2) - 2 = 0.899 (below 1).
  const Configuration c = cubic_lattice(6, 2.05, 1.0);
  const GapDistribution d = gap_distribution(c);
  const double n = static_cast<double>(c.size());
  EXPECT_EQ(d.gaps.total, static_cast<std::size_t>(9 * n));
  EXPECT_EQ(d.overlapping, 0u);
  EXPECT_EQ(d.gaps.below, 0u);
  auto count = [&](double gap) {
    const int k = static_cast<int>(std::floor((std::log10(gap) + 4.0) * 5.0));
    return d.gaps.density[k] * d.gaps.total * (d.gaps.edges[k + 1] - d.gaps.edges[k]);
  };
  EXPECT_NEAR(count(0.05), 3 * n, 1e-6);
  EXPECT_NEAR(count(2.05 * std::sqrt(2.0) - 2.0), 6 * n, 1e-6);
  EXPECT_NEAR(d.gaps.mean, (3 * 0.05 + 6 * (2.05 * std::sqrt(2.0) - 2.0)) / 9, 1e-12);
}

TEST(Distributions, PairDistributionCountsTheLatticeShells) {
  // Simple cubic, spacing 2: the shell at r = 2 holds 6 neighbours per particle, at 2 sqrt(2) 12, at 2 sqrt(3) 8.
  const Configuration c = cubic_lattice(8, 2.0, 1.0);
  const PairDistribution p = pair_distribution(c, 5.0, 0.05);
  const double n = static_cast<double>(c.size()), density = n * (n - 1) / (2 * c.box.volume());
  auto neighbours_per_particle = [&](double r) {
    const int k = static_cast<int>(r / p.dr);
    const double lo = k * p.dr, hi = lo + p.dr;
    return p.g[k] * density * 4.0 / 3.0 * std::numbers::pi * (hi * hi * hi - lo * lo * lo) * 2.0 / n;
  };
  EXPECT_NEAR(neighbours_per_particle(2.0), 6.0, 1e-9);
  EXPECT_NEAR(neighbours_per_particle(2.0 * std::sqrt(2.0)), 12.0, 1e-9);
  EXPECT_NEAR(neighbours_per_particle(2.0 * std::sqrt(3.0)), 8.0, 1e-9);
  EXPECT_NEAR(neighbours_per_particle(4.0), 6.0, 1e-9);
  EXPECT_DOUBLE_EQ(p.g[static_cast<int>(1.5 / p.dr)], 0.0);
}

TEST(Distributions, IdealGasHasUnitPairDistributionInSpaceAndInTheShearPlane) {
  const Configuration c = ideal_gas(6000, 24.0, 7);
  const PairDistribution p = pair_distribution(c, 6.0, 0.5, 0.5, 1.0);
  double mean = 0.0;
  int bins = 0;
  for (std::size_t k = 0; k < p.r.size(); ++k)
    if (p.r[k] > 2.0) {
      EXPECT_NEAR(p.g[k], 1.0, 0.08) << "r = " << p.r[k];
      mean += p.g[k], ++bins;
    }
  EXPECT_NEAR(mean / bins, 1.0, 0.02);
  const std::size_t m = p.xy_centres.size();
  ASSERT_EQ(p.g_xy.size(), m * m);
  double sum = 0.0;
  for (double g : p.g_xy) sum += g;
  EXPECT_NEAR(sum / static_cast<double>(m * m), 1.0, 0.02);
  // The map is symmetric under d -> -d (both ends of every pair are counted).
  for (std::size_t iy = 0; iy < m; ++iy)
    for (std::size_t ix = 0; ix < m; ++ix)
      EXPECT_DOUBLE_EQ(p.g_xy[iy * m + ix], p.g_xy[(m - 1 - iy) * m + (m - 1 - ix)]);
}

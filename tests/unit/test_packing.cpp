// Random packings: no overlap (brute force over all pairs), the requested volume fraction and species volume shares,
// reproducibility from the seed (also across thread counts), and a clear error for an unreachable volume fraction.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"
#include "dem/packing.hpp"

using namespace suspend;

namespace {
// Equal-volume bidisperse mixture, size ratio 1.4: the standard dense-suspension benchmark.
std::vector<double> bidisperse(std::size_t n, double ratio = 1.4, double large_share = 0.5) {
  const std::vector<Species> species{{1.0, 1.0 - large_share}, {ratio, large_share}};
  return species_radii(species, species_counts(species, n));
}

double brute_force_min_gap(const std::vector<Vec3>& x, const std::vector<double>& a, const Box& box) {
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j)
      gap = std::min(gap, box.minimum_image(x[i], x[j]).d.norm() - a[i] - a[j]);
  return gap;
}

double exact_volume_fraction(const std::vector<double>& a, const Box& box) {
  double v = 0.0;
  for (double r : a) v += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  return v / (box.length().x() * box.length().y() * box.length().z());
}
}  // namespace

TEST(Packing, DenseBidisperseHasNoOverlapAndTheTargetVolumeFraction) {
  const auto a = bidisperse(300);
  const Box box = cube_for_volume_fraction(a, 0.60);
  PackingParams params;
  params.seed = 3;
  params.min_gap = 1e-6;
  const Packing p = random_packing(a, box, params);
  ASSERT_EQ(p.position.size(), a.size());
  const double gap = brute_force_min_gap(p.position, a, box);
  EXPECT_GE(gap, params.min_gap);
  EXPECT_NEAR(p.report.min_gap, gap, 1e-12);
  EXPECT_NEAR(exact_volume_fraction(a, box), 0.60, 1e-3);
  EXPECT_NEAR(p.report.phi, exact_volume_fraction(a, box), 1e-12);
  for (const Vec3& r : p.position)
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(r[k], 0.0);
      EXPECT_LT(r[k], box.length()[k]);
    }
  EXPECT_GT(p.report.iterations, 0);
  EXPECT_GE(p.report.wall_seconds, 0.0);
}

TEST(Packing, UserMinimumGapIsRespectedInAnElongatedBox) {
  const auto a = bidisperse(300, 2.0, 0.3);
  const Box box(18.0, 14.0, 16.0);
  PackingParams params;
  params.min_gap = 0.05;
  const Packing p = random_packing(a, box, params);
  EXPECT_GE(brute_force_min_gap(p.position, a, box), 0.05);
  EXPECT_NEAR(p.report.phi, exact_volume_fraction(a, box), 1e-12);
}

TEST(Packing, SameSeedSamePositionsOtherSeedOtherPositions) {
  const auto a = bidisperse(200);
  const Box box = cube_for_volume_fraction(a, 0.55);
  PackingParams params;
  params.seed = 11;
  const Packing first = random_packing(a, box, params);
  const Packing again = random_packing(a, box, params);
  params.seed = 12;
  const Packing other = random_packing(a, box, params);
  bool all_same = true, any_same = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    all_same = all_same && (first.position[i] == again.position[i]);  // bit-identical
    any_same = any_same || (first.position[i] == other.position[i]);
  }
  EXPECT_TRUE(all_same);
  EXPECT_FALSE(any_same);
}

TEST(Packing, BitIdenticalForAnyThreadCount) {
  // Above the OpenMP threshold of the force loop, so the parallel path is the one compared.
  const auto a = bidisperse(4200);
  const Box box = cube_for_volume_fraction(a, 0.25);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Packing serial = random_packing(a, box);
  omp_set_num_threads(2);
  const Packing parallel = random_packing(a, box);
  omp_set_num_threads(threads);
  ASSERT_EQ(serial.position.size(), parallel.position.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(serial.position[i], parallel.position[i]) << "particle " << i;
}

TEST(Packing, UnreachableVolumeFractionIsAnInputErrorNamingTheHighestReached) {
  const auto a = bidisperse(120);
  const Box box = cube_for_volume_fraction(a, 0.80);
  PackingParams params;
  params.max_retries = 1;
  try {
    random_packing(a, box, params);
    FAIL() << "phi = 0.80 cannot be packed without overlap";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("volume fraction 0.8000 is unreachable"), std::string::npos) << message;
    EXPECT_NE(message.find("highest reached without overlap: 0."), std::string::npos) << message;
  }
}

TEST(Packing, BadInputIsRejected) {
  const auto a = bidisperse(50);
  PackingParams params;
  params.min_gap = -1.0;
  EXPECT_THROW(random_packing(a, Box(20, 20, 20), params), InputError);
  EXPECT_THROW(random_packing(a, Box(2.5, 20, 20)), InputError);  // narrower than a large sphere
  EXPECT_THROW(random_packing({1.0, -1.0}, Box(20, 20, 20)), InputError);
  EXPECT_THROW(cube_for_volume_fraction(a, 1.2), InputError);
}

TEST(Packing, CubeHasTheRequestedVolumeFraction) {
  const auto a = bidisperse(777, 3.0, 0.2);
  const Box box = cube_for_volume_fraction(a, 0.5);
  EXPECT_NEAR(exact_volume_fraction(a, box), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(box.length().x(), box.length().z());
}

TEST(SpeciesCounts, ExactWhenTheSharesAllowIt) {
  // Size ratio 2, equal volumes: eight small spheres per large one.
  const std::vector<Species> species{{1.0, 0.5}, {2.0, 0.5}};
  EXPECT_EQ(species_counts(species, 900), (std::vector<std::size_t>{800, 100}));
}

TEST(SpeciesCounts, VolumeSharesMatchTheRequestWithinOneParticle) {
  for (const auto& species : {std::vector<Species>{{1.0, 0.5}, {1.4, 0.5}}, std::vector<Species>{{1.0, 0.8}, {3.0, 0.2}},
                              std::vector<Species>{{1.0, 0.2}, {1.2, 0.3}, {1.5, 0.5}}}) {
    for (std::size_t total : {200u, 1000u, 65536u}) {
      const auto counts = species_counts(species, total);
      std::size_t sum = 0;
      double volume = 0.0;
      for (std::size_t k = 0; k < species.size(); ++k) {
        sum += counts[k];
        volume += counts[k] * std::pow(species[k].radius, 3);
      }
      EXPECT_EQ(sum, total);
      for (std::size_t k = 0; k < species.size(); ++k) {
        const double share = counts[k] * std::pow(species[k].radius, 3) / volume;
        const double one_particle = std::pow(species.back().radius, 3) / volume;
        EXPECT_NEAR(share, species[k].volume_share, one_particle) << "species " << k << ", N = " << total;
      }
    }
  }
}

TEST(SpeciesCounts, FromABoxFillTheVolumeFraction) {
  const std::vector<Species> species{{1.0, 0.8}, {3.0, 0.2}};
  const Box box(60.0, 50.0, 40.0);
  const auto counts = species_counts(species, 0.5, box);
  const auto a = species_radii(species, counts);
  ASSERT_EQ(a.size(), counts[0] + counts[1]);
  // Rounding each count to the nearest integer moves phi by at most half a particle volume per species.
  const double half_particles = 0.5 * 4.0 / 3.0 * std::numbers::pi * (1.0 + 27.0) / box.volume();
  EXPECT_NEAR(exact_volume_fraction(a, box), 0.5, half_particles);
  EXPECT_NEAR(4.0 / 3.0 * std::numbers::pi * 27.0 * counts[1] / box.volume(), 0.5 * 0.2,
              0.5 * 4.0 / 3.0 * std::numbers::pi * 27.0 / box.volume());
  EXPECT_THROW(species_counts({{1.0, 0.6}, {2.0, 0.6}}, 100), InputError);  // shares must sum to 1
}

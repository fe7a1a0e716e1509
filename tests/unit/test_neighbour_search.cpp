// Cell-list search against brute force on random polydisperse boxes, with Lees-Edwards offsets.
#include <gtest/gtest.h>

#include <omp.h>

#include <random>

#include "dem/neighbour_search.hpp"

using namespace suspend;

namespace {
struct Config {
  std::vector<Vec3> position;
  std::vector<double> radius;
};
Config random_config(int n, const Vec3& L, double size_ratio, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Config c;
  for (int i = 0; i < n; ++i) {
    c.position.emplace_back(L.x() * u(rng), L.y() * u(rng), L.z() * u(rng));
    c.radius.push_back(u(rng) < 0.5 ? 1.0 : size_ratio);
  }
  return c;
}
}  // namespace

class NeighbourSearchVsBruteForce : public ::testing::TestWithParam<std::tuple<double, double>> {};

TEST_P(NeighbourSearchVsBruteForce, SamePairs) {
  const auto [size_ratio, offset_fraction] = GetParam();
  const Vec3 L(23.0, 19.0, 21.0);
  Box box(L);
  box.set_shear_offset(offset_fraction * L.x());
  const Config c = random_config(900, L, size_ratio, 7);
  std::vector<NeighbourPair> fast, slow;
  CellListSearch search;
  search.find_pairs(c.position, c.radius, box, 0.3, fast);
  find_pairs_brute_force(c.position, c.radius, box, 0.3, slow);
  EXPECT_GT(search.cells()[0], 0) << "the cell list, not the fallback, must be tested";
  EXPECT_FALSE(slow.empty());
  EXPECT_EQ(fast, slow);
}

INSTANTIATE_TEST_SUITE_P(OffsetsAndSizeRatios, NeighbourSearchVsBruteForce,
                         ::testing::Combine(::testing::Values(1.0, 1.4, 3.0),
                                            ::testing::Values(0.0, 0.137, -0.4999, 0.4999, -0.5)));

TEST(NeighbourSearch, ThreeCellsPerAxisWithShearDoesNotDoubleCount) {
  // The sheared window spans four x cells but only three exist: each pair must still appear once.
  const Vec3 L(9.5, 9.5, 9.5);
  Box box(L);
  const Config c = random_config(300, L, 1.4, 11);
  for (double f : {0.0, 0.1, 0.33, 0.49, -0.2}) {
    box.set_shear_offset(f * L.x());
    std::vector<NeighbourPair> fast, slow;
    CellListSearch search;
    search.find_pairs(c.position, c.radius, box, 0.2, fast);
    find_pairs_brute_force(c.position, c.radius, box, 0.2, slow);
    EXPECT_EQ(search.cells()[0], 3);
    EXPECT_EQ(fast, slow) << "offset fraction " << f;
  }
}

TEST(NeighbourSearch, FullStencilListsTheSamePairs) {
  // The benchmark's full stencil (every pair met from both cells, both y faces crossed through the sheared image)
  // against brute force.
  const Vec3 L(23.0, 19.0, 21.0);
  Box box(L);
  const Config c = random_config(900, L, 1.4, 13);
  for (double f : {0.0, 0.137, -0.4999, 0.4999}) {
    box.set_shear_offset(f * L.x());
    std::vector<NeighbourPair> fast, slow;
    CellListSearch search(Stencil::full);
    search.find_pairs(c.position, c.radius, box, 0.3, fast);
    find_pairs_brute_force(c.position, c.radius, box, 0.3, slow);
    EXPECT_FALSE(slow.empty());
    EXPECT_EQ(fast, slow) << "offset fraction " << f;
  }
}

TEST(NeighbourSearch, SameListForAnyThreadCount) {
  // 1500 particles: binning and the final ordering both run in parallel (above 1024 particles).
  const Vec3 L(25.0, 25.0, 25.0);
  Box box(L);
  box.set_shear_offset(0.21 * L.x());
  const Config c = random_config(1500, L, 1.4, 5);
  std::vector<NeighbourPair> one, two, slow;
  CellListSearch search;
  omp_set_num_threads(1);
  search.find_pairs(c.position, c.radius, box, 0.3, one);
  omp_set_num_threads(2);
  search.find_pairs(c.position, c.radius, box, 0.3, two);
  find_pairs_brute_force(c.position, c.radius, box, 0.3, slow);
  EXPECT_EQ(one, slow);
  EXPECT_EQ(two, slow);
}

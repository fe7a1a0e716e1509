// Block averaging against series whose mean and standard error are known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "io/statistics.hpp"

using suspend::io::block_average;

namespace {
// AR(1): x_n = mu + rho (x_{n-1} - mu) + noise, stationary variance s^2. Its mean over n samples has standard error
// s / sqrt(n) * sqrt((1 + rho) / (1 - rho)) for n >> correlation time (1 + rho) / (1 - rho).
std::vector<double> ar1(std::size_t n, double mu, double rho, double s, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, s * std::sqrt(1.0 - rho * rho));
  std::vector<double> x(n);
  double v = mu + std::normal_distribution<double>(0.0, s)(rng);
  for (auto& xi : x) xi = v = mu + rho * (v - mu) + g(rng);
  return x;
}
}  // namespace

TEST(BlockAverage, UncorrelatedSeriesGivesTheTextbookError) {
  const std::size_t n = 1 << 14;
  const auto x = ar1(n, 3.0, 0.0, 2.0, 1);
  const auto r = block_average(x);
  EXPECT_NEAR(r.mean, 3.0, 4.0 * 2.0 / std::sqrt(n));
  EXPECT_NEAR(r.sem, 2.0 / std::sqrt(n), 0.15 * 2.0 / std::sqrt(n));
}

TEST(BlockAverage, CorrelatedSeriesRecoversTheInflatedError) {
  const std::size_t n = 1 << 16;
  const double rho = 0.95, s = 1.0;
  const double exact = s / std::sqrt(n) * std::sqrt((1 + rho) / (1 - rho));  // correlation time ~ 39 samples
  // Averaged over independent series so the test checks the estimator, not one draw.
  double sem_sum = 0.0;
  int inside = 0;
  const int trials = 40;
  for (int t = 0; t < trials; ++t) {
    const auto r = block_average(ar1(n, -1.0, rho, s, 100 + t));
    sem_sum += r.sem;
    if (std::abs(r.mean + 1.0) < 2.0 * r.sem) ++inside;
  }
  EXPECT_NEAR(sem_sum / trials, exact, 0.15 * exact);
  EXPECT_GE(inside, 34) << "about 95% of 2-sigma intervals must contain the true mean";
  // The naive error ignores the correlation and is far too small.
  const auto naive = block_average(ar1(n, -1.0, rho, s, 7), n);
  EXPECT_LT(naive.sem, 0.4 * exact);
}

TEST(BlockAverage, ShortAndConstantSeries) {
  EXPECT_EQ(block_average({}).samples, 0u);
  const auto one = block_average({2.5});
  EXPECT_DOUBLE_EQ(one.mean, 2.5);
  EXPECT_DOUBLE_EQ(one.sem, 0.0);
  const auto flat = block_average(std::vector<double>(100, 4.0));
  EXPECT_DOUBLE_EQ(flat.mean, 4.0);
  EXPECT_DOUBLE_EQ(flat.sem, 0.0);
}

// The step bound from the relative motion of the interacting pairs (dem/integrate/pair_motion.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "dem/integrate/pair_motion.hpp"
#include "dem/integrate/time_step_control.hpp"
#include "tests/simulation_state.hpp"

using namespace suspend;

namespace {

const PairMotionLimits limits{5e-4, 2e-3, 5e-3, 0.1};

// Particles i = 0, j = 1 at distance r along x, radii 1.
Particles pair_at(double r) {
  Particles p = test_support::state_of({Vec3(5.0, 5.0, 5.0), Vec3(5.0 + r, 5.0, 5.0)}, {1.0, 1.0}).particles;
  return p;
}

ActivePair active(const Particles& p, int y_images = 0) {
  return {0, 1, y_images, PairGeometry::from(p.position[1] - p.position[0], 1.0, 1.0)};
}

}  // namespace

TEST(PairMotion, AContactIsBoundByItsNormalMotionAndItsSlip) {
  Particles p = pair_at(2.001);  // gap 1e-3 inside the roughness range 5e-3
  p.velocity[1] = Vec3(0.1, 0.0, 0.0);  // closing along n at 0.1
  const std::vector<ActivePair> pairs{active(p)};
  std::vector<ContactRecord> records(1);
  records[0].contact = true;
  EXPECT_DOUBLE_EQ(pair_motion_rate(pairs, p, 0.0, records, limits), 0.1 / 5e-4);
  p.velocity[1] = Vec3(0.0, 0.6, 0.0);  // sliding across n at 0.6
  EXPECT_DOUBLE_EQ(pair_motion_rate(pairs, p, 0.0, records, limits), 0.6 / 2e-3);
  // Rolling without slip (contact point at rest) and a rigid rotation of the pair: nothing to bound.
  p.velocity[1] = Vec3::Zero();
  p.angular_velocity[0] = p.angular_velocity[1] = Vec3(0.0, 0.0, 0.7);
  p.velocity[1] = Vec3(0.0, 0.0, 0.7).cross(p.position[1] - p.position[0]);
  EXPECT_NEAR(pair_motion_rate(pairs, p, 0.0, records, limits), 0.0, 1e-12);
}

TEST(PairMotion, AnApproachingPairClosesAFractionOfItsDistanceToContact) {
  Particles p = pair_at(2.205);  // gap 0.205: 0.2 beyond the contact range
  p.velocity[0] = Vec3(0.05, 0.0, 0.0);
  p.velocity[1] = Vec3(-0.05, 3.0, 0.0);  // the tangential motion of a pair out of contact is not bound
  const std::vector<ActivePair> pairs{active(p)};
  const std::vector<ContactRecord> records(1);
  EXPECT_NEAR(pair_motion_rate(pairs, p, 0.0, records, limits), 0.1 / (5e-4 + 0.1 * 0.2), 1e-12);
  // The same pair across the sheared y face: its image moves at u_j - y_images gammadot L_y.
  Particles q = pair_at(2.205);
  q.velocity[1] = Vec3(1.5, 0.0, 0.0);  // j's own velocity; its image (y_images 1, image velocity 1.5) is at rest
  EXPECT_NEAR(pair_motion_rate({active(q, 1)}, q, 1.5, records, limits), 0.0, 1e-15);
}

TEST(PairMotion, RankTwoIsTheSecondFastestPair) {
  // Particles 0-1 in contact closing at 0.1 (rate 200), 2-3 out of contact approaching at 0.1 across a gap of 0.205
  // (rate 0.1 / 0.0205), 4-5 in contact sliding at 0.6 (rate 300).
  Particles p = test_support::state_of({Vec3(5, 5, 5), Vec3(7.001, 5, 5), Vec3(5, 9, 5), Vec3(7.205, 9, 5),
                                        Vec3(5, 13, 5), Vec3(7.001, 13, 5)},
                                       {1, 1, 1, 1, 1, 1})
                    .particles;
  p.velocity[1] = Vec3(-0.1, 0.0, 0.0);
  p.velocity[3] = Vec3(-0.1, 0.0, 0.0);
  p.velocity[5] = Vec3(0.0, 0.6, 0.0);
  auto pair = [&](int i, int j) {
    return ActivePair{static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), 0,
                      PairGeometry::from(p.position[j] - p.position[i], 1.0, 1.0)};
  };
  const std::vector<ActivePair> pairs{pair(0, 1), pair(2, 3), pair(4, 5)};
  std::vector<ContactRecord> records(3);
  records[0].contact = records[2].contact = true;
  KthLargest scratch;
  StepLimit kind = StepLimit::fixed;
  EXPECT_DOUBLE_EQ(pair_motion_rate(pairs, p, 0.0, records, limits, 1, nullptr, &kind), 0.6 / 2e-3);
  EXPECT_EQ(kind, StepLimit::slip);
  EXPECT_DOUBLE_EQ(pair_motion_rate(pairs, p, 0.0, records, limits, 1, &scratch), 0.6 / 2e-3);
  EXPECT_DOUBLE_EQ(pair_motion_rate(pairs, p, 0.0, records, limits, 2, &scratch, &kind), 0.1 / 5e-4);
  EXPECT_EQ(kind, StepLimit::contact_normal);  // the ranked pair's kind, not the fastest one's
  EXPECT_NEAR(pair_motion_rate(pairs, p, 0.0, records, limits, 3, &scratch, &kind), 0.1 / (5e-4 + 0.1 * 0.2), 1e-12);
  EXPECT_EQ(kind, StepLimit::approach);
  EXPECT_EQ(bound_rank(999, 500), 1u);
  EXPECT_EQ(bound_rank(2000, 500), 4u);
  EXPECT_EQ(bound_rank(65536, 0), 1u);
}

TEST(PairMotion, PairsBoundFollowsTheFastestPairNotTheFastestParticle) {
  TimeStepParams ts;
  ts.implicit_contacts = true;
  const ContactLaw law = ComposedLaw<HertzAdhesiveCoulomb>{};
  const double h_r = contact_range(law);
  ASSERT_GT(h_r, 0.0);
  const double last_dt = 1.0;
  StepLimit limit = StepLimit::fixed;
  // A particle moving at 0.2 relative to the flow, with no pair moving: the particle bound, max_displacement / 0.2.
  EXPECT_DOUBLE_EQ(overdamped_time_step(ts, law, 0.01, 0.2, 1.0, last_dt, 0.0, {}, &limit), ts.max_displacement / 0.2);
  EXPECT_EQ(limit, StepLimit::particles);
  // The former rule: the contact displacement (a tenth of the range) for every particle.
  TimeStepParams former = ts;
  former.bound = TimeStepParams::Bound::particles;
  EXPECT_DOUBLE_EQ(overdamped_time_step(former, law, 0.01, 0.2, 1.0, last_dt, 0.0), 0.1 * h_r / 0.2);
  // A pair rate above the particle bound decides, and says which kind of pair motion it was.
  EXPECT_DOUBLE_EQ(overdamped_time_step(ts, law, 0.01, 0.2, 1.0, last_dt, 0.0, {1000.0, StepLimit::slip}, &limit),
                   1e-3);
  EXPECT_EQ(limit, StepLimit::slip);
  // Nothing moves: the strain increment, then the growth of the implicit step over the last one.
  EXPECT_DOUBLE_EQ(overdamped_time_step(ts, law, 1e-3, 0.0, 1.0, last_dt, 0.0, {}, &limit), ts.growth * last_dt);
  EXPECT_EQ(limit, StepLimit::growth);
  EXPECT_DOUBLE_EQ(overdamped_time_step(ts, law, 1.0, 0.0, 1.0, last_dt, 0.0, {}, &limit), ts.max);
  EXPECT_EQ(limit, StepLimit::strain);
  TimeStepParams fixed = ts;
  fixed.mode = TimeStepParams::Mode::fixed;
  EXPECT_DOUBLE_EQ(overdamped_time_step(fixed, law, 1.0, 0.2, 1.0, last_dt, 0.0, {}, &limit), fixed.fixed);
  EXPECT_EQ(limit, StepLimit::fixed);
  EXPECT_DOUBLE_EQ(contact_displacement(ts, law, 0.0), 0.1 * h_r);
  EXPECT_DOUBLE_EQ(contact_displacement(ts, law, 1e-4), 4e-4);  // four compliance lengths
}

TEST(StepLimitCounts, SharesAreLargestFirstAndLeaveOutBoundsThatSetNoStep) {
  StepLimitCounts counts;
  EXPECT_EQ(counts.shares(), "");
  for (int k = 0; k < 3; ++k) counts.add(StepLimit::slip);
  counts.add(StepLimit::approach);
  EXPECT_EQ(counts.total(), 4);
  EXPECT_EQ(counts[StepLimit::slip], 3);
  EXPECT_EQ(counts.shares(), "slip 75%, approach 25%");
}

TEST(BoundingSpeed, IsTheFastestOfEveryFastestOfParticles) {
  std::vector<double> speeds{0.3, 2.0, 0.1, 1.5, 0.7, 1.9};
  std::vector<double> s = speeds;
  EXPECT_EQ(bounding_speed(s, 0), 2.0);  // the fastest of all
  s = speeds;
  EXPECT_EQ(bounding_speed(s, 4), 2.0);  // 6 / 4 = 1: the fastest
  s = speeds;
  EXPECT_EQ(bounding_speed(s, 3), 1.9);  // 6 / 3 = 2: the second fastest
  s = speeds;
  EXPECT_EQ(bounding_speed(s, 2), 1.5);  // the third
  std::vector<double> none;
  EXPECT_EQ(bounding_speed(none, 500), 0.0);
}

// The point of the rule: for speeds with Gaussian tails the fastest of N grows with N (extreme value, ~ sqrt(2 ln N)),
// the fastest of every 500 does not. Speeds |v| of 3-d Gaussian velocities (Maxwell), 20 seeded draws per N.
TEST(BoundingSpeed, DoesNotGrowWithTheNumberOfParticles) {
  auto mean_bound = [](std::size_t n, int fastest_of) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g;
    double sum = 0.0;
    for (int draw = 0; draw < 20; ++draw) {
      std::vector<double> s(n);
      for (double& v : s) {
        const double x = g(rng), y = g(rng), z = g(rng);
        v = std::sqrt(x * x + y * y + z * z);
      }
      sum += bounding_speed(s, fastest_of);
    }
    return sum / 20.0;
  };
  const double max_500 = mean_bound(500, 0), max_8000 = mean_bound(8000, 0);
  const double rule_500 = mean_bound(500, 500), rule_8000 = mean_bound(8000, 500);
  EXPECT_EQ(max_500, rule_500);            // below 1000 particles: the fastest of all, as before
  EXPECT_GT(max_8000 / max_500, 1.15);     // Maxwell tail: 4.58 / 3.98 expected
  EXPECT_NEAR(rule_8000 / rule_500, 1.0, 0.04);
}

TEST(KthLargest, IsTheKthLargestOfTheStream) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> values(1000);
  for (double& v : values) v = u(rng);
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end(), std::greater<>());
  for (const std::size_t k : {1u, 2u, 7u, 1000u, 1500u}) {
    KthLargest ranking;
    ranking.reset(k);
    for (double v : values) ranking.add(v);
    EXPECT_EQ(ranking.value(), sorted[std::min<std::size_t>(k, sorted.size()) - 1]) << k;
    std::vector<double> copy = values;
    EXPECT_EQ(ranking.value(), kth_largest(copy, k)) << k;
  }
  KthLargest none;
  none.reset(3);
  EXPECT_EQ(none.value(), 0.0);
  EXPECT_EQ(none.tag(), -1);
  // The tag travels with its value: the 2nd largest of 0.5 (tag 1), 0.9 (tag 2), 0.7 (tag 3) is 0.7, tag 3.
  KthLargest tagged;
  tagged.reset(2);
  tagged.add(0.5, 1);
  tagged.add(0.9, 2);
  tagged.add(0.7, 3);
  EXPECT_EQ(tagged.value(), 0.7);
  EXPECT_EQ(tagged.tag(), 3);
}

// O(N)-memory contact history store (paper 000 section 2.1): insert/lookup/release, orientation of the stored
// stretch, sorted bounded rows, paper 000's capacity estimate, memory proportional to the contacts, restore from
// checkpoint entries, carrying histories across a neighbour-list rebuild with a different pair order, and a
// frictional contact that keeps its history while its particles wrap through the periodic (Lees-Edwards) faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "contact_test_support.hpp"
#include "core/box.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact_history.hpp"

using namespace suspend;
using namespace suspend::test;

namespace {
PairHistory contact(double tx, double rx = 0.0) { return {Vec3(tx, 0.5 * tx, 0.0), Vec3(rx, 0.0, 0.0), true}; }
}  // namespace

TEST(ContactHistory, InsertLookupUpdateRelease) {
  ContactHistory store(10, 4);
  EXPECT_FALSE(store.lookup(3, 7).in_contact);
  store.store(3, 7, contact(1.0));
  store.store(3, 1, contact(2.0));
  EXPECT_TRUE(store.contains(7, 3));
  EXPECT_EQ(store.size(), 2u);
  EXPECT_EQ(store.lookup(3, 7).tangential_stretch, contact(1.0).tangential_stretch);
  store.store(3, 7, contact(5.0));  // update in place
  EXPECT_EQ(store.size(), 2u);
  EXPECT_EQ(store.lookup(3, 7).tangential_stretch, contact(5.0).tangential_stretch);
  store.release(7, 3);
  EXPECT_FALSE(store.contains(3, 7));
  EXPECT_EQ(store.lookup(3, 7).tangential_stretch, Vec3::Zero());
  store.store(3, 1, PairHistory{});  // a separated pair is released
  EXPECT_EQ(store.size(), 0u);
  EXPECT_THROW(store.lookup(3, 3), InputError);
  EXPECT_THROW(store.lookup(3, 10), InputError);
}

TEST(ContactHistory, TheNormalLawsStateTravelsWithThePairInEitherOrder) {
  ContactHistory store(6, 4);
  store.store(4, 2, {Vec3(1.0, 0.0, 0.0), Vec3::Zero(), true, 0.25});
  EXPECT_EQ(store.lookup(2, 4).normal_state, 0.25);  // a scalar of the pair: no orientation
  EXPECT_EQ(store.lookup(4, 2).normal_state, 0.25);
  std::vector<NeighbourPair> pairs = {{2, 4}, {1, 5}};
  std::vector<PairHistory> h(2);
  store.gather(pairs, h);
  h[1] = {Vec3::Zero(), Vec3::Zero(), true, 0.5};
  store.scatter(pairs, h);
  EXPECT_EQ(store.lookup(5, 1).normal_state, 0.5);
  EXPECT_EQ(store.entries()[1].history.normal_state, 0.25);  // rows in order: (1, 5), then (2, 4)
}

TEST(ContactHistory, PairSeenInReverseOrderGetsTheSwappedStretch) {
  ContactHistory store(6, 4);
  store.store(4, 2, contact(1.0, 3.0));
  const PairHistory forward = store.lookup(2, 4);
  EXPECT_EQ(forward.tangential_stretch, -contact(1.0).tangential_stretch);
  EXPECT_EQ(forward.rolling_stretch, contact(1.0, 3.0).rolling_stretch);  // u_r is symmetric under the swap
  EXPECT_EQ(store.lookup(4, 2).tangential_stretch, contact(1.0).tangential_stretch);
}

TEST(ContactHistory, PaperCapacityEstimateAndBoundedMemory) {
  EXPECT_EQ(ContactHistory::capacity_for(1.0, 1.0), 26u);   // (3^3 - 1) spheres in the shell of thickness 2 a
  EXPECT_EQ(ContactHistory::capacity_for(1.0, 1.4), 37u);   // 3.4^3 - 1.4^3 = 36.56
  EXPECT_EQ(ContactHistory::capacity_for(1.0, 3.0), 98u);   // 5^3 - 3^3, paper 000's a_2/a_1 = 3 suspension
  ContactHistory store(5, 3);
  store.store(0, 4, contact(1.0));
  store.store(0, 2, contact(2.0));
  store.store(0, 3, contact(3.0));
  EXPECT_THROW(store.store(0, 1, contact(4.0)), NumericalError);  // row full: reported, not dropped silently
  EXPECT_EQ(store.size(), 3u);
  EXPECT_EQ(store.lookup(0, 3).tangential_stretch, contact(3.0).tangential_stretch);  // sorted insert kept rows
  EXPECT_EQ(store.lookup(0, 2).tangential_stretch, contact(2.0).tangential_stretch);
  // scatter enforces the same bound.
  const std::vector<NeighbourPair> four = {{0, 1}, {0, 2}, {3, 0}, {0, 4}};
  const std::vector<PairHistory> in(four.size(), contact(1.0));
  EXPECT_THROW(store.scatter(four, in), NumericalError);
}

TEST(ContactHistory, MemoryGrowsWithTheContactsNotWithTheCapacity) {
  // 20000 particles with the a_2/a_1 = 3 capacity (M = 98): N x M slots would take 20000 x 98 x 64 B = 125 MB;
  // one contact per particle must cost a few tens of bytes per particle.
  const std::uint32_t n = 20000;
  ContactHistory store(n, ContactHistory::capacity_for(1.0, 3.0));
  std::vector<NeighbourPair> pairs;
  for (std::uint32_t i = 0; i + 1 < n; i += 2) pairs.push_back({i, i + 1});
  const std::vector<PairHistory> in(pairs.size(), contact(1.0, 2.0));
  store.scatter(pairs, in);
  EXPECT_EQ(store.size(), pairs.size());
  // Per particle: its row offset and cursor (8 B) and half a contact of partner, source (8 B) and stretches with the
  // normal and twisting states (64 B): 44 B.
  EXPECT_LE(store.memory_bytes(), 45u * n);
  std::vector<PairHistory> out(pairs.size());
  store.gather(pairs, out);
  for (const PairHistory& h : out) {
    EXPECT_TRUE(h.in_contact);
    EXPECT_EQ(h.rolling_stretch, contact(1.0, 2.0).rolling_stretch);
  }
}

TEST(ContactHistory, RestoreOfEntriesReproducesTheStore) {
  ContactHistory a(8, 5), b(8, 5);
  a.store(5, 2, contact(1.0, 2.0));
  a.store(0, 7, contact(3.0));
  a.store(2, 6, contact(4.0, -1.0));
  b.store(1, 3, contact(9.0));  // replaced by the restore
  b.restore(a.entries());
  ASSERT_EQ(b.size(), 3u);
  const auto ea = a.entries(), eb = b.entries();
  for (std::size_t k = 0; k < ea.size(); ++k) {
    EXPECT_EQ(ea[k].i, eb[k].i);
    EXPECT_EQ(ea[k].j, eb[k].j);
    EXPECT_EQ(ea[k].history.tangential_stretch, eb[k].history.tangential_stretch);
    EXPECT_EQ(ea[k].history.rolling_stretch, eb[k].history.rolling_stretch);
  }
  EXPECT_EQ(b.lookup(2, 5).tangential_stretch, -contact(1.0).tangential_stretch);
  EXPECT_FALSE(b.contains(1, 3));
}

TEST(ContactHistory, HistoriesSurviveARebuildWithADifferentPairOrder) {
  const std::uint32_t n = 50;
  std::mt19937_64 rng(51);
  std::vector<NeighbourPair> pairs;
  std::uniform_int_distribution<std::uint32_t> pick(0, n - 1);
  while (pairs.size() < 120) {
    const std::uint32_t i = pick(rng), j = pick(rng);
    if (i == j) continue;
    const NeighbourPair p{std::min(i, j), std::max(i, j)};
    if (std::find(pairs.begin(), pairs.end(), p) == pairs.end()) pairs.push_back(p);
  }
  std::vector<PairHistory> h(pairs.size());
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = {random_vector(rng), random_vector(rng), k % 3 != 0};
  ContactHistory store(n, ContactHistory::capacity_for(1.0, 1.4));
  store.scatter(pairs, h);
  EXPECT_EQ(store.size(), 80u);  // the pairs not in contact were released

  // Rebuild: shuffled, a third of the pairs listed as (j, i), some dropped, some new.
  std::vector<NeighbourPair> rebuilt;
  std::vector<PairHistory> expected;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (k % 7 == 0) continue;  // left the neighbour list
    const bool reverse = k % 3 == 1;
    rebuilt.push_back(reverse ? NeighbourPair{pairs[k].j, pairs[k].i} : pairs[k]);
    const PairHistory stored = h[k].in_contact ? h[k] : PairHistory{};
    expected.push_back(reverse ? stored.swapped() : stored);
  }
  rebuilt.push_back({7, 7 + n / 2});
  expected.push_back({});
  std::vector<std::size_t> order(rebuilt.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<NeighbourPair> shuffled;
  for (auto k : order) shuffled.push_back(rebuilt[k]);

  std::vector<PairHistory> got(shuffled.size());
  store.gather(shuffled, got);
  for (std::size_t s = 0; s < shuffled.size(); ++s) {
    const PairHistory& e = expected[order[s]];
    EXPECT_EQ(got[s].in_contact, e.in_contact);
    EXPECT_EQ(got[s].tangential_stretch, e.in_contact ? e.tangential_stretch : Vec3::Zero());
    EXPECT_EQ(got[s].rolling_stretch, e.in_contact ? e.rolling_stretch : Vec3::Zero());
  }
  // Scatter with the new list: pairs absent from it are released, the rest stay.
  store.scatter(shuffled, got);
  std::size_t in_contact = 0;
  for (const auto& g : got) in_contact += g.in_contact ? 1 : 0;
  EXPECT_EQ(store.size(), in_contact);
  for (std::size_t k = 0; k < pairs.size(); k += 7) EXPECT_FALSE(store.contains(pairs[k].i, pairs[k].j));
}

TEST(ContactHistory, FrictionalContactKeepsItsHistoryThroughPeriodicWraps) {
  // A sliding pair straddling the sheared y face and drifting through the x face: positions are wrapped every
  // step, indices never change, and the tangential force matches the same motion in unbounded space.
  Box box(10.0, 10.0, 10.0);
  box.set_shear_offset(3.0);
  LinearSpringCoulomb law;
  law.normal.p = {1.0e4};
  law.kt = 2.0e3;
  law.friction.p.mu = 0.5;
  const double dt = 1e-3;
  const Vec3 u_i(200.0, 0.0, 0.0), u_j(200.4, 0.0, 0.3);  // both cross x = 10 during the run; j slides
  const Vec3 d0(0.0, 1.99, 0.0);
  Vec3 r_i(9.0, 9.0, 5.0), r_j = r_i + d0;
  box.wrap(r_i);
  box.wrap(r_j);
  Vec3 free_i = r_i, free_j = free_i + d0;  // unbounded reference
  ContactHistory store(2, 26);
  const std::vector<NeighbourPair> pairs = {{0, 1}};
  std::vector<PairHistory> h(1);
  PairHistory reference;
  int x_crossings = 0;
  for (int step = 0; step < 20; ++step) {
    const RelativeMotion m{u_i, u_j, Vec3::Zero(), Vec3::Zero()};
    store.gather(pairs, h);
    const PairForce f = law(PairGeometry::from(box.minimum_image(r_i, r_j).d, 1.0, 1.0), m, dt, h[0]);
    store.scatter(pairs, h);
    const PairForce f_ref = law(PairGeometry::from(free_j - free_i, 1.0, 1.0), m, dt, reference);
    EXPECT_LT((f.total_on_j() - f_ref.total_on_j()).norm(), 1e-7) << "step " << step;
    r_i += u_i * dt;
    r_j += u_j * dt;
    free_i += u_i * dt;
    free_j += u_j * dt;
    const double x_before = r_i.x();
    box.wrap(r_i);
    box.wrap(r_j);
    x_crossings += r_i.x() < x_before ? 1 : 0;
  }
  EXPECT_GE(x_crossings, 1);
  EXPECT_TRUE(store.contains(1, 0));
  // Sticking all along (k_t xi = 20 < mu F_n = 50): the stretch is the accumulated slip 20 steps x 0.5 x dt, up to
  // the round-off of positions of size 10 advanced in steps of 0.2.
  EXPECT_NEAR(store.lookup(0, 1).tangential_stretch.norm(), 20 * 0.5 * dt, 1e-6);
}

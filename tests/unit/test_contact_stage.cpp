// The contact stage keeps a history only for the pairs its contact law can touch (dem/contact_stage.hpp): pairs
// within the law's range or in contact before. A pair without a history slot that the law brings into contact is a
// NumericalError, never a silently lost history.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "dem/contact/contact_law.hpp"
#include "dem/contact_stage.hpp"
#include "dem/pair_forces.hpp"

using namespace suspend;

namespace {

// Two unit spheres along x with the given surface gap (negative: overlap), and a third one far from both.
Particles pair_at(double gap) {
  Particles p;
  p.resize(3);
  p.position = {Vec3(5, 5, 5), Vec3(7 + gap, 5, 5), Vec3(5, 5, 9)};
  p.radius = {1.0, 1.0, 1.0};
  p.velocity = {Vec3(0, 0.1, 0), Vec3(0, -0.1, 0), Vec3::Zero()};
  return p;
}

ComposedLaw<LinearSpringCoulomb> coulomb() {
  LinearSpringCoulomb law;
  law.normal.p.kn = 1e3;
  law.friction.p.mu = 0.5;
  return {law, {}};
}

}  // namespace

TEST(ContactStage, APairWithoutAHistorySlotMayNotComeIntoContact) {
  const Particles p = pair_at(-0.01);
  const std::vector<ActivePair> active{
      {0, 1, 0, PairGeometry::from(p.position[1] - p.position[0], 1.0, 1.0)}};
  std::vector<PairHistory> history(1);
  PairSums sums;
  std::vector<Vec3> pair_force;
  std::vector<PairSums> local;
  const std::vector<std::int32_t> slot{0}, none{-1};
  accumulate_pair_forces(active, p, 0.0, coulomb(), 1e-3, history, sums, pair_force, local, nullptr, nullptr, &slot);
  EXPECT_TRUE(history[0].in_contact);
  EXPECT_GT(history[0].tangential_stretch.norm(), 0.0);
  EXPECT_THROW(accumulate_pair_forces(active, p, 0.0, coulomb(), 1e-3, history, sums, pair_force, local, nullptr,
                                      nullptr, &none),
               NumericalError);
}

TEST(ContactStage, AContactKeepsItsHistoryAndAPairOutOfReachNeedsNone) {
  // Stage range 0.5 (a surface-force range, say): the pair at gap 0.3 is active but beyond the spring's range 0.
  const Box box(12, 12, 12);
  for (const double gap : {-0.01, 0.3}) {
    Particles p = pair_at(gap);
    ContactStage stage(0.5, 0.2, p, {});
    const ContactLaw law = coulomb();
    ASSERT_FALSE(stage.evaluate(p, box, 0.0, law, 1e-3, false, 0.1).has_value());
    ASSERT_EQ(stage.pairs().size(), 1u);
    stage.store_histories();
    const std::vector<ContactHistory::Entry> stored = stage.histories();
    if (gap < 0.0) {
      ASSERT_EQ(stored.size(), 1u);
      EXPECT_GT(stored[0].history.tangential_stretch.norm(), 0.0);
      // Apart by 0.01 at the next step: slotted because it is stored; the law ends the contact and the store
      // releases it.
      p.position[1].x() += 0.02;
      ASSERT_FALSE(stage.evaluate(p, box, 0.0, law, 1e-3, false, 0.1).has_value());
      stage.store_histories();
      EXPECT_TRUE(stage.histories().empty());  // separated: released
    } else {
      EXPECT_TRUE(stored.empty());
      EXPECT_EQ(stage.sums().contacts, 0u);
    }
  }
}

// The ContactLaw variant: each alternative composes its contact law with the optional surface forces, one visit
// evaluates a whole pair list, and SoftRepulsion (the original law) keeps its behaviour.
#include <gtest/gtest.h>

#include <vector>

#include "contact_test_support.hpp"
#include "dem/contact/contact_law.hpp"

using namespace suspend;
using namespace suspend::test;

TEST(ContactLaw, ComposedLawAddsSurfaceForcesOnTopOfTheContact) {
  ComposedLaw<LinearSpringCoulomb> composed;
  composed.contact.normal.p = {1.0e4};
  composed.contact.kt = 2.0e3;
  composed.surface.repulsion = ElectrostaticRepulsion{{1.0, 0.02, 20.0}};
  composed.surface.attraction = VanDerWaals{};
  const ContactLaw law = composed;
  validate(law);
  EXPECT_DOUBLE_EQ(interaction_range(law), 4.0);

  const PairGeometry g = PairGeometry::from(Vec3(1.99, 0.0, 0.0), 1.0, 1.0);
  const RelativeMotion m{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  PairHistory h;
  const PairForce f = std::visit([&](const auto& l) { return l(g, m, 1e-3, h); }, law);
  EXPECT_NEAR(f[Contribution::contact_normal].x(), 100.0, 1e-9);
  EXPECT_NEAR(f[Contribution::repulsion].x(), 1.0, 1e-12);  // plateau F_ER a-bar through overlap
  EXPECT_NEAR(f[Contribution::adhesion].x(), -1.0 / 19.0, 1e-12);
  EXPECT_NEAR(std::visit([&](const auto& l) { return l.energy(g); }, law),
              0.5e4 * 1e-4 + composed.surface.energy(g), 1e-12);
}

TEST(ContactLaw, SoftRepulsionIsOneAlternativeAndCarriesNoHistory) {
  const ContactLaw law = ComposedLaw<ContactModel<SoftRepulsion>>{{SoftRepulsion{{1.0e4}}}, {}};
  const PairGeometry g = PairGeometry::from(Vec3(0.0, 1.99, 0.0), 1.0, 1.0);
  PairHistory h{Vec3(1.0, 0.0, 0.0), Vec3::Zero(), true};
  const PairForce f =
      std::visit([&](const auto& l) { return l(g, RelativeMotion{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(),
                                                                  Vec3::Zero()}, 1e-3, h); }, law);
  EXPECT_NEAR(f[Contribution::contact_normal].y(), 100.0, 1e-9);
  EXPECT_FALSE(h.in_contact);
  EXPECT_EQ(interaction_range(law), 0.0);
}

TEST(ContactLaw, EveryAlternativeValidatesAndReportsItsRange) {
  std::vector<ContactLaw> laws = {ComposedLaw<ContactModel<SoftRepulsion>>{},
                                  ComposedLaw<LinearSpringCoulomb>{},
                                  ComposedLaw<LinearSpringCoulombRolling>{},
                                  ComposedLaw<LinearSpringCriticalLoad>{},
                                  ComposedLaw<LinearSpringCriticalLoadRolling>{},
                                  ComposedLaw<HertzAdhesiveCoulomb>{}};
  for (const auto& l : laws) EXPECT_NO_THROW(validate(l));
  EXPECT_DOUBLE_EQ(interaction_range(laws.back()), 5e-3);  // h_r
}

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
  composed.contact.normal.p = {1.0e4, 2.0e3, 0.0};
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

TEST(ContactLaw, EvaluatePairsVisitsOnceAndMatchesTheDirectCall) {
  HertzAdhesiveParams p;
  p.roughness = 0.01;
  p.kn = 1.0e5;
  p.f_adh = 1.0;
  const HertzAdhesiveCoulomb direct{HertzAdhesive(p), {{0.5}}};
  const ContactLaw law = ComposedLaw<HertzAdhesiveCoulomb>{direct, {}};
  const std::vector<PairGeometry> geometry = {PairGeometry::from(Vec3(2.005, 0.0, 0.0), 1.0, 1.0),
                                              PairGeometry::from(Vec3(0.0, 2.5, 0.0), 1.0, 1.0),
                                              PairGeometry::from(Vec3(0.0, 0.0, 2.397), 1.0, 1.4)};
  const RelativeMotion m{Vec3::Zero(), Vec3(0.1, 0.2, 0.3), Vec3::Zero(), Vec3::Zero()};
  std::vector<PairHistory> history(3), history_direct(3);
  std::vector<PairForce> out(3);
  evaluate_pairs(
      law, 0, 3, 1e-3, [&](std::size_t k) { return PairState{geometry[k], m}; },
      [&](std::size_t k) -> PairHistory& { return history[k]; },
      [&](std::size_t k, const PairForce& f) { out[k] = f; });
  for (std::size_t k = 0; k < 3; ++k) {
    const PairForce f = direct(geometry[k], m, 1e-3, history_direct[k]);
    EXPECT_EQ(f.total_on_j(), out[k].total_on_j());
    EXPECT_EQ(history[k].in_contact, history_direct[k].in_contact);
  }
  EXPECT_TRUE(history[0].in_contact);
  EXPECT_FALSE(history[1].in_contact);
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

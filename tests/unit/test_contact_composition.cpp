// Contact sub-models compose (issue 16): any normal law with any friction law and rolling resistance, each reading
// and writing its own keys. Checked here on the pairs the papers never combined: paper 004's Hertz-adhesive contact
// with paper 002's critical-load friction (friction only once the elastic load F_n + F_adh exceeds F_CL) and with
// paper 000's rolling resistance (torque capped at mu_r (F_n + F_adh)), and soft repulsion with Coulomb friction.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "contact_test_support.hpp"
#include "core/error.hpp"
#include "dem/contact/contact_law.hpp"
#include "dem/simulation.hpp"
#include "io/case.hpp"
#include "io/contact_case.hpp"
#include "io/schema_reader.hpp"
#include "tests/simulation_state.hpp"

using namespace suspend;
using namespace suspend::io;

namespace {
// Without the short-range repulsion, so that the load is the Hertz force alone.
HertzAdhesiveParams simple() {
  HertzAdhesiveParams p = test::round_hertz_adhesive();
  p.repulsion_stiffness = 0.0;
  return p;
}
// Equal unit spheres on x at surface gap h; j slides along y at speed v relative to i.
PairGeometry at_gap(double h) { return PairGeometry::from(Vec3(2.0 + h, 0.0, 0.0), 1.0, 1.0); }
RelativeMotion sliding(double v) { return {Vec3::Zero(), Vec3(0.0, v, 0.0), Vec3::Zero(), Vec3::Zero()}; }
// Slides long enough for the tangential spring to reach its cap; returns the last step's force.
template <class Law>
PairForce slide(const Law& law, double h, PairHistory& hist) {
  PairForce f;
  for (int s = 0; s < 2000; ++s) f = law(at_gap(h), sliding(1.0), 1e-3, hist);
  return f;
}

const char* base = R"(
particles: {phi: 0.3, count: 50, bidisperse: {size_ratio: 1.4, large_volume_share: 0.5}}
contact: {law: hertz_adhesive}
run: {strain: 1}
)";
Case with_contact(const std::string& contact) {
  YAML::Node root = YAML::Load(base);
  apply_override(root, "contact=" + contact);
  return parse_case(root, "");
}
// The message a contact block is refused with ("" when it is accepted).
std::string error_of(const std::string& contact) {
  try {
    with_contact(contact);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(ContactComposition, HertzWithCriticalLoadIsFrictionlessBelowTheThresholdOnTheElasticLoad) {
  const HertzAdhesive hertz(simple());
  const double h = 0.002, delta = 0.01 - h;
  const double elastic = 1.0e5 * std::pow(delta, 1.5);  // F_n + F_adh = 71.55 (paper 004 eq. 14)
  const ContactModel<HertzAdhesive, CriticalLoadFriction> below{hertz, {{0.5, elastic + 0.01}}, {}, test::round_adhesion()};
  const ContactModel<HertzAdhesive, CriticalLoadFriction> above{hertz, {{0.5, 0.2}}, {}, test::round_adhesion()};
  PairHistory h1, h2;
  const PairForce f_below = slide(below, h, h1);
  const PairForce f_above = slide(above, h, h2);
  EXPECT_EQ(f_below[Contribution::contact_tangential].norm(), 0.0);
  EXPECT_FALSE(f_below.sliding);
  // Sliding at the cap mu (L - F_CL), L the elastic force, whatever the adhesion (the net F_n is elastic - F_adh).
  EXPECT_TRUE(f_above.sliding);
  EXPECT_NEAR(f_above[Contribution::contact_tangential].norm(), 0.5 * (elastic - 0.2), 1e-13 * elastic);
  EXPECT_LT(f_above[Contribution::contact_tangential].y(), 0.0);  // opposes the slip of j
  // The normal part is the Hertz law's, unchanged by the friction composed with it.
  EXPECT_NEAR(f_above[Contribution::contact_normal].x(), elastic, 1e-13 * elastic);
  EXPECT_NEAR(f_above[Contribution::adhesion].x(), -2.0, 1e-15);
}

TEST(ContactComposition, HertzWithRollingResistanceSaturatesAtMuRTimesTheElasticLoad) {
  const HertzAdhesive hertz(simple());
  const double kr = hertz.secant_stiffness() / 100.0, mu_r = 0.1, w = 0.5, dt = 1e-4;
  const ContactModel<HertzAdhesive, CoulombFriction, RollingResistance> law{hertz, {{0.5}}, {{kr, mu_r}}};
  const double h = 0.002, elastic = 1.0e5 * std::pow(0.01 - h, 1.5);
  // Counter-rotating spheres roll without slip (paper 000 Appendix B): only the rolling spring is loaded.
  const RelativeMotion m{Vec3::Zero(), Vec3::Zero(), Vec3(0.0, 0.0, w), Vec3(0.0, 0.0, -w)};
  PairHistory hist;
  PairForce f = law(at_gap(h), m, dt, hist);
  // One step: T_i = a_ij n x k_r xi_r with xi_r = u_r dt = a_ij n x (omega_i - omega_j) dt = -2 w dt y.
  EXPECT_NEAR(f.torque_i.z(), -2.0 * kr * w * dt, 1e-12);
  for (int s = 0; s < 20000; ++s) f = law(at_gap(h), m, dt, hist);
  EXPECT_NEAR(std::abs(f.torque_i.z()), mu_r * elastic, 1e-13 * elastic);  // a_ij = 1
  EXPECT_NEAR(f.torque_j.z(), -f.torque_i.z(), 1e-15);
  EXPECT_LT(f[Contribution::contact_tangential].norm(), 1e-12);
}

TEST(ContactComposition, SoftRepulsionTakesCoulombFriction) {
  ContactModel<SoftRepulsion, CoulombFriction> law{SoftRepulsion{{1.0e3}}, {{0.4}}};
  law.kt = 200.0;
  PairHistory hist;
  const PairForce f = slide(law, -0.01, hist);  // overlap 0.01: F_n = 10
  EXPECT_NEAR(f[Contribution::contact_normal].x(), 10.0, 1e-12);
  EXPECT_NEAR(f[Contribution::contact_tangential].norm(), 4.0, 1e-12);
  EXPECT_TRUE(hist.in_contact);
}

TEST(ContactComposition, CaseReadsHertzWithCriticalLoadAndRolling) {
  const Case c = with_contact(
      "{law: hertz_adhesive, gamma_bar: 0.5, g_adh: 1.8, friction: critical_load, critical_load: 4, mu_s: 0.3,"
      " rolling: {mu_r: 0.05}}");
  const auto& law =
      std::get<ComposedLaw<ContactModel<HertzAdhesive, CriticalLoadFriction, RollingResistance>>>(c.simulation.contact);
  const HertzAdhesiveParams& p = law.contact.normal.params();
  EXPECT_DOUBLE_EQ(law.contact.friction.p.critical_load, 4.0);
  EXPECT_DOUBLE_EQ(law.contact.friction.p.mu, 0.3);
  // Default rolling stiffness: the Hertz secant stiffness at the typical compression over 100.
  EXPECT_DOUBLE_EQ(law.contact.rolling.p.kr, p.kn * std::sqrt(p.eps_bar * p.roughness) / 100.0);
  EXPECT_DOUBLE_EQ(law.contact.rolling.p.mu_r, 0.05);
  EXPECT_DOUBLE_EQ(adhesion_force(c.simulation.contact), 6.0 * M_PI * 1.8);
  // The resolved case reads back to the same case.
  EXPECT_EQ(to_yaml_text(parse_case(YAML::Load(to_yaml_text(c)), "")), to_yaml_text(c));
}

TEST(ContactComposition, CoulombWithZeroCoefficientIsNoFriction) {
  const Case c = with_contact("{law: hertz_adhesive, mu_s: 0}");
  EXPECT_TRUE(std::holds_alternative<ComposedLaw<ContactModel<HertzAdhesive>>>(c.simulation.contact));
  const Case d = with_contact("{law: hertz_adhesive}");  // paper 004's mu_s = 0.5 by default
  EXPECT_DOUBLE_EQ(std::get<ComposedLaw<HertzAdhesiveCoulomb>>(d.simulation.contact).contact.friction.p.mu, 0.5);
}

TEST(ContactComposition, EveryNormalFrictionAndRollingCombinationIsReachableFromACase) {
  std::set<std::size_t> alternatives;
  for (const char* normal : {"soft_repulsion", "linear_spring", "hertz_adhesive", "jkr"})
    for (const char* friction : {"none", "coulomb", "critical_load"})
      for (const bool rolling : {false, true}) {
        const std::string contact = std::string("{law: ") + normal + ", friction: " + friction +
                                    (rolling ? ", rolling: {mu_r: 0.1}" : "") + "}";
        const Case c = with_contact(contact);
        alternatives.insert(c.simulation.contact.index());
        EXPECT_EQ(contact_law_name(c.simulation.contact), normal);
        EXPECT_EQ(to_yaml_text(parse_case(YAML::Load(to_yaml_text(c)), "")), to_yaml_text(c)) << contact;
      }
  EXPECT_EQ(alternatives.size(), std::variant_size_v<ContactLaw>);
}

TEST(ContactComposition, FrictionNoneRefusesACoefficient) {
  YAML::Node root = YAML::Load(base);
  apply_override(root, "contact={law: linear_spring, friction: none, mu: 0.3}");
  try {
    parse_case(root, "");
    FAIL() << "accepted mu with friction: none";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contact.mu"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("friction: none"), std::string::npos) << e.what();
  }
}

// Messages name the key the case writes (issue 37, item 8): mu_s for the Hertz-adhesive law's friction, k_hat for
// the springs, not the coefficients' internal names (2fbb67f said contact.mu and contact.kn).
TEST(ContactComposition, ValidationNamesTheKeysOfTheCase) {
  auto message = [](const auto& law) {
    try {
      law.validate();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const HertzAdhesive hertz(simple());
  EXPECT_EQ(message(ContactModel<HertzAdhesive, CoulombFriction>{hertz, {{-0.5}}}).rfind("contact.mu =", 0), 0u);
  EXPECT_EQ(message(ContactModel<HertzAdhesive, CriticalLoadFriction>{hertz, {{-0.5, 0.1}}}).rfind("contact.mu =", 0),
            0u);
  EXPECT_EQ(message(ContactModel<SoftRepulsion, CoulombFriction>{SoftRepulsion{{1.0e3}}, {{-0.4}}})
                .rfind("contact.mu =", 0),
            0u);
  EXPECT_EQ(message(ContactModel<SoftRepulsion>{SoftRepulsion{{-1.0}}}).rfind("contact.k_hat", 0), 0u);
  LinearSpringDashpot spring;
  spring.p.kn = 0.0;
  EXPECT_EQ(message(ContactModel<LinearSpringDashpot>{spring}).rfind("contact.k_hat", 0), 0u);
}

// Parameters per species pair: the pair of species 0 and 1 here slides without friction while like pairs keep
// mu_s = 0.5 (a case such as smooth large spheres among rough small ones).
TEST(ContactSpeciesPairs, ThePairsSpeciesChooseTheParameters) {
  ComposedLaw<HertzAdhesiveCoulomb> law{{HertzAdhesive(simple()), {{0.5}}}, {}, {}};
  law.set_pair(0, 1, {HertzAdhesive(simple()), {{0.0}}}, 2);
  PairHistory h00, h01, h10;
  PairForce f00, f01, f10;
  for (int s = 0; s < 2000; ++s) {
    f00 = law(0, 0, at_gap(0.002), sliding(1.0), 1e-3, h00);
    f01 = law(0, 1, at_gap(0.002), sliding(1.0), 1e-3, h01);
    f10 = law(1, 0, at_gap(0.002), sliding(1.0), 1e-3, h10);
  }
  EXPECT_GT(f00[Contribution::contact_tangential].norm(), 30.0);
  EXPECT_EQ(f01[Contribution::contact_tangential].norm(), 0.0);
  EXPECT_EQ(f10[Contribution::contact_tangential].norm(), 0.0);
  EXPECT_EQ(f01[Contribution::contact_normal], f00[Contribution::contact_normal]);
}

TEST(ContactSpeciesPairs, TheDriverUsesEachPairsOwnStiffness) {
  // Two overlapping spheres of species 0 and 1 separate at the Stokes velocity of their pair's spring,
  // k_01 delta / (6 pi) (drag only), not at the like pairs' k delta / (6 pi).
  const double overlap = 0.01, k = 1.0e3, k01 = 4.0e3;
  auto st = test_support::state_of({{10, 10, 10}, {10, 10, 12 - overlap}}, {1.0, 1.0});
  st.particles.species = {0, 1};
  SimulationParams params;
  params.flow.shear_rate = 0.0;
  ComposedLaw<ContactModel<SoftRepulsion>> law{{SoftRepulsion{{k}}}, {}, {}};
  law.set_pair(0, 1, {SoftRepulsion{{k01}}}, 2);
  params.contact = law;
  Simulation sim(st, Box(20, 20, 20), params);
  sim.evaluate();
  EXPECT_NEAR(sim.state().particles.velocity[1].z(), k01 * overlap / (6.0 * M_PI), 1e-12);
  EXPECT_NEAR(stiffness_scale(params.contact), k01, 0.0);  // the explicit step resolves the stiffest pair
}

TEST(ContactSpeciesPairs, CaseReadsAndWritesSpeciesPairs) {
  const Case c = with_contact("{law: hertz_adhesive, g_adh: 0.9, species_pairs: [{species: [0, 1], mu_s: 0.1, "
                              "g_adh: 0.3}]}");
  const auto& law = std::get<ComposedLaw<HertzAdhesiveCoulomb>>(c.simulation.contact);
  ASSERT_FALSE(law.pairs.empty());
  EXPECT_DOUBLE_EQ(law.contact_of(0, 0).friction.p.mu, 0.5);
  EXPECT_DOUBLE_EQ(law.contact_of(1, 1).friction.p.mu, 0.5);
  EXPECT_DOUBLE_EQ(law.contact_of(0, 1).friction.p.mu, 0.1);
  EXPECT_DOUBLE_EQ(law.contact_of(1, 0).adhesion_force(), 6.0 * M_PI * 0.3);
  EXPECT_DOUBLE_EQ(law.contact_of(1, 0).normal.params().eps_bar, 0.05);  // the case's other keys
  EXPECT_DOUBLE_EQ(adhesion_force(c.simulation.contact), 6.0 * M_PI * 0.9);  // sigma* keeps the law's F_adh
  EXPECT_EQ(to_yaml_text(parse_case(YAML::Load(to_yaml_text(c)), "")), to_yaml_text(c));
}

TEST(ContactSpeciesPairs, RefusesWhatASpeciesPairCannotChange) {
  std::string e = error_of("{law: hertz_adhesive, species_pairs: [{species: [0, 2], mu_s: 0.1}]}");
  EXPECT_NE(e.find("contact.species_pairs[0].species"), std::string::npos) << e;
  e = error_of("{law: hertz_adhesive, species_pairs: [{species: [0, 1], law: linear_spring}]}");
  EXPECT_NE(e.find("contact.species_pairs[0].law"), std::string::npos) << e;
  e = error_of("{law: hertz_adhesive, species_pairs: [{species: [0, 1], friction: critical_load}]}");
  EXPECT_NE(e.find("not which friction law"), std::string::npos) << e;
  e = error_of("{law: hertz_adhesive, species_pairs: [{species: [0, 1], mu_z: 0.1}]}");
  EXPECT_NE(e.find("contact.species_pairs[0].mu_z: unknown key"), std::string::npos) << e;
  // [1, 0] is [0, 1]: a second entry for it would silently replace the first.
  e = error_of("{law: hertz_adhesive, species_pairs: [{species: [0, 1], mu_s: 0.1}, {species: [1, 0], mu_s: 0.2}]}");
  EXPECT_NE(e.find("contact.species_pairs[1].species"), std::string::npos) << e;
  EXPECT_NE(e.find("given twice"), std::string::npos) << e;
}

// Damping, adhesion, the tangential stiffness and twisting are separate choices with their own keys, for every law
// (issue 38), and a resolved case reads back to itself.
TEST(ContactSubModels, EachChoiceReadsAndWritesItsOwnKeys) {
  const Case c = with_contact("{law: linear_spring, k_hat: 4.0e5, damping: viscoelastic, dissipation_time: 1.0e-3, "
                              "adhesion: dmt, work_of_adhesion: 0.5, friction: coulomb, mu: 0.4, kt: 3.0e4, "
                              "twisting: {mu_twist: 0.2}}");
  const auto& law = std::get<ComposedLaw<LinearSpringCoulomb>>(c.simulation.contact).contact;
  EXPECT_EQ(law.damping.model, NormalDamping::Model::viscoelastic);
  EXPECT_DOUBLE_EQ(law.damping.coefficient, 1.0e-3);
  EXPECT_EQ(law.adhesion.model, Adhesion::Model::dmt);
  EXPECT_DOUBLE_EQ(adhesion_force(c.simulation.contact), M_PI * 0.5);  // 2 pi W R*, R* = 1/2
  EXPECT_DOUBLE_EQ(law.tangential_stiffness(), 3.0e4);
  EXPECT_TRUE(law.twisting.active);
  EXPECT_DOUBLE_EQ(law.twisting.stiffness, 4.0e3);  // the secant stiffness / 100, as the rolling spring
  EXPECT_DOUBLE_EQ(law.twisting.mu, 0.2);
  EXPECT_EQ(to_yaml_text(parse_case(YAML::Load(to_yaml_text(c)), "")), to_yaml_text(c));

  // Hertz: paper 004's constant adhesion by default, switched off by its own key; mu and mu_s are one coefficient;
  // k_t is eq. 18's unless given.
  const Case no_adhesion = with_contact("{law: hertz_adhesive, adhesion: none, mu: 0.3}");
  const auto& hertz = std::get<ComposedLaw<HertzAdhesiveCoulomb>>(no_adhesion.simulation.contact);
  EXPECT_FALSE(hertz.contact.adhesion.active());
  EXPECT_DOUBLE_EQ(hertz.contact.friction.p.mu, 0.3);
  const HertzAdhesiveParams& p = hertz.contact.normal.params();
  EXPECT_DOUBLE_EQ(hertz.contact.tangential_stiffness(), 2.0 / 7.0 * p.kn * std::sqrt(p.eps_bar * p.roughness));
  const Case paper = with_contact("{law: hertz_adhesive}");
  EXPECT_DOUBLE_EQ(adhesion_force(paper.simulation.contact), 6.0 * M_PI * 0.9);

  // The linear spring's former gamma_n key is the viscous model; 0 is no damping.
  const Case dashpot = with_contact("{law: linear_spring, gamma_n: 0.04}");
  const auto& damped = std::get<ComposedLaw<LinearSpringCoulomb>>(dashpot.simulation.contact);
  EXPECT_EQ(damped.contact.damping.model, NormalDamping::Model::viscous);
  EXPECT_DOUBLE_EQ(damped.contact.damping.coefficient, 0.04);
  const Case undamped = with_contact("{law: linear_spring, gamma_n: 0}");
  EXPECT_FALSE(std::get<ComposedLaw<LinearSpringCoulomb>>(undamped.simulation.contact).contact.damping.active());
}

TEST(ContactSubModels, RefusesChoicesThatDoNotCompose) {
  std::string e = error_of("{law: jkr, adhesion: constant}");
  EXPECT_NE(e.find("contact.adhesion: law: jkr carries its own adhesion"), std::string::npos) << e;
  e = error_of("{law: linear_spring, damping: viscoelastic, gamma_n: 1}");
  EXPECT_NE(e.find("contact.gamma_n"), std::string::npos) << e;
  e = error_of("{law: hertz_adhesive, adhesion: dmt, g_adh: 1}");
  EXPECT_NE(e.find("contact.g_adh"), std::string::npos) << e;
  e = error_of("{law: linear_spring, adhesion: dmt}");
  EXPECT_NE(e.find("contact.work_of_adhesion"), std::string::npos) << e;
  e = error_of("{law: linear_spring, twisting: {k_twist: -1}}");
  EXPECT_NE(e.find("contact.twisting.k_twist"), std::string::npos) << e;
}

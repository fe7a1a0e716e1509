// Case validation: every kind of bad input gives one clear InputError naming the key, the value and what is allowed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "io/case.hpp"
#include "io/initial_configuration.hpp"
#include "io/schema_reader.hpp"
#include "tests/scratch_dir.hpp"

using namespace suspend;
using namespace suspend::io;

namespace {
const char* base = R"(
particles:
  phi: 0.4
  count: 100
  bidisperse: {size_ratio: 1.4, large_volume_share: 0.5}
contact: {law: soft_repulsion, k_hat: 1000}
run: {strain: 2}
)";

std::string error_of(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  YAML::Node root = YAML::Load(yaml);
  try {
    for (const auto& o : overrides) apply_override(root, o);
    parse_case(root, "");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The error the initial configuration of `base` with these overrides stops at ("" when it builds).
std::string configuration_error_of(const std::vector<std::string>& overrides) {
  YAML::Node root = YAML::Load(base);
  for (const auto& o : overrides) apply_override(root, o);
  try {
    build_initial_configuration(parse_case(root, ""));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Case, ValidCaseFillsDefaults) {
  const Case c = parse_case(YAML::Load(base), "");
  EXPECT_DOUBLE_EQ(c.particles.phi, 0.4);
  ASSERT_EQ(c.particles.species.size(), 2u);
  EXPECT_DOUBLE_EQ(c.particles.species[1].radius, 1.4);
  EXPECT_DOUBLE_EQ(c.simulation.flow.shear_rate, 1.0);
  EXPECT_EQ(c.hydrodynamics, "pairwise");
  EXPECT_DOUBLE_EQ(c.run.average_from, 0.4);  // default: the first 20% of the strain is transient
}

TEST(Case, UnknownKeySuggestsTheClosestAllowedKey) {
  const std::string e = error_of(base, {"particles.phii=0.5"});
  EXPECT_NE(e.find("particles.phii: unknown key"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'phi'"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << "one line";
}

TEST(Case, UnknownSectionIsReported) {
  const std::string e = error_of(std::string(base) + "flw: {shear_rate: 2}\n");
  EXPECT_NE(e.find("flw: unknown key; did you mean 'flow'"), std::string::npos) << e;
}

TEST(Case, WrongTypeNamesKeyValueAndExpectation) {
  const std::string e = error_of(base, {"particles.phi=abc"});
  EXPECT_NE(e.find("particles.phi: 'abc' is not a number"), std::string::npos) << e;
  const std::string m = error_of(base, {"run.output=3"});
  EXPECT_NE(m.find("run.output: expected a mapping"), std::string::npos) << m;
}

TEST(Case, OutOfRangeNamesTheAllowedInterval) {
  const std::string e = error_of(base, {"particles.phi=0.9"});
  EXPECT_NE(e.find("particles.phi: 0.9 is out of range: must be in (0, 0.74)"), std::string::npos) << e;
  EXPECT_NE(error_of(base, {"contact.k_hat=-1"}).find("contact.k_hat"), std::string::npos);
  EXPECT_NE(error_of(base, {"run.average_from=5"}).find("must be below run.strain"), std::string::npos);
}

TEST(Case, ChoiceListsAllowedWords) {
  const std::string e = error_of(base, {"contact.law=soft_repulsio"});
  EXPECT_NE(e.find("contact.law: 'soft_repulsio' is not allowed (one of: soft_repulsion, linear_spring, hertz_adhesive, jkr)"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("did you mean 'soft_repulsion'"), std::string::npos) << e;
}

TEST(Case, VolumeSharesMustSumToOneAndSmallestRadiusIsTheUnit) {
  const std::string shares = R"(
particles:
  phi: 0.4
  count: 100
  species: [{radius: 1, volume_share: 0.5}, {radius: 2, volume_share: 0.4}]
)";
  EXPECT_NE(error_of(shares).find("particles.species: volume shares sum to 0.9"), std::string::npos);
  const std::string unit = R"(
particles:
  phi: 0.4
  count: 100
  species: [{radius: 2, volume_share: 1}]
)";
  EXPECT_NE(error_of(unit).find("smallest radius is the length unit"), std::string::npos);
}

TEST(Case, CountAndBoxAreExclusive) {
  EXPECT_NE(error_of(base, {"box.cube=20"}).find("particles.count and box are both given"), std::string::npos);
  EXPECT_NE(error_of("particles: {phi: 0.3}\n").find("particles.count: missing"), std::string::npos);
}

TEST(Case, MissingInitialFileIsReported) {
  const std::string e = error_of(base, {"particles.initial={from: file, file: /nonexistent/config.txt}"});
  EXPECT_NE(e.find("particles.initial.file: '/nonexistent/config.txt' does not exist"), std::string::npos) << e;
}

TEST(Case, MalformedOverride) {
  EXPECT_NE(error_of(base, {"particles.phi"}).find("expected KEY=VALUE"), std::string::npos);
  EXPECT_NE(error_of(base, {"particles.phi.=0.45"}).find("ends with a dot"), std::string::npos);
  EXPECT_NE(error_of(base, {".particles.phi=0.45"}).find("starts or ends with a dot"), std::string::npos);
  EXPECT_NE(error_of(base, {"particles.phi=!!str 0.45"}).find("particles.phi: YAML tags"), std::string::npos);
  EXPECT_NE(error_of(base, {"particles.phi.x=1"}).find("holds a value"), std::string::npos);
}

TEST(Case, OverrideCreatesNestedKeys) {
  YAML::Node root = YAML::Load(base);
  apply_override(root, "run.output.series_every=0.5");
  apply_override(root, "flow.shear_rate=2");
  const Case c = parse_case(root, "");
  EXPECT_DOUBLE_EQ(c.run.output.series_every, 0.5);
  EXPECT_DOUBLE_EQ(c.simulation.flow.shear_rate, 2.0);
}

TEST(Case, ResolvedYamlReadsBackToTheSameCase) {
  const Case c = parse_case(YAML::Load(base), "");
  const Case d = parse_case(YAML::Load(to_yaml_text(c)), "");
  EXPECT_EQ(to_yaml_text(c), to_yaml_text(d));
}

// The groups come back as given: recomputed from k_n they would read 0.9000000000000001, and each read-write of the
// resolved case would move them again (a restart or a sweep would then see another case).
TEST(Case, AdhesiveGroupsReadBackAsGiven) {
  YAML::Node root = YAML::Load(base);
  apply_override(root, "contact={law: hertz_adhesive, gamma_bar: 0.9, g_adh: 1.0}");
  const std::string once = to_yaml_text(parse_case(root, ""));
  EXPECT_NE(once.find("gamma_bar: 0.9\n"), std::string::npos) << once;
  EXPECT_EQ(to_yaml_text(parse_case(YAML::Load(once), "")), once);
}

// A case recorded by an older version (a checkpoint, a sweep point) is the same case when this version resolves it
// to the same one: a key gained since with the value the old form implied, or a last-digit change of a recomputed
// group, is no change; a changed parameter is named.
TEST(Case, RecordedCaseChangesIgnoreImpliedKeysAndLastDigits) {
  YAML::Node root = YAML::Load(base);
  apply_override(root, "contact={law: hertz_adhesive, gamma_bar: 0.9, g_adh: 1.0, mu_s: 0.5}");
  const std::string now = result_identity(parse_case(root, ""));
  // As the version before the contact sub-models wrote it: no friction key, mu_s, no kt and no adhesion key.
  std::string old_form = now;
  YAML::Node old_node = YAML::Load(now);
  for (const char* key : {"friction", "kt", "adhesion", "mu"}) old_node["contact"].remove(key);
  old_node["contact"]["mu_s"] = 0.5;
  YAML::Emitter e;
  e << old_node;
  old_form = e.c_str();
  old_form.replace(old_form.find("gamma_bar: 0.9\n"), 15, "gamma_bar: 0.9000000000000001\n");
  EXPECT_EQ(case_changes(old_form, now, result_identity), "");
  EXPECT_EQ(case_changes(now, now, physics_fingerprint), "");
  std::string other = old_form;
  other.replace(other.find("mu_s: 0.5"), 9, "mu_s: 0.4");
  EXPECT_EQ(case_changes(other, now, result_identity), "contact.mu 0.4 -> 0.5");
  EXPECT_EQ(case_changes("not: [a case", now, result_identity), "the recorded case is unreadable");
}

// Two values of run.time_step.fastest_of that give the motion bounds the same rank k = N / fastest_of (at least 1)
// are the same case: a record from before the quantile rule (no key, meaning 0: the fastest of all) matches today's
// default 500 below 1000 particles, not above. The linear solvers' iteration caps are no part of a case's identity
// (they decide when a run gives up, not what it computes).
TEST(Case, RecordedStepRankAndSolverCapsAreNoChangeWhereTheyGiveTheSameRun) {
  for (const long count : {100L, 999L, 1000L}) {
    YAML::Node root = YAML::Load(base);
    apply_override(root, "particles.count=" + std::to_string(count));
    const std::string now = result_identity(parse_case(root, ""));
    YAML::Node old_form = YAML::Load(now);
    old_form["run"]["time_step"].remove("fastest_of");
    old_form["hydrodynamics"]["solver"]["max_iterations"] = 200;
    YAML::Emitter e;
    e << old_form;
    const std::string changes = case_changes(e.c_str(), now, result_identity);
    if (count < 1000)
      EXPECT_EQ(changes, "") << count;
    else
      EXPECT_EQ(changes, "run.time_step.fastest_of 0 -> 500") << count;
  }
  EXPECT_EQ(result_identity(parse_case(YAML::Load(base), "")).find("max_iterations"), std::string::npos);
}

// FCM records written before the fast setting became the default (2026-12-05) lack far_field_every (older still)
// or predictor (written only when lagged_far_field): they meant every step and the extrapolated start, so a
// campaign point or checkpoint of such a run still matches a case that sets those values, and differs from one
// that takes today's defaults, naming both keys.
TEST(Case, RecordedFcmCasesMeanTheirFormerDefaults) {
  YAML::Node root = YAML::Load(std::string(base) + "hydrodynamics: {model: fcm, fcm: {far_field_every: 1, "
                                                   "predictor: extrapolated}}\n");
  const std::string every_step = result_identity(parse_case(root, ""));
  YAML::Node old_form = YAML::Load(every_step);
  old_form["hydrodynamics"]["fcm"].remove("predictor");
  YAML::Emitter with_key;
  with_key << old_form;
  EXPECT_EQ(case_changes(with_key.c_str(), every_step, result_identity), "");
  old_form["hydrodynamics"]["fcm"].remove("far_field_every");
  YAML::Emitter older;
  older << old_form;
  EXPECT_EQ(case_changes(older.c_str(), every_step, result_identity), "");
  const std::string fast = result_identity(parse_case(YAML::Load(std::string(base) + "hydrodynamics: {model: fcm}\n"), ""));
  const std::string changes = case_changes(older.c_str(), fast, result_identity);
  EXPECT_NE(changes.find("hydrodynamics.fcm.far_field_every 1 -> 10"), std::string::npos) << changes;
  EXPECT_NE(changes.find("hydrodynamics.fcm.predictor extrapolated -> lagged_far_field"), std::string::npos) << changes;
}

TEST(Case, UnreachableVolumeFractionForTheBox) {
  // 0.72 is below the schema bound but far above random close packing: the generator must refuse it.
  const std::string e = configuration_error_of({"particles.phi=0.72", "particles.count=40"});
  EXPECT_NE(e.find("unreachable"), std::string::npos) << "phi = 0.72 must be unreachable: " << e;
}

TEST(Case, ParticleTableFileErrorsNameTheLine) {
  const std::string path = suspend::testing_support::scratch_dir() + "/bad_table.txt";
  std::ofstream(path) << "# x y z a\n1 2 3 1\n4 5 six 1\n";
  try {
    read_particle_table(path);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_table.txt:3"), std::string::npos) << e.what();
  }
  // A row that is not four finite numbers is an error naming its line, never a skipped line.
  for (const std::string row : {"nan 1 1 1", "1 inf 1 1", "1e999 1 1 1", "x y z a", "1 2 3", "1 2 3 1 5", "1 2 3 -1",
                                "1 2 3 1abc"}) {
    std::ofstream(path) << "1 2 3 1\n\n# comment\n" << row << "  # row 4\n";
    try {
      read_particle_table(path);
      ADD_FAILURE() << "'" << row << "' was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bad_table.txt:4"), std::string::npos) << row << ": " << e.what();
    }
  }
}

TEST(Case, ParticleCountThatDisagreesWithTheFileIsRefused) {
  const std::string path = suspend::testing_support::scratch_dir() + "/two.txt";
  std::ofstream(path) << "2 2 2 1\n6 6 6 1\n";
  const std::string e = configuration_error_of({"particles.initial={from: file, file: " + path + "}", "particles.count=3"});
  EXPECT_NE(e.find("particles.count: 3 disagrees with the 2 particles"), std::string::npos)
      << "a count of 3 for a file of 2 particles: " << e;
}

TEST(CaseContact, PaperGroupsBecomeHertzAdhesiveParameters) {
  YAML::Node root = YAML::Load(base);
  apply_override(root, "contact={law: hertz_adhesive, gamma_bar: 0.5, g_adh: 1.8, mu_s: 0.3}");
  const Case c = parse_case(root, "");
  const auto& law = std::get<ComposedLaw<HertzAdhesiveCoulomb>>(c.simulation.contact);
  const HertzAdhesiveParams& p = law.contact.normal.params();
  // Paper 004 eq. 17: Gamma-bar = 6 pi eta a^2 gammadot / (k_n (eps_bar h_r)^(3/2)); G_adh = F_adh / (6 pi eta a^2 gammadot).
  EXPECT_NEAR(p.kn, 6.0 * M_PI / (0.5 * std::pow(0.05 * 0.005, 1.5)), 1e-6 * p.kn);
  EXPECT_NEAR(law.contact.adhesion.force(PairGeometry::from(Vec3(2, 0, 0), 1, 1)), 6.0 * M_PI * 1.8, 1e-12);
  EXPECT_DOUBLE_EQ(law.contact.friction.p.mu, 0.3);
  EXPECT_DOUBLE_EQ(p.roughness, 5e-3);
  // The resolved case prints the groups back.
  const YAML::Node y = to_yaml(c);
  EXPECT_NEAR(y["contact"]["gamma_bar"].as<double>(), 0.5, 1e-12);
  EXPECT_NEAR(y["contact"]["g_adh"].as<double>(), 1.8, 1e-12);
}

TEST(CaseContact, LinearSpringVariantsAndSurfaceForces) {
  YAML::Node root = YAML::Load(base);
  apply_override(root, "contact={law: linear_spring, k_hat: 2.0e4, friction: critical_load, mu: 0.8, critical_load: 3,"
                       " rolling: {mu_r: 0.05}, repulsion: {force: 1, debye_length: 0.02},"
                       " attraction: {hamaker: 6.3e-5}}");
  const Case c = parse_case(root, "");
  const auto& law = std::get<ComposedLaw<LinearSpringCriticalLoadRolling>>(c.simulation.contact);
  EXPECT_DOUBLE_EQ(law.contact.normal.p.kn, 2.0e4);
  EXPECT_DOUBLE_EQ(law.contact.tangential_stiffness(), 2.0 / 7.0 * 2.0e4);  // paper 000 table 1 ratio by default
  EXPECT_DOUBLE_EQ(law.contact.friction.p.critical_load, 3.0);
  EXPECT_DOUBLE_EQ(law.contact.rolling.p.kr, 2.0e2);  // k_n / 100
  ASSERT_TRUE(law.surface.repulsion && law.surface.attraction);
  EXPECT_DOUBLE_EQ(law.surface.attraction->p.hamaker, 6.3e-5);
  EXPECT_NEAR(interaction_range(c.simulation.contact), 20 * 0.02 > 4.0 ? 0.4 : 4.0, 1e-12);
  // Round trip through the resolved YAML gives the same case.
  EXPECT_EQ(to_yaml_text(parse_case(YAML::Load(to_yaml_text(c)), "")), to_yaml_text(c));
}

TEST(CaseContact, KeysOfAnotherLawAreUnknown) {
  const std::string e = error_of(base, {"contact={law: linear_spring, roughness: 0.01}"});
  EXPECT_NE(e.find("contact.roughness: unknown key"), std::string::npos) << e;
  // mu_s is paper 004's name of mu, for every law; not both.
  EXPECT_NE(error_of(base, {"contact={law: linear_spring, mu: 0.5, mu_s: 0.5}"}).find("contact.mu_s: the same"),
            std::string::npos);
  EXPECT_NE(error_of(base, {"contact={law: linear_spring, friction: none, mu: 0.5}"}).find("contact.mu: must be 0"),
            std::string::npos);
}

TEST(Case, FlowControlWaveIntegratorAndModelKeys) {
  const Case s = parse_case(YAML::Load(std::string(base) + "flow: {control: stress, shear_stress: 5}\n"), "");
  EXPECT_EQ(s.simulation.flow.control, FlowControl::stress);
  EXPECT_DOUBLE_EQ(s.simulation.flow.shear_stress, 5.0);
  const Case w = parse_case(YAML::Load(std::string(base) + "flow: {type: wavy, amplitude: 20}\n"), "");
  EXPECT_DOUBLE_EQ(w.simulation.flow.wave_amplitude, 20.0);
  EXPECT_EQ(w.simulation.flow.wave_periods, 1);
  const Case f = parse_case(YAML::Load(std::string(base) + "hydrodynamics: {model: fcm, fcm: {grid_spacing: 0.4}}\n"), "");
  EXPECT_EQ(f.hydrodynamics, "fcm");
  EXPECT_DOUBLE_EQ(f.fcm.grid_spacing, 0.4);
  // The resolved case reads back to itself.
  EXPECT_EQ(to_yaml_text(parse_case(to_yaml(w), "")), to_yaml_text(w));
  EXPECT_NE(error_of(std::string(base) + "flow: {control: stress}\n").find("flow.shear_stress: missing"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(base) + "flow: {shear_stress: 2}\n").find("flow.shear_stress"), std::string::npos);
  EXPECT_NE(error_of(std::string(base) + "flow: {type: wavy}\n").find("flow.amplitude"), std::string::npos);
  EXPECT_NE(error_of(base, {"run.integrator=inertial", "run.stokes_number=-1"})
                .find("run.stokes_number"), std::string::npos);
  EXPECT_NE(error_of(base, {"run.stokes_number=0.1"}).find("run.stokes_number"),
            std::string::npos);
  const Case fs = parse_case(YAML::Load(std::string(base) + "hydrodynamics: {model: fcm}\n"
                                                            "flow: {control: stress, shear_stress: 1}\n"), "");
  EXPECT_EQ(fs.simulation.flow.control, FlowControl::stress);
  EXPECT_NE(error_of(std::string(base) + "hydrodynamics: {model: fcm}\nflow: {type: wavy, amplitude: 1}\n")
                .find("flow.type"), std::string::npos);
  YAML::Node implicit = YAML::Load(std::string(base) + "hydrodynamics: {lubrication: {enabled: true}}\n");
  apply_override(implicit, "run.time_step.contacts=implicit");
  const Case ic = parse_case(implicit, "");
  EXPECT_TRUE(ic.simulation.time_step.implicit_contacts);
  EXPECT_EQ(to_yaml_text(parse_case(to_yaml(ic), "")), to_yaml_text(ic));
  EXPECT_NE(error_of(std::string(base) + "hydrodynamics: {lubrication: {enabled: false}}\n",
                     {"run.time_step.contacts=implicit"})
                .find("run.time_step.contacts"), std::string::npos);
  EXPECT_NE(error_of(base, {"run.time_step.contacts=sometimes"}).find("run.time_step.contacts"), std::string::npos);
  EXPECT_NE(error_of(std::string(base) + "hydrodynamics: {model: fcm, fcm: {grid_spacng: 1}}\n")
                .find("hydrodynamics.fcm.grid_spacng"), std::string::npos);
}

TEST(Case, SigmaStarSetsTheImposedStressFromTheAdhesionForce) {
  // Paper 004 eq. 20: sigma* = 6 pi Sigma_12 a_1^2 / F_adh and F_adh = 6 pi G_adh (eta_0 gammadot_ref a_1^2 units),
  // so Sigma_12 = sigma* G_adh.
  YAML::Node root = YAML::Load(base);
  apply_override(root, "contact={law: hertz_adhesive, g_adh: 2.5, gamma_bar: 0.36}");
  apply_override(root, "flow={control: stress, sigma_star: 0.7}");
  const Case c = parse_case(root, "");
  EXPECT_NEAR(c.simulation.flow.shear_stress, 0.7 * 2.5, 1e-12);
  EXPECT_EQ(to_yaml_text(parse_case(to_yaml(c), "")), to_yaml_text(c));
  EXPECT_NE(error_of(base, {"flow={control: stress, sigma_star: 1}"}).find("flow.sigma_star: needs an adhesive"),
            std::string::npos);
  EXPECT_NE(error_of(base, {"flow={control: stress, sigma_star: 1, shear_stress: 1}"}).find("not both"),
            std::string::npos);
  EXPECT_NE(error_of(base, {"flow={sigma_star: 1}"}).find("flow.sigma_star: is a target of flow.control = stress"),
            std::string::npos);
}

TEST(Case, JammedThresholdsAreReadAndPrintedUnderImposedStress) {
  YAML::Node root = YAML::Load(std::string(base) + "flow: {control: stress, shear_stress: 5}\n");
  apply_override(root, "run.jammed={viscosity: 500, strain: 0.1}");
  const Case c = parse_case(root, "");
  EXPECT_DOUBLE_EQ(c.run.jammed_viscosity, 500.0);
  EXPECT_DOUBLE_EQ(c.run.jammed_strain, 0.1);
  EXPECT_DOUBLE_EQ(to_yaml(c)["run"]["jammed"]["viscosity"].as<double>(), 500.0);
  EXPECT_NE(error_of(base, {"run.jammed.viscosity=0"}).find("run.jammed.viscosity"), std::string::npos);
}

TEST(Case, KeysGivenTwiceAndTagsAreRefused) {
  // yaml-cpp keeps both entries of a repeated key and reads the first: the second would be silently ignored.
  EXPECT_NE(error_of(std::string(base) + "flow: {shear_rate: 2, shear_rate: 3}\n").find("flow.shear_rate: given twice"),
            std::string::npos);
  EXPECT_NE(error_of(std::string(base) + "run: {strain: 3}\n").find("run: given twice"), std::string::npos);
  EXPECT_NE(error_of(std::string(base) + "title: !!str suspension\n").find("title: YAML tags"), std::string::npos);
  EXPECT_EQ(error_of(std::string(base) + "title: \"quoted\"\n"), "");
}

TEST(Case, FcmMultiRateKeys) {
  const Case d = parse_case(YAML::Load(std::string(base) + "hydrodynamics: {model: fcm}\n"), "");
  EXPECT_EQ(d.fcm.far_field_every, 10);  // the fast setting (issue 14)
  EXPECT_TRUE(d.fcm.lagged_predictor);
  EXPECT_EQ(to_yaml(d)["hydrodynamics"]["fcm"]["predictor"].as<std::string>(), "lagged_far_field");
  const Case every = parse_case(YAML::Load(std::string(base) + "hydrodynamics: {model: fcm, fcm: {far_field_every: 1, "
                                                               "predictor: extrapolated}}\n"), "");
  EXPECT_EQ(every.fcm.far_field_every, 1);
  EXPECT_FALSE(every.fcm.lagged_predictor);
  EXPECT_EQ(to_yaml_text(parse_case(to_yaml(every), "")), to_yaml_text(every));
  EXPECT_DOUBLE_EQ(d.fcm.lagged_cutoff, 2.25);
  EXPECT_DOUBLE_EQ(d.fcm.lagged_tolerance, 1e-6);
  const Case f = parse_case(YAML::Load(std::string(base) + "hydrodynamics: {model: fcm, fcm: {far_field_every: 10, "
                                                           "lagged_cutoff: 3.5, lagged_tolerance: 1e-8}}\n"), "");
  EXPECT_EQ(f.fcm.far_field_every, 10);
  EXPECT_DOUBLE_EQ(f.fcm.lagged_cutoff, 3.5);
  EXPECT_DOUBLE_EQ(f.fcm.lagged_tolerance, 1e-8);
  EXPECT_EQ(to_yaml_text(parse_case(to_yaml(f), "")), to_yaml_text(f));
  EXPECT_NE(error_of(base, {"hydrodynamics.fcm.far_field_every=0"}).find("hydrodynamics.fcm.far_field_every"),
            std::string::npos);
  EXPECT_NE(error_of(base, {"hydrodynamics.fcm.lagged_cutoff=1.5"}).find("hydrodynamics.fcm.lagged_cutoff"),
            std::string::npos);
  EXPECT_NE(error_of(base, {"hydrodynamics.fcm.lagged_tolerance=0"}).find("hydrodynamics.fcm.lagged_tolerance"),
            std::string::npos);
}

TEST(Case, ContactsAreImplicitWhereverTheModelSolvesAndTheStepFollowsThePairs) {
  // Default: implicit contact springs with the resistance solve (lubrication) or FCM's sub-grid terms; explicit
  // for Stokes drag alone and for the inertial integrator, which have no overdamped solve to hold them.
  const Case lubricated = parse_case(YAML::Load(base), "");
  EXPECT_TRUE(lubricated.simulation.time_step.implicit_contacts);
  EXPECT_EQ(lubricated.simulation.time_step.bound, TimeStepParams::Bound::pairs);
  EXPECT_DOUBLE_EQ(lubricated.simulation.time_step.gap_change, 0.1);
  EXPECT_DOUBLE_EQ(lubricated.simulation.resistance.tolerance, 1e-6);
  YAML::Node drag = YAML::Load(base);
  apply_override(drag, "hydrodynamics.lubrication.enabled=false");
  EXPECT_FALSE(parse_case(drag, "").simulation.time_step.implicit_contacts);
  YAML::Node inertial = YAML::Load(base);
  apply_override(inertial, "run.integrator=inertial");
  EXPECT_FALSE(parse_case(inertial, "").simulation.time_step.implicit_contacts);
  YAML::Node fcm = YAML::Load(base);
  apply_override(fcm, "hydrodynamics.model=fcm");
  EXPECT_TRUE(parse_case(fcm, "").simulation.time_step.implicit_contacts);
  apply_override(fcm, "hydrodynamics.fcm.subgrid=false");
  EXPECT_FALSE(parse_case(fcm, "").simulation.time_step.implicit_contacts);
  // Bad values name the key.
  EXPECT_NE(error_of(base, {"run.time_step.bound=cells"}).find("run.time_step.bound"), std::string::npos);
  EXPECT_NE(error_of(base, {"run.time_step.gap_change=0"}).find("run.time_step.gap_change"), std::string::npos);
  EXPECT_NE(error_of(base, {"run.time_step.gap_change=2"}).find("run.time_step.gap_change"), std::string::npos);
}

TEST(Case, RecordedCasesWithoutAStepBoundMeanTheParticleBound) {
  // A case recorded before run.time_step.bound existed (checkpoint fingerprint, campaign point) was run with every
  // particle's displacement bounded: it is read so, and differs from the new default by that key alone.
  YAML::Node root = YAML::Load(base);
  apply_override(root, "run.time_step.bound=particles");
  const std::string former = result_identity(parse_case(root, ""));
  YAML::Node old_form = YAML::Load(former);
  old_form["run"]["time_step"].remove("bound");
  old_form["run"]["time_step"].remove("gap_change");
  YAML::Emitter recorded;
  recorded << old_form;
  EXPECT_EQ(case_changes(recorded.c_str(), former, result_identity), "");
  const std::string now = result_identity(parse_case(YAML::Load(base), ""));
  const std::string changes = case_changes(recorded.c_str(), now, result_identity);
  EXPECT_NE(changes.find("run.time_step.bound particles -> pairs"), std::string::npos) << changes;
}

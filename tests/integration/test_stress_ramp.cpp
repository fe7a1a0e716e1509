// The stress ramp through the program (io/protocols/stress_ramp.cpp): a dilute suspension is Newtonian, so the flow
// curve a ramp reads has the steady eta_r in every bin of stress and flows from the first bin; impossible settings
// are refused naming the key. (An adhesive sample ramped from arrest: docs/flow.md.)
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/integration/cli_support.hpp"

using namespace suspend::test;
using json = nlohmann::json;

namespace {
const std::string dilute =
    "particles: {phi: 0.05}\nbox: {cube: 12}\nhydrodynamics: {model: pairwise, lubrication: {enabled: true, "
    "inner_cutoff: 1.0e-3, outer_cutoff: 0.25}}\ncontact: {law: soft_repulsion, k_hat: 1.0e4}\nrun: {seed: 4}\n";
}  // namespace

TEST(StressRamp, ADiluteSuspensionReadsItsSteadyViscosityInEveryBin) {
  const std::string c = write_case("ramp_dilute.yaml", dilute);
  const std::string steady_dir = fresh_dir("ramp_steady"), ramp_dir = fresh_dir("ramp");
  ASSERT_EQ(run({"run", c, "--out", steady_dir, "--quiet", "--threads", "1", "--set", "run.strain=0.2", "--set",
                 "run.average_from=0.05"})
                .code,
            0);
  const double steady = json::parse(read_text(steady_dir + "/summary.json"))["eta_r"]["mean"];
  const Result r = run({"run", c, "--out", ramp_dir, "--quiet", "--threads", "1", "--set", "flow.type=stress_ramp",
                        "--set", "flow.shear_stress=1", "--set", "flow.ramp_time=0.5", "--set", "flow.bins=5", "--set",
                        "run.strain=0.4", "--set", "run.average_from=0.3"});
  ASSERT_EQ(r.code, 0) << r.err;
  const json ramp = json::parse(read_text(ramp_dir + "/summary.json"))["ramp"];
  const std::vector<double> stress = ramp["stress"], eta = ramp["viscosity"];
  ASSERT_EQ(stress.size(), 5u);  // rows in time fill every bin, the slow first one included
  for (std::size_t b = 0; b < stress.size(); ++b) {
    EXPECT_NEAR(stress[b], 0.2 * b + 0.1, 0.02) << b;
    EXPECT_NEAR(eta[b], steady, 0.02 * steady) << b;
  }
  EXPECT_DOUBLE_EQ(ramp["flow_onset_stress"].get<double>(), stress[0]);
}

TEST(StressRamp, ImpossibleSettingsAreRefusedNamingTheKey) {
  const std::string c = write_case("ramp_errors.yaml", dilute);
  const std::string out = fresh_dir("never");
  auto refused = [&](const std::vector<std::string>& sets, const std::string& fragment) {
    std::vector<std::string> args = {"run", c, "--out", out, "--set", "flow.type=stress_ramp"};
    for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
    expect_input_error(args, fragment, out);
  };
  refused({"flow.shear_stress=1"}, "flow.ramp_time: missing");
  refused({"flow.shear_stress=1", "flow.ramp_time=2", "flow.initial_stress=1"},
          "flow.shear_stress must exceed flow.initial_stress");
  refused({"flow.shear_stress=1", "flow.ramp_time=2", "flow.control=rate"}, "flow.control");
  refused({"flow.shear_stress=1", "flow.ramp_time=2", "flow.bins=0"}, "flow.bins");
}

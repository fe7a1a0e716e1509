// Step-stress creep through the program (io/protocols/creep.cpp): a dilute suspension is Newtonian, so its creep
// viscosity S / gammadot equals the steady eta_r of the same case and its compliance grows as J(t) = t / eta_r, in
// both hydrodynamic models, sampled from the first steps on; a creep from a level steps the stress exactly at step_time; impossible settings are
// refused naming the key. (Arrest below and flow above the yield stress of an adhesive suspension: docs/flow.md.)
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "io/hdf5.hpp"
#include "io/run_file.hpp"

#include "tests/integration/cli_support.hpp"
#include "tests/integration/dilute_case.hpp"

using namespace suspend::test;
using json = nlohmann::json;

namespace {
void expect_creep_viscosity_is_the_steady_one(const std::string& model, double box) {
  const std::string c = write_case("creep_dilute_" + model + ".yaml", dilute_case(model, box));
  const std::vector<std::string> window = {"run.strain=0.2", "run.average_from=0.05"};
  const double steady = run_summary_in(c, fresh_dir("steady_" + model), window)["eta_r"]["mean"];
  std::vector<std::string> creep = window;
  creep.insert(creep.end(), {"flow.type=creep", "flow.shear_stress=1", "flow.shear_rate=null"});
  const json s = run_summary_in(c, fresh_dir("creep_" + model), creep);
  const json& b = s["creep"];
  const double eta = b["eta_r"]["mean"];
  std::cout << model << ": creep eta_r " << eta << ", steady eta_r " << steady << "\n";
  EXPECT_NEAR(eta, steady, 0.02 * steady) << model;
  EXPECT_GT(eta, 1.0 + 2.5 * 0.05 - 0.01);  // Einstein, plus what the model adds
  EXPECT_EQ(b["shear_stress"].get<double>(), 1.0);
  // Newtonian: J(t) = t / eta_r at every sampled time, spaced evenly in log t.
  const std::vector<double> t = b["compliance"]["time_since_step"], j = b["compliance"]["J"];
  ASSERT_GE(t.size(), 10u);
  EXPECT_LE(t.size(), 31u);
  // Rows evenly in log(t - t_1) as well as in strain: J(t) from the first steps, over more than two decades.
  EXPECT_LT(100.0 * t.front(), t.back()) << "first " << t.front() << ", last " << t.back();
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(j[k], t[k] / steady, 0.03 * t[k] / steady) << k;
}
}  // namespace

TEST(Creep, DiluteCreepViscosityIsTheSteadyOneInThePairwiseModel) {
  expect_creep_viscosity_is_the_steady_one("pairwise", 12);
}

TEST(Creep, DiluteCreepViscosityIsTheSteadyOneWithFcm) { expect_creep_viscosity_is_the_steady_one("fcm", 10); }

TEST(Creep, FromALevelTheStressStepsAtStepTime) {
  const std::string c = write_case("creep_level.yaml", dilute_case("pairwise", 12));
  const std::string out = fresh_dir("creep_level");
  const json s = run_summary_in(c, out,
                             {"flow.type=creep", "flow.shear_stress=1", "flow.initial_stress=0.4",
                              "flow.step_time=0.15", "run.strain=0.3", "run.average_from=0.25"});
  suspend::io::h5::File f = suspend::io::h5::File::open(out + "/run.h5", false);
  const std::vector<double> time = suspend::io::read_series(f.id(), "time"),
                            sxy = suspend::io::read_series(f.id(), "stress/total", 3),
                            strain = suspend::io::read_series(f.id(), "strain");
  ASSERT_GT(time.size(), 10u);
  int before = 0, after = 0;
  for (std::size_t r = 0; r < time.size(); ++r) {
    if (time[r] < 0.15 * (1 - 1e-9)) {
      EXPECT_NEAR(sxy[r], 0.4, 1e-9) << r;
      ++before;
    }
    if (time[r] > 0.15 * (1 + 1e-9)) {
      EXPECT_NEAR(sxy[r], 1.0, 1e-9) << r;
      ++after;
    }
  }
  EXPECT_GT(before, 3);
  EXPECT_GT(after, 3);
  // J(t) = (gamma(t) - gamma(t_1)) / S = (t - t_1) / eta_r: the flow under S_0 went on at S_0 / eta_r, the step
  // added (S - S_0) / eta_r.
  const double eta = s["creep"]["eta_r"]["mean"];
  const std::vector<double> t = s["creep"]["compliance"]["time_since_step"], j = s["creep"]["compliance"]["J"];
  ASSERT_FALSE(t.empty());
  EXPECT_NEAR(j.back(), t.back() / eta, 0.02 * t.back() / eta);
  EXPECT_NEAR(s["creep"]["time_since_step"].get<double>() + 0.15, time.back(), 1e-9);
}

TEST(Creep, ImpossibleSettingsAreRefusedNamingTheKey) {
  const std::string c = write_case("creep_errors.yaml", dilute_case("pairwise", 12));
  const std::string out = fresh_dir("never");
  auto refused = [&](const std::vector<std::string>& sets, const std::string& fragment) {
    std::vector<std::string> args = {"run", c, "--out", out, "--set", "flow.type=creep"};
    for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
    expect_input_error(args, fragment, out);
  };
  refused({}, "flow.shear_stress: missing");
  refused({"flow.shear_stress=1", "flow.control=rate"}, "flow.control");
  refused({"flow.shear_stress=1", "flow.initial_stress=0.5"}, "flow.initial_stress: is the stress before step_time");
  refused({"flow.shear_stress=1", "flow.initial_stress=1", "flow.step_time=1"},
          "flow.initial_stress equals flow.shear_stress");
  refused({"flow.shear_stress=1", "flow.step_time=-1"}, "flow.step_time");
}

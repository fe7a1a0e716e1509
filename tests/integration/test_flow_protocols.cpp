// Flow protocols through the program (core/flow.hpp, io/oscillatory_response.hpp): a dilute suspension under
// oscillatory shear is purely viscous in both hydrodynamic models (eta' = the steady eta_r of the same case, eta''
// = 0), under imposed rate and imposed stress; an oscillation restarted from a checkpoint continues exactly;
// shear reversal of a dense frictional suspension drops the viscosity, which then recovers.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "io/hdf5.hpp"
#include "io/run_file.hpp"

#include "tests/integration/cli_support.hpp"
#include "tests/integration/dilute_case.hpp"

using namespace suspend::test;
using json = nlohmann::json;

namespace {
json run_summary(const std::string& case_file, const std::string& name, const std::vector<std::string>& sets) {
  return run_summary_in(case_file, fresh_dir(name), sets);
}

// eta' of a dilute case equals its steady eta_r within 3%, |eta''| < 2% of eta', under rate and stress control.
// `cycles`: whole cycles run, all averaged (a dilute suspension has no structural transient).
void expect_purely_viscous(const std::string& model, double box, int steps_per_cycle, int cycles) {
  const std::string c = write_case("dilute_" + model + ".yaml", dilute_case(model, box));
  const double steady =
      run_summary(c, "steady_" + model, {"run.strain=0.1", "run.average_from=0.02"})["eta_r"]["mean"];
  const std::string per_cycle = "flow.steps_per_cycle=" + std::to_string(steps_per_cycle);
  // Rate control: gamma_0 = 0.1, 4 gamma_0 of accumulated strain per cycle.
  const json rate = run_summary(c, "rate_" + model,
                                {"flow.type=oscillatory", "flow.strain_amplitude=0.1", "flow.angular_frequency=1",
                                 per_cycle, "run.strain=" + std::to_string(0.4 * cycles), "run.average_from=0"});
  // Stress control: Sigma_0 = 0.5, gamma_0 = Sigma_0 / (eta omega) ~ 0.44, about 1.76 per cycle.
  const json stress = run_summary(c, "stress_" + model,
                                  {"flow.type=oscillatory", "flow.control=stress", "flow.stress_amplitude=0.5",
                                   "flow.angular_frequency=1", per_cycle, "run.strain=" + std::to_string(1.8 * cycles),
                                   "run.average_from=0"});
  for (const json* s : {&rate, &stress}) {
    const json& o = (*s)["oscillatory"];
    ASSERT_GE(o["cycles"].get<int>(), 1) << o.dump();
    const double eta1 = o["eta_prime"]["mean"], eta2 = o["eta_double_prime"]["mean"];
    std::cout << model << " " << o["harmonics"]["response"] << ": eta' " << eta1 << ", eta'' " << eta2
              << ", steady eta_r " << steady << ", cycles " << o["cycles"] << "\n";
    EXPECT_NEAR(eta1, steady, 0.03 * steady) << model;
    EXPECT_LT(std::abs(eta2), 0.02 * eta1) << model;
    EXPECT_DOUBLE_EQ((*s)["eta_r"]["mean"].get<double>(), eta1);  // eta_r of an oscillation is eta'
    EXPECT_GT(eta1, 1.0 + 2.5 * 0.05 - 0.01);                      // Einstein, plus what the model adds
  }
  EXPECT_NEAR(rate["oscillatory"]["strain_amplitude"].get<double>(), 0.1, 1e-3);
  EXPECT_NEAR(stress["oscillatory"]["stress_amplitude"].get<double>(), 0.5, 5e-3);
}
}  // namespace

TEST(OscillatoryShear, DiluteSuspensionIsPurelyViscousInThePairwiseModel) {
  expect_purely_viscous("pairwise", 12, 100, 3);
}

TEST(OscillatoryShear, DiluteSuspensionIsPurelyViscousWithFcm) { expect_purely_viscous("fcm", 10, 32, 2); }

TEST(OscillatoryShear, AKilledAndRestartedOscillationEndsBitIdentical) {
  // Time, the rate's phase, the accumulated strain and the time-based series clock all come back from the
  // checkpoint: run B, killed once a checkpoint past 0.4 of accumulated strain exists, ends as run A.
  const std::string c = write_case("dilute_restart.yaml", dilute_case("pairwise", 12));
  std::vector<std::string> args = {"run", c, "--threads", "1", "--quiet"};
  for (const char* s : {"flow.type=oscillatory", "flow.strain_amplitude=0.1", "flow.angular_frequency=2",
                        "flow.steps_per_cycle=200", "run.average_from=0.4", "run.strain=2.4",
                        "run.output.checkpoint_every=0.1"})
    args.insert(args.end(), {"--set", s});
  auto into = [&](const std::string& dir) {
    std::vector<std::string> a = args;
    a.insert(a.end(), {"--out", dir});
    return a;
  };
  const std::string a = fresh_dir("osc_a"), b = fresh_dir("osc_b");
  ASSERT_EQ(run(into(a)).code, 0);
  const pid_t pid = spawn(into(b), b + ".err");
  bool killed = false;
  const auto t0 = std::chrono::steady_clock::now();
  while (!killed && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120)) {
    if (fs::exists(b + "/checkpoint.h5")) {
      try {
        suspend::io::h5::File f = suspend::io::h5::File::open(b + "/checkpoint.h5", false);
        if (suspend::io::h5::double_attribute(f.id(), ".", "accumulated_strain") >= 0.4) {
          kill(pid, SIGKILL);
          killed = true;
        }
      } catch (const std::exception&) {
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(wait_exit(pid), 128 + SIGKILL) << "the run finished before it could be killed: make it longer";
  std::vector<std::string> again = args;
  again.insert(again.end(), {"--restart", b + "/checkpoint.h5"});
  const Result r = run(again);
  ASSERT_EQ(r.code, 0) << r.err;
  suspend::io::h5::File ra = suspend::io::h5::File::open(a + "/run.h5", false);
  suspend::io::h5::File rb = suspend::io::h5::File::open(b + "/run.h5", false);
  for (const char* s : {"time", "strain", "accumulated_strain", "shear_rate", "stress/total", "stress/lubrication"})
    EXPECT_EQ(suspend::io::read_series(ra.id(), s), suspend::io::read_series(rb.id(), s)) << s;
  const json sa = json::parse(read_text(a + "/summary.json")), sb = json::parse(read_text(b + "/summary.json"));
  EXPECT_EQ(sa["oscillatory"]["eta_prime"], sb["oscillatory"]["eta_prime"]);
  EXPECT_EQ(sa["oscillatory"]["eta_double_prime"], sb["oscillatory"]["eta_double_prime"]);
}

// Shear reversal (Gadala-Maria & Acrivos 1980): 100 frictional spheres at phi 0.50 (lubrication, mu = 1, implicit
// springs) sheared to strain 3, then back. The contact network of the forward shear does not resist the reverse
// shear: the viscosity drops to a small fraction at once, then the network rebuilds and it recovers within 3 strain
// units. Under imposed rate and imposed stress.
TEST(ShearReversal, ViscosityDropsAtOnceThenRecovers) {
  for (const char* control : {"rate", "stress"}) {
    const std::string out = fresh_dir(std::string("reversal_") + control);
    std::vector<std::string> args = {"run", SUSPEND_SOURCE_DIR "/tests/data/restart_case.yaml", "--out", out,
                                     "--threads", "1", "--quiet"};
    for (const std::string& s :
         {std::string("particles.phi=0.5"), std::string("contact.k_hat=1e5"),
          std::string("hydrodynamics.lubrication.enabled=true"), std::string("run.time_step.contacts=implicit"),
          std::string("flow.type=reversal"), std::string("flow.reverse_at=3"), std::string("run.strain=6"),
          std::string("run.average_from=5"), std::string("flow.control=") + control,
          std::string(control) == "stress" ? std::string("flow.shear_stress=50") : std::string("flow.shear_rate=1"),
          // So few soft spheres this dense press contacts to the 10% overlap bound now and then (under imposed
          // rate seeds 1, 2, 5 and 6 all stop at an overlap of 0.1000-0.1001 a_1, seeds 1 and 2 also with the
          // engine before the solver's row order of issue 35): the bound is raised, the reversal is the subject. They also
          // stall now and then under imposed stress (seed 2); the reversal wants a flowing sample, which seed 3 is
          // under both controls.
          std::string("run.max_overlap=0.2"), std::string("run.seed=3")})
      args.insert(args.end(), {"--set", s});
    const Result r = run(args);
    ASSERT_EQ(r.code, 0) << r.err;
    const json rev = json::parse(read_text(out + "/summary.json"))["reversals"];
    ASSERT_EQ(rev.size(), 1u);
    const double before = rev[0]["eta_before"]["mean"], after = rev[0]["eta_after"]["mean"];
    const double lowest = rev[0]["eta_min"];
    // The mean viscosity over the first half strain after the reversal, from the series.
    suspend::io::h5::File f = suspend::io::h5::File::open(out + "/run.h5", false);
    const std::vector<double> g = suspend::io::read_series(f.id(), "accumulated_strain");
    const std::vector<double> rate = suspend::io::read_series(f.id(), "shear_rate");
    const std::vector<double> sxy = suspend::io::read_series(f.id(), "stress/total", 3);
    double early = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < g.size(); ++k)
      if (g[k] > 3.02 && g[k] <= 3.5) early += sxy[k] / rate[k], ++n;
    early /= n;
    std::cout << control << " control: eta before " << before << ", min " << lowest << ", mean over 0.02-0.5 after "
              << early << ", last strain unit " << after << "\n";
    EXPECT_GT(before, 50.0) << control;  // a dense frictional suspension: contacts carry most of the stress
    EXPECT_LT(lowest, 0.25 * before) << control;
    EXPECT_LT(early, 0.35 * before) << control;
    EXPECT_GT(after, 0.6 * before) << control;
    EXPECT_LT(after, 1.6 * before) << control;
    // Under stress control the rate reverses with the stress: the viscosity stays positive.
    EXPECT_LT(rate.back(), 0.0) << control;
  }
}

TEST(FlowProtocols, ImpossibleSettingsAreRefusedNamingTheKey) {
  const std::string c = write_case("dilute_errors.yaml", dilute_case("pairwise", 12));
  const std::string out = fresh_dir("never");
  auto refused = [&](const std::vector<std::string>& sets, const std::string& fragment) {
    std::vector<std::string> args = {"run", c, "--out", out};
    for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
    expect_input_error(args, fragment, out);
  };
  refused({"flow.type=oscillatory", "flow.strain_amplitude=0.1"}, "flow.angular_frequency: missing");
  refused({"flow.type=oscillatory", "flow.angular_frequency=1"}, "flow.strain_amplitude: missing");
  refused({"flow.type=oscillatory", "flow.angular_frequency=1", "flow.strain_amplitude=0.1", "flow.shear_rate=2"},
          "flow.shear_rate: an oscillation's rate is strain_amplitude x angular_frequency");
  refused({"flow.type=reversal"}, "flow.reverse_at: missing");
  refused({"flow.type=reversal", "flow.reverse_at=[2, 1]"}, "flow.reverse_at: the strains must increase");
  refused({"run.output.series_per_cycle=50"}, "run.output.series_per_cycle: applies to flow.type = oscillatory only");
  refused({"flow.type=wavy", "flow.amplitude=1", "hydrodynamics.model=fcm"}, "flow.type = wavy is not available");
}

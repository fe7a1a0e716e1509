// The flow protocols as values (core/flow.hpp, read by io/protocols/) and the harmonic analysis of an oscillation
// (io/oscillatory_response.hpp), against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/flow.hpp"
#include "io/oscillatory_response.hpp"
#include "io/protocols/protocol.hpp"

using namespace suspend;
using std::numbers::pi;

namespace {
// A flow mapping read as a case reads it (io/protocols/).
Flow read_flow(const std::string& yaml) {
  io::SchemaReader f(YAML::Load(yaml), "flow");
  Flow flow;
  std::optional<double> sigma_star;
  io::ProtocolKeys keys{f, flow, sigma_star};
  const std::string type = f.text("type", "simple_shear");
  flow.protocol = io::read_protocol(type, keys);
  f.finish();
  flow.validate();
  return flow;
}

std::string refusal(const std::string& yaml) {
  try {
    read_flow(yaml);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(FlowProtocol, OscillationImposesGammaZeroSinOmegaT) {
  const Flow f = read_flow("{type: oscillatory, strain_amplitude: 0.3, angular_frequency: 2}");
  // gamma = 0.3 sin(2 t): gammadot = 0.6 cos(2 t), whatever the accumulated strain.
  for (double t : {0.0, 0.4, 1.3, 7.7}) EXPECT_DOUBLE_EQ(f.rate(t, 123.0), 0.6 * std::cos(2.0 * t));
  EXPECT_DOUBLE_EQ(f.period(), pi);
  EXPECT_TRUE(f.periodic());
  EXPECT_DOUBLE_EQ(f.max_time_step(0.0), pi / 400.0);
  EXPECT_EQ(f.next_event_strain(1.0), INFINITY);
  EXPECT_EQ(f.next_event_time(1.0), INFINITY);
  EXPECT_DOUBLE_EQ(f.progress_rate(-0.5), 0.5);  // an oscillation counts accumulated strain
  const Flow s = read_flow("{type: oscillatory, control: stress, stress_amplitude: 4, angular_frequency: 2}");
  EXPECT_DOUBLE_EQ(s.stress(0.3, 0.0), 4.0 * std::sin(0.6));
  EXPECT_DOUBLE_EQ(s.protocol->largest_target(s), 4.0);
}

TEST(FlowProtocol, ReversalFlipsTheDirectionAtEachGivenAccumulatedStrain) {
  const Flow f = read_flow("{type: reversal, shear_rate: 2, reverse_at: [3, 5]}");
  EXPECT_DOUBLE_EQ(f.rate(0.0, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(f.rate(9.0, 2.999), 2.0);
  EXPECT_DOUBLE_EQ(f.rate(9.0, 3.0), -2.0);  // a step ends exactly on the reversal: the new direction holds
  EXPECT_DOUBLE_EQ(f.rate(9.0, 5.5), 2.0);
  EXPECT_DOUBLE_EQ(f.next_event_strain(0.0), 3.0);
  EXPECT_DOUBLE_EQ(f.next_event_strain(3.0), 5.0);
  EXPECT_EQ(f.next_event_strain(5.0), INFINITY);
  EXPECT_EQ(f.max_time_step(0.0), INFINITY);
  EXPECT_FALSE(f.counts_signed_strain());
  const Flow s = read_flow("{type: reversal, control: stress, shear_stress: 5, reverse_at: 3}");
  EXPECT_DOUBLE_EQ(s.stress(9.0, 4.0), -5.0);
}

TEST(FlowProtocol, SteadyShearIsUnchangedAndCountsSignedStrain) {
  Flow f;  // nobody set a protocol: steady shear
  f.shear_rate = 1.5;
  EXPECT_DOUBLE_EQ(f.rate(10.0, 99.0), 1.5);
  EXPECT_DOUBLE_EQ(f.progress_rate(-0.5), -0.5);
  EXPECT_EQ(f.max_time_step(0.0), INFINITY);
  EXPECT_FALSE(f.periodic());
  EXPECT_EQ(read_flow("{shear_rate: 1.5}").protocol_name(), "simple_shear");
}

TEST(FlowProtocol, CreepStepsAndARampRisesLinearlyThenHolds) {
  const Flow c = read_flow("{type: creep, shear_stress: 2, initial_stress: 0.5, step_time: 3}");
  EXPECT_EQ(c.control, FlowControl::stress);
  EXPECT_DOUBLE_EQ(c.stress(2.9, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(c.stress(3.0, 0.0), 2.0);  // a step ends on t_1: the new stress holds from it
  EXPECT_DOUBLE_EQ(c.next_event_time(1.0), 3.0);
  EXPECT_EQ(c.next_event_time(3.0), INFINITY);
  EXPECT_TRUE(c.counts_signed_strain());
  const Flow r = read_flow("{type: stress_ramp, shear_stress: 3, initial_stress: 1, ramp_time: 10, bins: 4}");
  EXPECT_DOUBLE_EQ(r.stress(0.0, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(r.stress(2.5, 0.0), 1.5);
  EXPECT_DOUBLE_EQ(r.stress(12.0, 0.0), 3.0);
  EXPECT_DOUBLE_EQ(r.max_time_step(5.0), 10.0 / 200.0);
  EXPECT_EQ(r.max_time_step(10.0), INFINITY);
  EXPECT_DOUBLE_EQ(r.next_event_time(5.0), 10.0);
  EXPECT_DOUBLE_EQ(r.protocol->series_time_interval(5.0), 10.0 / 16.0);
  EXPECT_EQ(r.protocol->series_time_interval(10.0), INFINITY);
}

TEST(FlowProtocol, ImpossibleSettingsNameTheirKey) {
  EXPECT_NE(refusal("{type: oscillatory, strain_amplitude: 0.1}").find("flow.angular_frequency"), std::string::npos);
  EXPECT_NE(refusal("{type: oscillatory, angular_frequency: 1, strain_amplitude: 0}").find("flow.strain_amplitude"),
            std::string::npos);
  EXPECT_NE(refusal("{type: reversal}").find("flow.reverse_at"), std::string::npos);
  EXPECT_NE(refusal("{type: reversal, reverse_at: [2, 1]}").find("increasing"), std::string::npos);
  EXPECT_NE(refusal("{type: shear_ramp}").find("flow.type"), std::string::npos);
  EXPECT_NE(refusal("{type: wavy, control: stress, shear_stress: 1, amplitude: 1}").find("flow.control"),
            std::string::npos);
}

TEST(OscillatoryResponse, RecoversModuliAndThirdHarmonicOfAKnownSignal) {
  // gamma = g0 sin(w t); Sigma = g0 (G' sin + G'' cos) + s3 sin(3 w t), sampled unevenly (as steps land).
  const double w = 0.7, g0 = 0.2, gp = 1.3, gpp = 4.1, s3 = 0.05;
  std::vector<double> t, stress, rate;
  for (double x = 0.0; x < 5.2 * 2 * pi / w; x += (2 * pi / w) / 97.0 * (1.0 + 0.3 * std::sin(11.0 * x))) {
    t.push_back(x);
    rate.push_back(g0 * w * std::cos(w * x));
    stress.push_back(g0 * (gp * std::sin(w * x) + gpp * std::cos(w * x)) + s3 * std::sin(3 * w * x));
  }
  const io::OscillatoryResponse r = io::oscillatory_response(t, stress, rate, w, 1.0, false);
  EXPECT_EQ(r.cycles, 4u);  // cycles 1-4 start after t = 1 and end before 5.2 periods
  EXPECT_NEAR(r.eta_prime.mean, gpp / w, 2e-3 * gpp / w);
  EXPECT_NEAR(r.eta_double_prime.mean, gp / w, 2e-3 * gpp / w);
  EXPECT_NEAR(r.strain_amplitude, g0, 2e-3 * g0);
  EXPECT_NEAR(r.stress_amplitude, g0 * std::hypot(gp, gpp), 2e-3 * g0 * gpp);
  EXPECT_NEAR(r.harmonics[0], s3 / (g0 * std::hypot(gp, gpp)), 2e-3);
  EXPECT_LT(r.harmonics[1], 2e-3);
}

TEST(OscillatoryResponse, StressControlledViscousResponseGivesTheViscosity) {
  // Sigma = S0 sin(w t) on a Newtonian fluid of viscosity eta: gammadot = Sigma / eta, eta' = eta, eta'' = 0.
  const double w = 3.0, s0 = 2.0, eta = 1.7;
  std::vector<double> t, stress, rate;
  for (double x = 0.0; x < 3.0 * 2 * pi / w; x += (2 * pi / w) / 200.0) {
    t.push_back(x);
    stress.push_back(s0 * std::sin(w * x));
    rate.push_back(s0 * std::sin(w * x) / eta);
  }
  const io::OscillatoryResponse r = io::oscillatory_response(t, stress, rate, w, 0.0, true);
  EXPECT_GE(r.cycles, 2u);
  EXPECT_NEAR(r.eta_prime.mean, eta, 1e-9);
  EXPECT_NEAR(r.eta_double_prime.mean, 0.0, 1e-9);
  EXPECT_NEAR(r.strain_amplitude, s0 / (eta * w), 1e-3 * s0 / (eta * w));
}

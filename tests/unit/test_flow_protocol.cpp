// The flow protocols as a value (core/flow.hpp) and the harmonic analysis of an oscillation
// (io/oscillatory_response.hpp), against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/flow.hpp"
#include "io/oscillatory_response.hpp"

using namespace suspend;
using std::numbers::pi;

TEST(FlowProtocol, OscillationImposesGammaZeroSinOmegaT) {
  Flow f;
  f.protocol = FlowProtocol::oscillatory;
  f.strain_amplitude = 0.3;
  f.angular_frequency = 2.0;
  f.validate();
  // gamma = 0.3 sin(2 t): gammadot = 0.6 cos(2 t), whatever the accumulated strain.
  for (double t : {0.0, 0.4, 1.3, 7.7}) EXPECT_DOUBLE_EQ(f.rate(t, 123.0), 0.6 * std::cos(2.0 * t));
  EXPECT_DOUBLE_EQ(f.period(), pi);
  EXPECT_DOUBLE_EQ(f.max_time_step(), pi / 400.0);
  EXPECT_EQ(f.next_reversal(1.0), INFINITY);
  EXPECT_DOUBLE_EQ(f.progress_rate(-0.5), 0.5);  // an oscillation counts accumulated strain
  f.control = FlowControl::stress;
  f.stress_amplitude = 4.0;
  EXPECT_DOUBLE_EQ(f.stress(0.3, 0.0), 4.0 * std::sin(0.6));
}

TEST(FlowProtocol, ReversalFlipsTheDirectionAtEachGivenAccumulatedStrain) {
  Flow f;
  f.protocol = FlowProtocol::reversal;
  f.shear_rate = 2.0;
  f.shear_stress = 5.0;
  f.reverse_at = {3.0, 5.0};
  f.validate();
  EXPECT_DOUBLE_EQ(f.rate(0.0, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(f.rate(9.0, 2.999), 2.0);
  EXPECT_DOUBLE_EQ(f.rate(9.0, 3.0), -2.0);  // a step ends exactly on the reversal: the new direction holds
  EXPECT_DOUBLE_EQ(f.stress(9.0, 4.0), -5.0);
  EXPECT_DOUBLE_EQ(f.rate(9.0, 5.5), 2.0);
  EXPECT_DOUBLE_EQ(f.next_reversal(0.0), 3.0);
  EXPECT_DOUBLE_EQ(f.next_reversal(3.0), 5.0);
  EXPECT_EQ(f.next_reversal(5.0), INFINITY);
  EXPECT_EQ(f.max_time_step(), INFINITY);
}

TEST(FlowProtocol, SteadyShearIsUnchangedAndCountsSignedStrain) {
  Flow f;
  f.shear_rate = 1.5;
  EXPECT_DOUBLE_EQ(f.rate(10.0, 99.0), 1.5);
  EXPECT_DOUBLE_EQ(f.progress_rate(-0.5), -0.5);
  EXPECT_EQ(f.max_time_step(), INFINITY);
}

TEST(FlowProtocol, ImpossibleSettingsNameTheirKey) {
  auto message = [](const Flow& f) {
    try {
      f.validate();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  Flow o;
  o.protocol = FlowProtocol::oscillatory;
  o.strain_amplitude = 0.1;
  EXPECT_NE(message(o).find("flow.angular_frequency"), std::string::npos);
  o.angular_frequency = 1.0;
  o.strain_amplitude = 0.0;
  EXPECT_NE(message(o).find("flow.strain_amplitude"), std::string::npos);
  Flow r;
  r.protocol = FlowProtocol::reversal;
  EXPECT_NE(message(r).find("flow.reverse_at"), std::string::npos);
  r.reverse_at = {2.0, 1.0};
  EXPECT_NE(message(r).find("increasing"), std::string::npos);
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

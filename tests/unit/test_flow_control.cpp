// Flow control of the pairwise engine: imposed shear stress and the wavy shear of paper 000 eq. 17.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "dem/simulation.hpp"
#include "tests/simulation_state.hpp"

using namespace suspend;
using suspend::test_support::state_of;
using std::numbers::pi;

namespace {

// A small dense cluster: a lubricated pair (gap 0.01), an overlapping pair and a pair across the sheared y face.
SimulationState cluster() {
  return state_of({{5, 5, 5}, {7.01, 5.3, 5}, {5, 7.39, 5.2}, {2, 9.2, 3}, {2.1, 1.2, 3.0}, {8, 2, 8}},
                  {1.0, 1.0, 1.4, 1.0, 1.0, 1.4});
}
}  // namespace

TEST(StressControl, DiluteSuspensionShearsAtTheTargetOverTheEinsteinViscosity) {
  // No pairs interact: Sigma_xy = gammadot (1 + 5/2 phi), so the rate must be sigma / (1 + 5/2 phi).
  const Box box(40, 40, 40);
  const auto st = state_of({{5, 5, 5}, {20, 20, 20}, {30, 10, 25}}, {1.0, 1.4, 1.0});
  const double phi = st.particles.volume() / box.volume();
  for (bool lubrication : {false, true}) {
    SimulationParams params;
    params.lubrication = lubrication;
    params.flow.control = FlowControl::stress;
    params.flow.shear_stress = 3.0;
    Simulation sim(st, box, params);
    sim.evaluate();
    EXPECT_NEAR(sim.shear_rate(), 3.0 / (1.0 + 2.5 * phi), 1e-12) << "lubrication " << lubrication;
    EXPECT_NEAR(sim.stress().total()(0, 1), 3.0, 1e-12);
    EXPECT_NEAR(sim.state().particles.velocity[1].x(), sim.shear_rate() * 20.0, 1e-10);
  }
}

TEST(StressControl, HitsTheTargetWithContactsAndLubricationAndEqualsTheRateControlledStep) {
  // Velocities and stress are linear in (gammadot, F_contact): the chosen rate, imposed instead, gives the same step.
  const Box box(10, 10, 10);
  SimulationParams params;
  params.lubrication = true;
  params.contact = ComposedLaw<ContactModel<SoftRepulsion>>{{SoftRepulsion{{1.0e3}}}, {}};
  params.flow.control = FlowControl::stress;
  params.flow.shear_stress = 2.5;
  params.resistance.tolerance = 1e-12;
  auto st = cluster();
  st.strain = 0.3;
  Simulation stress(st, box, params);
  stress.evaluate();
  EXPECT_NEAR(stress.stress().total()(0, 1), 2.5, 1e-9);
  EXPECT_GT(stress.contact_count(), 0u);

  params.flow.control = FlowControl::rate;
  params.flow.shear_rate = stress.shear_rate();
  st.shear_rate = stress.shear_rate();
  Simulation rate(st, box, params);
  rate.evaluate();
  EXPECT_NEAR(rate.stress().total()(0, 1), 2.5, 1e-9);
  for (std::size_t i = 0; i < st.particles.size(); ++i)
    EXPECT_LT((rate.state().particles.velocity[i] - stress.state().particles.velocity[i]).norm(), 1e-9) << i;
}

TEST(StressControl, CheckpointedStateContinuesBitForBit) {
  const Box box(10, 10, 10);
  SimulationParams params;
  params.lubrication = true;
  params.contact = ComposedLaw<ContactModel<SoftRepulsion>>{{SoftRepulsion{{1.0e3}}}, {}};
  params.flow.control = FlowControl::stress;
  params.flow.shear_stress = 2.0;
  Simulation whole(cluster(), box, params);
  for (int s = 0; s < 6; ++s) whole.advance();
  Simulation first(cluster(), box, params);
  for (int s = 0; s < 3; ++s) first.advance();
  const SimulationState saved = first.state_with_contacts();
  EXPECT_EQ(saved.warm_start.size(), 12 * saved.particles.size());
  Simulation second(saved, box, params);
  for (int s = 0; s < 3; ++s) second.advance();
  for (std::size_t i = 0; i < saved.particles.size(); ++i)
    EXPECT_EQ(second.state().particles.position[i], whole.state().particles.position[i]);
  EXPECT_EQ(second.state().strain, whole.state().strain);
}

TEST(WavyShear, LoneSphereMovesWithTheFaxenVelocityAndAddsItsFaxenStresslet) {
  // Paper 000 eq. 17 / A.1: U = U_inf + (a^2/6) lap U_inf, Omega = -(gammadot + U k cos ky)/2 about z,
  // S_xy = (20/3) pi a^3 (E_xy + (a^2/10) lap E_xy) with E_xy = (gammadot + U k cos ky)/2, lap E_xy = -U k^3 cos(ky)/2.
  const Box box(30, 30, 30);
  const double a = 1.4, y = 7.0, amplitude = 2.0, k = 2 * pi / 30.0;
  const auto st = state_of({{3, y, 4}}, {a});
  for (bool lubrication : {false, true}) {
    SimulationParams params;
    params.lubrication = lubrication;
    params.flow.wave_amplitude = amplitude;
    params.flow.wave_periods = 1;
    Simulation sim(st, box, params);
    sim.evaluate();
    const Particles& p = sim.state().particles;
    const double u = y + amplitude * std::sin(k * y) - (a * a / 6) * amplitude * k * k * std::sin(k * y);
    EXPECT_NEAR(p.velocity[0].x(), u, 1e-12) << "lubrication " << lubrication;
    EXPECT_NEAR(p.angular_velocity[0].z(), -0.5 * (1 + amplitude * k * std::cos(k * y)), 1e-12);
    const double e = 0.5 * (1 + amplitude * k * std::cos(k * y)), lap_e = -0.5 * amplitude * k * k * k * std::cos(k * y);
    const double s = (20.0 / 3.0) * pi * a * a * a * (e + a * a / 10 * lap_e);
    EXPECT_NEAR(sim.stress()[Contribution::hydrodynamic](0, 1), 1.0 + s / box.volume(), 1e-14);
  }
}

TEST(FlowControl, InconsistentSettingsAreRefusedNamingTheKey) {
  SimulationParams params;
  params.flow.control = FlowControl::stress;
  params.integrator = Integrator::inertial;
  EXPECT_THROW(params.validate(), InputError);
  params.integrator = Integrator::overdamped;
  params.flow.wave_amplitude = 1.0;
  params.flow.wave_periods = 1;
  EXPECT_THROW(params.validate(), InputError);
  params.flow.control = FlowControl::rate;
  params.flow.wave_periods = 0;
  EXPECT_THROW(params.validate(), InputError);
}

// The foundation dynamics: overdamped Stokes drag + soft repulsion in Lees-Edwards shear.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "dem/simulation.hpp"
#include "tests/simulation_state.hpp"

using namespace suspend;
using suspend::test_support::state_of;
using std::numbers::pi;

TEST(Simulation, DiluteSuspensionHasTheEinsteinViscosity) {
  // Far-apart spheres: each adds its Stokes stresslet (20/3) pi a^3 E, so eta_r = 1 + (5/2) phi exactly.
  const Box box(40, 40, 40);
  const auto st = state_of({{5, 5, 5}, {20, 20, 20}, {30, 10, 25}}, {1.0, 1.4, 1.0});
  Simulation sim(st, box, SimulationParams{});
  sim.evaluate();
  const double phi = st.particles.volume() / box.volume();
  EXPECT_NEAR(sim.stress().total()(0, 1), 1.0 + 2.5 * phi, 1e-14);
  EXPECT_EQ(sim.stress()[Contribution::contact_normal].norm(), 0.0);
  // A free sphere follows the flow and spins at -gammadot/2 about z.
  const Particles& p = sim.state().particles;
  EXPECT_NEAR(p.velocity[1].x(), 20.0, 1e-14);
  EXPECT_NEAR(p.angular_velocity[1].z(), -0.5, 1e-14);
}

TEST(Simulation, OverlappingPairSeparatesAtTheStokesVelocity) {
  const Box box(20, 20, 20);
  const double overlap = 0.01;
  auto st = state_of({{10, 10, 10}, {10, 10, 12 - overlap}}, {1.0, 1.0});
  SimulationParams params;
  params.flow.shear_rate = 1.0;
  Simulation sim(st, box, params);
  sim.evaluate();
  const double f = std::get<ComposedLaw<ContactModel<SoftRepulsion>>>(params.contact).contact.normal.p.kn * overlap;  // along z, pushing 1 away from 0
  EXPECT_NEAR(sim.state().particles.velocity[1].z(), f / (6 * pi), 1e-12);
  EXPECT_NEAR(sim.state().particles.velocity[0].z(), -f / (6 * pi), 1e-12);
  // Pair virial: -d F_j / V with d = 2 - overlap along z gives a positive pressure.
  const Mat3 s = sim.stress()[Contribution::contact_normal];
  EXPECT_NEAR(s(2, 2), -(2 - overlap) * f / box.volume(), 1e-12);
  EXPECT_GT(-s.trace() / 3, 0.0);
}

TEST(Simulation, ParticleCrossingTheShearedFaceIsRemapped) {
  // Paper 000 eq. 16: leaving through y = L_y, a particle re-enters at y - L_y, shifted by -offset in x, and its
  // x velocity drops by gammadot L_y. Particle 0 is pushed up through the top face by an overlapping neighbour.
  const Box box(10, 10, 10);
  const double overlap = 0.05;
  auto st = state_of({{5, 9.999, 5}, {5, 9.999 - 2 + overlap, 5}}, {1.0, 1.0});
  st.strain = 0.23;
  SimulationParams params;
  params.time_step.mode = TimeStepParams::Mode::fixed;
  params.time_step.fixed = 0.01;
  params.flow.shear_rate = 2.0;
  Simulation sim(st, box, params);
  sim.evaluate();
  const Vec3 r0 = sim.state().particles.position[0];
  const Vec3 u0 = sim.state().particles.velocity[0];
  EXPECT_NEAR(u0.x(), 2.0 * 9.999, 1e-12);
  EXPECT_NEAR(u0.y(), std::get<ComposedLaw<ContactModel<SoftRepulsion>>>(params.contact).contact.normal.p.kn * overlap / (6 * pi), 1e-9);
  sim.advance();
  const double offset = std::remainder((0.23 + 2.0 * 0.01) * 10.0, 10.0);
  EXPECT_NEAR(sim.box().shear_offset(), offset, 1e-12);
  const Vec3& r = sim.state().particles.position[0];
  EXPECT_NEAR(r.y(), r0.y() + u0.y() * 0.01 - 10.0, 1e-12);
  EXPECT_NEAR(r.x(), r0.x() + u0.x() * 0.01 - offset, 1e-12);
  EXPECT_NEAR(sim.state().particles.velocity[0].x(), u0.x() - 2.0 * 10.0, 1e-12);
  // The remapped particle keeps its distance to its neighbour (the physics does not see the face).
  EXPECT_NEAR(sim.box().minimum_image(sim.state().particles.position[1], r).d.norm(),
              (r0 + u0 * 0.01 - sim.state().particles.position[1]).norm(), 1e-9);
}

TEST(Simulation, RunawayOverlapStopsWithTheParticlesNamedAndStateKept) {
  const Box box(20, 20, 20);
  auto st = state_of({{10, 10, 10}, {10, 10, 11.5}}, {1.0, 1.0});  // overlap 0.5 > 0.1
  Simulation sim(st, box, SimulationParams{});
  try {
    sim.evaluate();
    FAIL() << "an overlap of half a radius must stop the run";
  } catch (const NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("step 0"), std::string::npos) << m;
    EXPECT_NE(m.find("particles 0 and 1"), std::string::npos) << m;
  }
  EXPECT_EQ(sim.state().particles.position[1], Vec3(10, 10, 11.5));
}

TEST(Simulation, ContactsAreThePairsWithANormalContactForce) {
  // Hertz + adhesion touches through asperities: a pair is in contact below the roughness height h_r, with no
  // overlap. Pairs (0,1) at gap 0.4 h_r and (2,3) at 0.9 h_r are contacts; (4,5) at 1.5 h_r and the distant
  // sphere 6 are not; a van der Waals attraction acting at a distance does not make a contact.
  const Box box(30, 30, 30);
  HertzAdhesiveParams hp;
  hp.roughness = 5e-3;
  hp.kn = 1e6;
  SimulationParams params;
  params.contact = ComposedLaw<HertzAdhesiveCoulomb>{{HertzAdhesive(hp), {{0.5}}, {}, Adhesion::constant(1.0)},
                                                     {std::nullopt, VanDerWaals{}}};
  const double h = hp.roughness;
  const auto st = state_of({{5, 5, 5}, {7 + 0.4 * h, 5, 5}, {5, 15, 5}, {5, 17.4 + 0.9 * h, 5}, {15, 5, 15},
                            {15, 5, 17 + 1.5 * h}, {25, 25, 25}},
                           {1.0, 1.0, 1.0, 1.4, 1.0, 1.0, 1.0});
  Simulation sim(st, box, params);
  sim.evaluate();
  EXPECT_EQ(sim.contact_count(), 2u);
  EXPECT_EQ(sim.max_overlap(), 0.0);
}

// Paper 000's modified velocity Verlet (eq. 15), run.integrator = inertial. The integrator owns what carries one
// step to the next: the half-step velocities u^{n+1/2}, w^{n+1/2} and the accelerations a^n, alpha^n (12 numbers per
// particle, checkpointed as SimulationState::verlet), and the masses St (4/3) pi a^3 and moments (2/5) m a^2. It asks
// its InertialModel for the hydrodynamic force at the half-step velocities (eq. 15c); the overdamped integration is
// Simulation's resistance solve.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "core/particles.hpp"
#include "core/ambient_flow.hpp"
#include "dem/hydrodynamic_model.hpp"

namespace suspend {

class VerletIntegrator {
 public:
  // From `saved` (12 per particle), or, when it is empty, from rest relative to the imposed flow with zero
  // acceleration: with last_dt = 0 the first evaluation gives u^0 = U_inf and a^0 = F(x^0, U_inf) / m, as eq. 15
  // needs. Throws InputError for a saved state of the wrong size. `model` answers the step's force question.
  VerletIntegrator(InertialModel& model, const Particles& p, double stokes_number, const std::vector<double>& saved,
                   const AmbientFlow& flow);
  // The state to checkpoint: 12 numbers per particle (u, w at the half step, then a, alpha).
  const std::vector<double>& saved() const { return state_; }

  // The velocities the contact laws see at a step's start: the half-step ones (eq. 15c).
  void set_contact_velocities(Particles& p) const;
  // The hydrodynamic force at the half-step velocities in the flow at `rate`, the accelerations a^{n+1} from it and
  // the load's contact forces, and u^{n+1} = u^{n+1/2} + (last_dt / 2) a^{n+1} (eq. 15d) into p. Returns the model's
  // response (its stress sums).
  const ExplicitResponse& velocities(const HydroLoad& load, double rate, const AmbientFlow& flow, double last_dt,
                                     Particles& p);
  // The explicit stability bound: `stability` x the contact time sqrt(m_min / k) and x the fastest hydrodynamic
  // relaxation time of the last evaluation.
  double stability_time_step(double stiffness, double stability) const;
  // u^{n+3/2} = u^{n+1} + (dt/2) a^{n+1}, stored with a^{n+1} (eqs. 15a-b): the velocity particle i moves with.
  Vec3 half_step(std::size_t i, const Particles& p, double dt);
  // A Lees-Edwards crossing changes the stored half-step velocity as it changes the particle's (eq. 16d).
  void subtract_velocity_x(std::size_t i, double dv) { state_[12 * i] -= dv; }

 private:
  InertialModel& model_;
  std::vector<double> state_;
  std::vector<double> mass_, moment_;
  Eigen::VectorXd disturbance_;
  std::vector<double> acceleration_;  // a^{n+1}, alpha^{n+1} of the current evaluation (6 per particle)
  double relaxation_rate_ = 0.0;      // bound on the fastest hydrodynamic relaxation rate
};

}  // namespace suspend

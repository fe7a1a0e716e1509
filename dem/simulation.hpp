// The one time step of both engines: particles in simple or wavy shear (paper 000 eq. 17) under Lees-Edwards
// boundaries, with the shared contact module and a pluggable hydrodynamic model (dem/hydrodynamic_model.hpp):
// Stokes drag + Faxen, pairwise lubrication, their explicit inertial form (dem/integrate/pairwise_models.hpp), or
// FCM with sub-grid lubrication (coupling/fcm_model.hpp). evaluate() walks the step as the physics tells it
// (docs/architecture.md section 2):
//   contacts -> time step (implicit contacts) -> hydrodynamics -> flow control -> checks -> stress -> time step.
//
// Overdamped (default, zero inertia): the model balances the contact forces, F_H + F_C = 0, for the velocities.
// Inertial (finite Stokes number St = rho a_1^2 gammadot_ref / eta_0, paper 000 eq. 11), the modified velocity-Verlet
// scheme of paper 000 eq. 15 with the hydrodynamic forces explicit at the half-step velocities:
//   x^{n+1} = x^n + dt u^{n+1/2},  u^{n+1/2} = u^n + (dt/2) a^n,  a^{n+1} = F(x^{n+1}, u^{n+1/2}) / m,
//   u^{n+1} = u^{n+1/2} + (dt/2) a^{n+1};   m = St (4/3) pi a^3, moment of inertia (2/5) m a^2.
// Flow control: an imposed shear rate, or an imposed shear stress: with zero inertia velocities and stress are
// linear in (gammadot, F_contact), Sigma_xy = gammadot Sigma_H + Sigma_C, so each step asks the model for the
// rate-driven and the force-driven parts and picks gammadot = (target - Sigma_C) / Sigma_H. Lees-Edwards follows the
// accumulated strain.
// Bulk stress (paper 000, eqs. 8-9), in units of eta_0 gammadot_ref:
//   Sigma = 2 eta <E_inf> + (1/V) [ model's particle and pair sums (stresslets, lubrication)  +  sum_pairs -sym(d F_j^T) ],
// with F_j the contact forces by contribution; eta_r = 1 + 2.5 phi for far-apart spheres.
// Units: eta_0 = 1, lengths in a_1, time in 1/gammadot_ref.
//
// A step is transactional: evaluate() computes forces, velocities and stress for the current configuration and
// checks them; advance() moves the particles. A numerical failure is raised from evaluate(), before anything
// moved, so the state is still the last good one and can be checkpointed.
#pragma once
#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/box.hpp"
#include "core/flow.hpp"
#include "core/particles.hpp"
#include "core/stress.hpp"
#include "dem/contact/contact_law.hpp"
#include "dem/contact_history.hpp"
#include "dem/contact_stage.hpp"
#include "core/ambient_flow.hpp"
#include "dem/hydrodynamic_model.hpp"
#include "dem/integrate/resistance_solver.hpp"
#include "dem/integrate/time_step_control.hpp"
#include "dem/integrate/verlet_integrator.hpp"
#include "dem/pair_forces.hpp"
#include "dem/verlet_list.hpp"

namespace suspend {

enum class Integrator { overdamped, inertial };

struct SimulationParams {
  Flow flow;  // control, protocol and shape of the imposed flow (core/flow.hpp)
  Integrator integrator = Integrator::overdamped;
  double stokes_number = 1.0e-3;            // inertial: St = rho a_1^2 gammadot_ref / eta_0 (the density in code units)
  ContactLaw contact = ComposedLaw<ContactModel<SoftRepulsion>>{};
  bool lubrication = false;           // pairwise lubrication and the resistance solve, else Stokes drag alone
  ResistanceSolverParams resistance;  // lubrication cutoffs and the linear solver
  TimeStepParams time_step;
  double max_overlap = 0.1;  // stop if any overlap exceeds this fraction of the smaller radius
  double skin = 0.4;         // neighbour-list skin (a_1)
  void validate() const;
};

// The dynamical state that a checkpoint must hold to continue exactly.
struct SimulationState {
  Particles particles;
  double time = 0.0;
  double strain = 0.0;              // signed: the Lees-Edwards cell's
  double accumulated_strain = 0.0;  // integral of |gammadot| dt (core/flow.hpp)
  std::int64_t step = 0;
  double last_dt = 0.0;  // time step of the last advance: frictional springs integrate the last velocities over it
  double shear_rate = 0.0;  // shear rate of the last advance (Lees-Edwards image velocity); 0: the imposed one
  // Inertial integrator: per particle 12 numbers, half-step velocity and angular velocity u^{n+1/2}, w^{n+1/2},
  // then acceleration and angular acceleration a^n, alpha^n. Empty when overdamped (or before the first step).
  std::vector<double> verlet;
  // Stored contact histories (tangential and rolling stretch) of the pairs in contact.
  std::vector<ContactHistory::Entry> contacts;
  // The hydrodynamic model's warm start (HydrodynamicModel::warm_start_state): the resistance solvers' last
  // disturbance velocities (6 or 12 per particle), the FCM solver's last solutions; empty for drag alone.
  std::vector<double> warm_start;
};

class Simulation {
 public:
  // The pairwise engine: the model of make_pairwise_model (drag, lubrication solved, or inertial explicit forces).
  Simulation(SimulationState state, const Box& box, const SimulationParams& params);
  // Any hydrodynamic model, e.g. FcmModel (coupling/fcm_model.hpp: fcm_simulation()).
  Simulation(SimulationState state, const Box& box, const SimulationParams& params,
             std::unique_ptr<HydrodynamicModel> model);

  // Forces, velocities, stress and the next time step for the current configuration. Throws NumericalError.
  void evaluate();
  // Moves particles by the velocities of the last evaluate() over its time step; wraps; updates strain and time.
  void advance();
  // Shortens the step evaluate() chose (never lengthens it), e.g. so that the last step ends on run.strain.
  void clip_time_step(double dt) { step_.at_most(dt, StepLimit::flow); }
  // The steps advanced by this object, by what set their length (printed at the end of `suspend run`).
  const StepLimitCounts& step_limits() const { return step_limits_; }

  // The state, with the contact histories and the model's warm start copied in (for checkpoints).
  SimulationState state_with_contacts() const;
  const SimulationState& state() const { return state_; }
  const Box& box() const { return box_; }
  const SimulationParams& params() const { return params_; }
  HydrodynamicModel& model() { return *model_; }
  const HydrodynamicModel& model() const { return *model_; }
  // Shear rate of the current step (the imposed one, or the one the stress control chose).
  double shear_rate() const { return rate_; }
  double time_step() const { return step_.dt; }
  const StressTensors& stress() const { return stress_; }
  double max_overlap() const { return contacts_.sums().max_overlap; }
  // Linear-solver iterations of the step (both problems under stress control) and the larger residual.
  int solver_iterations() const { return iterations_; }
  double solver_residual() const { return residual_; }
  std::size_t contact_count() const { return contacts_.sums().contacts; }
  const std::vector<ActivePair>& active_pairs() const { return contacts_.pairs(); }
  const VerletList& neighbours() const { return contacts_.neighbours(); }
  // Force on j of each active pair (same order as active_pairs()), for snapshots.
  const std::vector<Vec3>& pair_forces() const { return contacts_.pair_forces(); }
  ContactRecords contact_records() const { return contacts_.records(); }
  // Wall-clock seconds of the contact stage since construction.
  double contact_seconds() const { return contact_seconds_; }

 private:
  AmbientFlow flow(double rate) const { return params_.flow.ambient(rate, box_.length().y()); }
  [[noreturn]] void fail(const std::string& what) const;
  HydroLoad load(const ImplicitContacts& implicit) const;
  double overdamped_velocities(const HydroLoad& load);  // return the largest non-affine speed
  double inertial_velocities(const HydroLoad& load);
  void finish_stress(const StressTensors& hydrodynamic);
  StepBound next_time_step(double max_speed) const;
  // bound = pairs: the pairs' relative motion per unit step (dem/integrate/pair_motion.hpp) at the particles'
  // velocities, Lees-Edwards images moving at `rate` L_y; 0 otherwise.
  PairBound pair_rate(double rate) const;

  SimulationState state_;
  Box box_;
  SimulationParams params_;
  std::unique_ptr<HydrodynamicModel> model_;
  OverdampedModel* overdamped_ = nullptr;  // model_ as an overdamped step asks it (run.integrator = overdamped)
  double a_min_ = 1.0;  // smallest radius (overlap bound, time-step bound)
  ContactStage contacts_;
  std::optional<VerletIntegrator> verlet_;  // run.integrator = inertial: the velocity Verlet, its state and model
  double rate_ = 1.0;
  int iterations_ = 0;
  double residual_ = 0.0;
  std::vector<double> speeds_;                // scratch of nonaffine_bounding_speed
  mutable KthLargest pair_rates_;             // pair_rate's ranking
  std::vector<Vec3> nonaffine_;
  StressTensors stress_;
  StepBound step_;  // the step evaluate() chose and what set it
  StepLimitCounts step_limits_;
  // Implicit contacts: a step is solved again with the step its own motion allows when it exceeds that by this factor.
  static constexpr double step_overshoot = 2.0;
  const std::vector<Vec3>* contact_change_ = nullptr;  // the final solve's contact changes (model-owned)
  bool evaluated_ = false;
  double contact_seconds_ = 0.0;
};

}  // namespace suspend

// The pairwise engine's simulation: particles in simple or wavy shear (paper 000 eq. 17) under Lees-Edwards
// boundaries. Each particle feels Stokes drag with the Faxen terms against the imposed flow (paper 000 eq. A.1),
// optionally pairwise lubrication (paper 000 eq. 3, Appendix A), and the contact law (any law of the shared contact
// module, with its pair history).
//
// Overdamped (default, zero inertia), the force balance is
//   without lubrication:  U_i = U_inf + (a^2/6) lap U_inf + F_i / (6 pi a_i),  Omega_i = Omega_inf + T_i / (8 pi a_i^3);
//   with lubrication:     (R_Stokes + R_lub) dV = F_contact + R_FE : E_inf + F_Faxen  (dem/integrate/resistance_solver.hpp).
// Inertial (finite Stokes number St = rho a_1^2 gammadot_ref / eta_0, paper 000 eq. 11), the modified velocity-Verlet
// scheme of paper 000 eq. 15 with the hydrodynamic forces explicit at the half-step velocities:
//   x^{n+1} = x^n + dt u^{n+1/2},  u^{n+1/2} = u^n + (dt/2) a^n,  a^{n+1} = F(x^{n+1}, u^{n+1/2}) / m,
//   u^{n+1} = u^{n+1/2} + (dt/2) a^{n+1};   m = St (4/3) pi a^3, moment of inertia (2/5) m a^2.
// With lubrication the explicit forces are evaluated matrix-free (dem/integrate/explicit_hydrodynamics.hpp).
// Flow control: an imposed shear rate, or an imposed shear stress: with zero inertia velocities and stress are
// linear in (gammadot, F_contact), Sigma_xy = gammadot Sigma_H + Sigma_C, so each step solves the rate-driven and the
// force-driven problems and picks gammadot = (target - Sigma_C) / Sigma_H. Lees-Edwards follows the accumulated strain.
// Bulk stress (paper 000, eqs. 8-9), in units of eta_0 gammadot_ref:
//   Sigma = 2 eta <E_inf> + (1/V) [ sum_i (20/3) pi eta a_i^3 (E_inf + (a^2/10) lap E_inf)  +  sum_pairs -sym(d F_j^T) ],
// with F_j the contact and lubrication forces by contribution; eta_r = 1 + 2.5 phi for far-apart spheres.
// Units: eta_0 = 1, lengths in a_1, time in 1/gammadot_ref.
//
// A step is transactional: evaluate() computes forces, velocities and stress for the current configuration and
// checks them; advance() moves the particles. A numerical failure is raised from evaluate(), before anything
// moved, so the state is still the last good one and can be checkpointed.
#pragma once
#include <algorithm>
#include <cstdint>
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
#include "dem/integrate/explicit_hydrodynamics.hpp"
#include "dem/integrate/resistance_solver.hpp"
#include "dem/integrate/time_step_control.hpp"
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
  // The resistance solvers' last disturbance velocities (their warm starts), 6 per particle (12 under stress
  // control: the rate-driven then the force-driven problem); empty without lubrication.
  std::vector<double> warm_start;
};

class PairwiseSimulation {
 public:
  PairwiseSimulation(SimulationState state, const Box& box, const SimulationParams& params);

  // Forces, velocities, stress and the next time step for the current configuration. Throws NumericalError.
  void evaluate();
  // Moves particles by the velocities of the last evaluate() over its time step; wraps; updates strain and time.
  void advance();
  // Shortens the step evaluate() chose (never lengthens it), e.g. so that the last step ends on run.strain.
  void clip_time_step(double dt) { dt_ = std::min(dt_, dt); }

  // The state, with the contact histories copied in (for checkpoints).
  SimulationState state_with_contacts() const;
  const SimulationState& state() const { return state_; }
  const Box& box() const { return box_; }
  const SimulationParams& params() const { return params_; }
  // Shear rate of the current step (the imposed one, or the one the stress control chose).
  double shear_rate() const { return rate_; }
  double time_step() const { return dt_; }
  const StressTensors& stress() const { return stress_; }
  double max_overlap() const { return contacts_.sums().max_overlap; }
  // Conjugate-gradient iterations of the step (both problems under stress control) and the larger residual.
  int solver_iterations() const { return solve_.iterations + (force_solver_ ? force_solve_.iterations : 0); }
  double solver_residual() const { return std::max(solve_.residual, force_solver_ ? force_solve_.residual : 0.0); }
  std::size_t contact_count() const { return contacts_.sums().contacts; }
  const std::vector<ActivePair>& active_pairs() const { return contacts_.pairs(); }
  const VerletList& neighbours() const { return contacts_.neighbours(); }
  // Force on j of each active pair (same order as active_pairs()), for snapshots.
  const std::vector<Vec3>& pair_forces() const { return contacts_.pair_forces(); }
  const std::vector<ContactRecord>& contact_records() const { return contacts_.records(); }

 private:
  hydro::WavyShear flow(double rate) const {
    return {rate, params_.flow.wave_amplitude, params_.flow.wave_periods, box_.length().y()};
  }
  [[noreturn]] void fail(const std::string& what) const;
  void contact_forces(double image_velocity);
  double overdamped_velocities();  // returns the largest non-affine speed
  double inertial_velocities();
  void finish_stress(double rate);

  SimulationState state_;
  Box box_;
  SimulationParams params_;
  double a_min_ = 1.0;         // smallest radius (overlap bound, time-step bound)
  double radius_cubed_ = 0.0;  // sum of a^3, for the Stokes stresslets of the drag-only model
  ContactStage contacts_;
  std::vector<double> species_radius_;  // distinct radii
  std::vector<int> species_;            // index into species_radius_ per particle
  std::optional<ResistanceSolver> solver_;
  std::optional<ResistanceSolver> force_solver_;  // stress control: the force-driven problem (own warm start)
  std::optional<ExplicitHydrodynamics> explicit_;  // inertial with lubrication: matrix-free explicit forces
  ExplicitHydroResult explicit_out_;
  SolveResult solve_, force_solve_;
  Eigen::VectorXd disturbance_, hydro_force_;
  std::vector<Vec3> zero_;
  std::vector<double> mass_, moment_;
  std::vector<double> acceleration_;  // inertial: a^{n+1}, alpha^{n+1} of the current evaluation (6 per particle)
  double relaxation_rate_ = 0.0;      // inertial: bound on the fastest hydrodynamic relaxation rate
  double rate_ = 1.0;
  std::vector<Vec3> nonaffine_;
  StressTensors stress_;
  double dt_ = 0.0;
  bool evaluated_ = false;
};

}  // namespace suspend

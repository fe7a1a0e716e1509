// The FCM-resolved engine's simulation: the same interface, contact module, time-step control, failure handling
// and outputs as the pairwise engine (dem/simulation.hpp), with the hydrodynamics replaced by the Force Coupling
// Method plus sub-grid lubrication (DESIGN.md section 7; paper 004 sections II A-II B, II E 2).
//
// Force balance per particle (zero inertia): FCM hydrodynamic + sub-grid lubrication + contact = 0, solved for
// the velocities and the rigidity stresslets together (coupled_mobility.hpp). Contact forces use the velocities of
// the last step (as in the pairwise engine), so the solve is linear in the unknowns; with implicit contacts
// (run.time_step.contacts, dem/integrate/implicit_contacts.hpp) their change over the step enters the sub-grid
// pair terms. Flow control as in the pairwise engine: imposed rate, or imposed stress from the rate-driven and
// force-driven parts of the linear problem (CoupledMobility::solve_parts).
// Bulk stress, units eta_0 gammadot_ref:
//   hydrodynamic: 2 E_inf + (1/V) sum_i S_i (FCM stresslets; fcm::Solver::bulk_stress)
//   lubrication:  (1/V) sum over corrected pairs of their force dipoles (subgrid_lubrication.hpp)
//   contacts:     (1/V) sum_pairs -sym(d F_j) per Contribution (dem/pair_forces.hpp)
// eta_r -> 1 + 2.5 phi for dilute suspensions (test_coupling_suspension_viscosity).
// Units: eta_0 = 1, lengths in a_1, time in 1/gammadot_ref. Flow x, gradient y, vorticity z.
//
// A step is transactional exactly as in PairwiseSimulation: evaluate() computes everything and may throw
// NumericalError before anything moved; advance() moves the particles.
#pragma once
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "core/box.hpp"
#include "core/stress.hpp"
#include "coupling/coupled_mobility.hpp"
#include "coupling/subgrid_lubrication.hpp"
#include "dem/contact_stage.hpp"
#include "dem/pair_forces.hpp"
#include "dem/simulation.hpp"
#include "dem/verlet_list.hpp"

namespace suspend {

struct FcmParams {
  double grid_spacing = 0.0;       // h (a_1); <= 0 means half the smallest radius. Rounded to whole cells per box side
  double truncation_widths = 4.0;  // Gaussian envelopes cut at this many sigma_M (fcm::SolverOptions)
  double krylov_tolerance = 1e-4;  // relative residual of the coupled solve (coupled_mobility.hpp)
  int max_iterations = 200;        // GMRES iterations (one Stokes solve each) before NumericalError
  bool warm_start = true;          // start from the previous steps' velocities and stresslets (extrapolated);
                                   // SimulationState::warm_start: CoupledMobility::warm_start_state
  double preconditioner_cutoff = 2.2;  // s' below which pairs enter the GMRES near-field preconditioner
  // Multi-rate stepping: the full FCM solve at steps that are multiples of this, the lagged far field between
  // (coupled_mobility.hpp "Lagged far field"; 1: every step; docs/coupling.md section 3b has the measured errors).
  int far_field_every = 1;
  double lagged_cutoff = 2.25;     // s' below which pair corrections are solved on lagged steps too
  double lagged_tolerance = 1e-6;  // relative residual of the lagged steps' conjugate-gradient solve
  bool subgrid = true;             // sub-grid lubrication (false: FCM alone)
  double subgrid_cutoff = 3.5;     // s' = 2r/(a_i + a_j) beyond which the correction is zero
  double subgrid_taper_start = 2.5;        // s' where the correction starts tapering to zero (equal spheres)
  double subgrid_model_taper_start = 2.1;  // same for unequal spheres (singular model only)
  double table_spacing = 0.05;     // spacing in s' of the FCM pair-resistance table
  std::string cache_dir;           // where FCM pair tables are cached (empty: recomputed in every run)
  void validate() const;           // throws InputError naming the key (fcm.*)
};

class FcmSimulation {
 public:
  FcmSimulation(SimulationState state, const Box& box, const SimulationParams& params, const FcmParams& fcm = {});

  void evaluate();
  void advance();
  // Shortens the step evaluate() chose (never lengthens it), e.g. so that the last step ends on run.strain.
  void clip_time_step(double dt) { dt_ = std::min(dt_, dt); }

  SimulationState state_with_contacts() const;
  const SimulationState& state() const { return state_; }
  const Box& box() const { return box_; }
  const SimulationParams& params() const { return params_; }
  // Shear rate of the current step (the imposed one, or the one the stress control chose).
  double shear_rate() const { return rate_; }
  double time_step() const { return dt_; }
  const StressTensors& stress() const { return stress_; }
  double max_overlap() const { return contacts_.sums().max_overlap; }
  int solver_iterations() const { return result_.iterations; }
  std::size_t contact_count() const { return contacts_.sums().contacts; }
  const std::vector<ActivePair>& active_pairs() const { return contacts_.pairs(); }
  const VerletList& neighbours() const { return contacts_.neighbours(); }
  const std::vector<Vec3>& pair_forces() const { return contacts_.pair_forces(); }
  const std::vector<ContactRecord>& contact_records() const { return contacts_.records(); }

  // FCM-specific diagnostics.
  const FcmParams& fcm_params() const { return fcm_; }
  double solver_residual() const { return result_.residual; }
  int stokes_solves() const { return result_.stokes_solves; }
  // Since construction (this invocation of a run; a restart counts afresh): steps evaluated and Stokes solves.
  std::int64_t evaluated_steps() const { return evaluated_steps_; }
  std::int64_t total_stokes_solves() const { return total_stokes_solves_; }
  std::size_t corrected_pairs() const { return subgrid_ ? subgrid_->corrected_pairs() : 0; }
  coupling::CoupledMobility& mobility() { return *mobility_; }
  // Wall-clock seconds of the contact-force stage and the sub-grid assembly since construction.
  double contact_seconds() const { return contact_seconds_; }
  double subgrid_assembly_seconds() const { return subgrid_seconds_; }

 private:
  Vec3 ambient_velocity(const Vec3& r) const { return {rate_ * r.y(), 0.0, 0.0}; }
  [[noreturn]] void fail(const std::string& what) const;
  // The coupled solve for this configuration: imposed rate, or (stress control) the rate-driven and force-driven
  // parts combined with the rate that gives Sigma_xy = target; sets rate_ and result_.
  void solve_velocities();
  // Sigma_xy (times V) of one solution: FCM stresslets, sub-grid dipoles and implicit contact changes.
  double hydrodynamic_shear_stress(const coupling::CoupledResult& r, double rate) const;

  SimulationState state_;
  Box box_;
  SimulationParams params_;
  FcmParams fcm_;
  double a_min_ = 1.0;
  ContactStage contacts_;
  std::vector<double> species_radius_;
  std::vector<int> species_;
  std::optional<coupling::SubgridLubrication> subgrid_;
  std::optional<coupling::CoupledMobility> mobility_;
  coupling::CoupledResult result_, force_result_;  // stress control: result_ is the rate-driven part first
  double rate_ = 1.0;
  std::vector<Vec3> nonaffine_;
  StressTensors stress_;
  double dt_ = 0.0;
  bool evaluated_ = false;
  double contact_seconds_ = 0.0, subgrid_seconds_ = 0.0;
  std::int64_t evaluated_steps_ = 0, total_stokes_solves_ = 0;
};

}  // namespace suspend

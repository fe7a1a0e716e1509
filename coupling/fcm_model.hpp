// The FCM-resolved engine's hydrodynamics: the Force Coupling Method plus sub-grid lubrication (docs/coupling.md;
// paper 004 sections II A-II B, II E 2) as a model of the one time step (dem/simulation.hpp), which
// supplies the contacts, time-step control, flow control, checks and outputs of the pairwise engine.
//
// Force balance per particle (zero inertia): FCM hydrodynamic + sub-grid lubrication + contact = 0, solved for
// the velocities and the rigidity stresslets together (coupled_mobility.hpp). Contact forces use the velocities of
// the last step (as in the pairwise engine), so the solve is linear in the unknowns; with implicit contacts
// (run.time_step.contacts, dem/integrate/implicit_contacts.hpp) their change over the step enters the sub-grid
// pair terms. Imposed stress: the rate-driven and force-driven parts of the linear problem
// (CoupledMobility::solve_parts).
// Stress sums (the step divides by V and adds 2 E_inf):
//   hydrodynamic: sum_i S_i (FCM rigidity stresslets)
//   lubrication:  sum over corrected pairs of their force dipoles (subgrid_lubrication.hpp)
// eta_r -> 1 + 2.5 phi for dilute suspensions (test_coupling_suspension_viscosity).
// Units: eta_0 = 1, lengths in a_1, time in 1/gammadot_ref. Flow x, gradient y, vorticity z.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/box.hpp"
#include "core/stress.hpp"
#include "coupling/coupled_mobility.hpp"
#include "coupling/subgrid_lubrication.hpp"
#include "dem/hydrodynamic_model.hpp"
#include "dem/simulation.hpp"

namespace suspend {

struct FcmParams {
  double grid_spacing = 0.0;       // h (a_1); <= 0 means half the smallest radius. Rounded to whole cells per box side
  double truncation_widths = 4.0;  // Gaussian envelopes cut at this many sigma_M (fcm::SolverOptions)
  double krylov_tolerance = 1e-4;  // relative residual of the coupled solve (coupled_mobility.hpp)
  // GMRES iterations (one Stokes solve each) before NumericalError. A warm-started solve takes 1-3; the first full
  // solve in a jammed random packing at phi 0.64 (mu_s 0.3, sigma* 0.7) took 200-300.
  int max_iterations = 1000;
  bool warm_start = true;          // start from the previous steps' velocities and stresslets (extrapolated);
                                   // SimulationState::warm_start: CoupledMobility::warm_start_state
  double preconditioner_cutoff = 2.2;  // s' below which pairs enter the GMRES near-field preconditioner
  int preconditioner_iterations = 5;   // its inner block-SGS CG iterations (KrylovParams::inner_max_iterations)
  // Multi-rate stepping: the full FCM solve at steps that are multiples of this, the lagged far field between
  // (coupled_mobility.hpp "Lagged far field"; 1: every step; docs/coupling.md section 3b has the measured errors).
  // With the lagged predictor the default: FCM at 2-3x the pairwise engine's cost, its rheology that of every step
  // within the seed ensembles' errors (docs/validation.md section 3, "The fast setting").
  int far_field_every = 10;
  // Full solves start from the lagged-far-field step's velocities instead of the extrapolated ones
  // (KrylovParams::lagged_predictor; docs/coupling.md section 3c).
  bool lagged_predictor = true;
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

// The hydrodynamic model (dem/hydrodynamic_model.hpp) of FCM + sub-grid lubrication: each solve assembles the
// sub-grid pair terms of the configuration (with implicit contacts their steps too) and calls the coupled solve.
class FcmModel final : public OverdampedModel {
 public:
  // Validates the fcm.* keys and refuses what FCM cannot do (inertia, wavy shear, implicit contacts without the
  // sub-grid correction): InputError naming the key.
  FcmModel(const Particles& p, const Box& box, const SimulationParams& params, const FcmParams& fcm);
  // The same checks without building anything (the case reader refuses a case before its run starts).
  static void check(const SimulationParams& params, const FcmParams& fcm);
  double pair_range() const override { return subgrid_ ? subgrid_->range() : 0.0; }
  HydroResponse& solve(const HydroLoad& load, double rate) override;
  std::pair<HydroResponse&, HydroResponse&> solve_parts(const HydroLoad& load) override;
  std::vector<double> warm_start_state() const override { return mobility_->warm_start_state(); }
  void set_warm_start_state(const std::vector<double>& state, std::size_t n, bool parts) override {
    mobility_->set_warm_start_state(state, n, parts);
  }

  // Diagnostics.
  const FcmParams& fcm_params() const { return fcm_; }
  int stokes_solves() const { return stokes_solves_; }  // of the last step
  // Since construction (this invocation of a run; a restart counts afresh): steps solved and Stokes solves.
  std::int64_t evaluated_steps() const { return evaluated_steps_; }
  std::int64_t total_stokes_solves() const { return total_stokes_solves_; }
  std::size_t corrected_pairs() const { return subgrid_ ? subgrid_->corrected_pairs() : 0; }
  coupling::CoupledMobility& mobility() { return *mobility_; }
  // Wall-clock seconds of the sub-grid assembly since construction.
  double subgrid_assembly_seconds() const { return subgrid_seconds_; }

 private:
  // The sub-grid pair terms of this configuration, and the problem the coupled solve gets.
  coupling::CoupledProblem assemble(const HydroLoad& load, double rate);
  // The response of a coupled solution: velocities, stresslet and dipole sums, implicit contact changes.
  void respond(const coupling::CoupledResult& r, const std::vector<ActivePair>& pairs, HydroResponse& out) const;

  FcmParams fcm_;
  Flow flow_;  // the imposed flow; its ambient value at each rate (simple shear: FCM refuses the wave)
  RadiusClasses classes_;
  std::optional<coupling::SubgridLubrication> subgrid_;
  std::optional<coupling::CoupledMobility> mobility_;
  coupling::CoupledResult result_, force_result_;
  HydroResponse out_, force_out_;
  int stokes_solves_ = 0;
  double subgrid_seconds_ = 0.0;
  std::int64_t evaluated_steps_ = 0, total_stokes_solves_ = 0;
};

// A simulation with the FCM model.
Simulation fcm_simulation(SimulationState state, const Box& box, const SimulationParams& params,
                          const FcmParams& fcm = {});
// The FCM model of such a simulation (std::bad_cast for another model).
FcmModel& fcm_model(Simulation& sim);
const FcmModel& fcm_model(const Simulation& sim);

}  // namespace suspend

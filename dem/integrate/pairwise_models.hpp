// The pairwise engine's hydrodynamic models (dem/hydrodynamic_model.hpp), picked by make_pairwise_model from the
// case: hydrodynamics.lubrication.enabled and run.integrator.
//   StokesDragModel          overdamped, drag + Faxen alone (paper 000 eq. A.1):
//                              U_i = U_inf + (a^2/6) lap U_inf + F_i / (6 pi a_i),  Omega_i = Omega_inf + T_i / (8 pi a_i^3)
//   PairwiseResistanceModel  overdamped with pairwise lubrication: (R_Stokes + R_lub) dV = F + R_FE : E_inf + F_Faxen
//                            (dem/integrate/resistance_solver.hpp); under imposed stress a second solver keeps the
//                            force-driven problem's own warm start
//   ExplicitPairwiseModel    inertial (paper 000 eq. 15c): the hydrodynamic force at the half-step velocities,
//                            Stokes drag alone or with lubrication (dem/integrate/explicit_hydrodynamics.hpp)
// Stress sums of all three: the Stokes stresslets (20/3) pi a^3 (E_inf + (a^2/10) lap E_inf) (paper 000 eq. 9a) and,
// with lubrication, the pair terms.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "core/flow.hpp"
#include "dem/hydrodynamic_model.hpp"
#include "dem/integrate/explicit_hydrodynamics.hpp"
#include "dem/integrate/resistance_solver.hpp"

namespace suspend {

struct SimulationParams;

class StokesDragModel final : public OverdampedModel {
 public:
  explicit StokesDragModel(const Flow& flow) : flow_(flow) {}
  HydroResponse& solve(const HydroLoad& load, double rate) override;
  std::pair<HydroResponse&, HydroResponse&> solve_parts(const HydroLoad& load) override;

 private:
  // The drag response to the flow at `rate` and, if `loaded`, the load's forces.
  void respond(const HydroLoad& load, double rate, bool loaded, HydroResponse& out) const;
  Flow flow_;
  HydroResponse out_, force_out_;
};

class PairwiseResistanceModel final : public OverdampedModel {
 public:
  PairwiseResistanceModel(const Particles& p, const Flow& flow, const ResistanceSolverParams& params);
  double pair_range() const override { return params_.lubrication.outer_cutoff; }
  HydroResponse& solve(const HydroLoad& load, double rate) override;
  std::pair<HydroResponse&, HydroResponse&> solve_parts(const HydroLoad& load) override;
  // The solver's last disturbance velocities: 6 per particle, 12 after solve_parts (the rate-driven part first).
  std::vector<double> warm_start_state() const override;
  void set_warm_start_state(const std::vector<double>& state, std::size_t n, bool parts) override;
  const ResistanceSolver& solver() const { return solver_; }

 private:
  Flow flow_;
  ResistanceSolverParams params_;
  RadiusClasses classes_;
  ResistanceSolver solver_;
  SolveResult out_, force_out_;
};

class ExplicitPairwiseModel final : public InertialModel {
 public:
  // lubrication: pairwise lubrication (else Stokes drag alone).
  ExplicitPairwiseModel(const Particles& p, const Flow& flow, bool lubrication, const ResistanceSolverParams& params);
  double pair_range() const override { return explicit_ ? lubrication_range_ : 0.0; }
  const ExplicitResponse& explicit_forces(const HydroLoad& load, double rate, const Eigen::VectorXd& dv,
                                          const std::vector<double>& mass,
                                          const std::vector<double>& moment) override;

 private:
  Flow flow_;
  double lubrication_range_ = 0.0;
  RadiusClasses classes_;
  std::optional<ExplicitHydrodynamics> explicit_;
  ExplicitHydroResult out_;
};

// Validates `params` and refuses what the pairwise models cannot do (InputError naming the key).
void check_pairwise_model(const SimulationParams& params);
// The model of a pairwise case: drag alone, lubrication solved, or explicit forces (inertial); checked first.
std::unique_ptr<HydrodynamicModel> make_pairwise_model(const Particles& p, const SimulationParams& params);

}  // namespace suspend

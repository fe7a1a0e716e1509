#include "coupling/fcm_model.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace suspend {

namespace {
coupling::KrylovParams krylov_params(const FcmParams& f) {
  coupling::KrylovParams k;
  k.tolerance = f.krylov_tolerance;
  k.max_iterations = f.max_iterations;
  k.warm_start = f.warm_start;
  k.preconditioner_cutoff = f.preconditioner_cutoff;
  k.inner_max_iterations = f.preconditioner_iterations;
  k.far_field_every = f.far_field_every;
  k.lagged_predictor = f.lagged_predictor;
  k.lagged_cutoff = f.lagged_cutoff;
  k.lagged_tolerance = f.lagged_tolerance;
  return k;
}
}  // namespace

void FcmParams::validate() const {
  if (!std::isfinite(grid_spacing)) throw InputError("fcm.grid_spacing must be finite");
  if (!(truncation_widths >= 2.0 && truncation_widths <= 10.0))
    throw InputError("fcm.truncation_widths must lie in [2, 10]");
  krylov_params(*this).validate();
  coupling::SubgridParams{subgrid_cutoff, subgrid_taper_start, subgrid_model_taper_start}.validate();
  if (!(table_spacing > 0.0 && table_spacing <= 0.25)) throw InputError("fcm.table_spacing must lie in (0, 0.25]");
}

FcmModel::FcmModel(const Particles& p, const Box& box, const SimulationParams& params, const FcmParams& fcm)
    : fcm_(fcm), flow_(params.flow), classes_(p.radius) {
  check(params, fcm);
  if (p.size() == 0) throw InputError("fcm: no particles");
  const double a_min = classes_.radius.front();
  // Grid: whole cells per side, spacing as close to h as possible.
  const double h = fcm_.grid_spacing > 0.0 ? fcm_.grid_spacing : 0.5 * a_min;
  std::array<int, 3> grid{};
  for (int d = 0; d < 3; ++d) grid[d] = std::max(8, static_cast<int>(std::lround(box.length()[d] / h)));
  fcm::SolverOptions so;
  so.truncation_widths = fcm_.truncation_widths;
  mobility_.emplace(box.length(), grid, so, krylov_params(fcm_));
  if (fcm_.subgrid) {
    coupling::FcmPairTableParams tp;
    tp.grid_spacing = box.length().x() / grid[0];
    tp.truncation_widths = fcm_.truncation_widths;
    tp.ds = fcm_.table_spacing;
    subgrid_.emplace(classes_.radius,
                     coupling::SubgridParams{fcm_.subgrid_cutoff, fcm_.subgrid_taper_start,
                                             fcm_.subgrid_model_taper_start},
                     params.resistance.lubrication, tp, fcm_.cache_dir);
  }
}

void FcmModel::check(const SimulationParams& params, const FcmParams& fcm) {
  params.validate();
  if (params.time_step.implicit_contacts && !fcm.subgrid)
    throw InputError("run.time_step.contacts = implicit needs hydrodynamics.fcm.subgrid = true");
  if (params.flow.wave_amplitude != 0.0)
    throw InputError("flow.type = wavy is not available with hydrodynamics.model = fcm (use simple_shear, "
                     "oscillatory or reversal)");
  if (params.integrator != Integrator::overdamped)
    throw InputError("run.integrator = inertial is not available with hydrodynamics.model = fcm (use overdamped)");
  fcm.validate();
}

coupling::CoupledProblem FcmModel::assemble(const HydroLoad& load, double rate) {
  const Particles& p = load.particles;
  const double t0 = omp_get_wtime();
  if (subgrid_) {
    subgrid_->assemble(load.pairs, classes_.of_particle);
    if (load.implicit.enabled())
      subgrid_->add_contact_steps(load.pairs, *load.implicit.stiffness, load.implicit.dt, p.position,
                                  flow_.ambient(1.0, load.box.length().y()));
  }
  subgrid_seconds_ += omp_get_wtime() - t0;
  coupling::CoupledProblem pb{p.position, p.radius, load.force, load.torque, flow_.ambient(rate, load.box.length().y()),
                              load.box.shear_offset()};
  // Full solves at multiples of far_field_every (by step number, so a restart keeps the schedule). The lagged far
  // field holds for the rate of its full solve: an imposed rate that changed since the last step (oscillation,
  // reversal) refreshes it. Stress control solves unit-rate and force parts, which do not depend on it.
  pb.refresh_far_field = fcm_.far_field_every <= 1 || load.step % fcm_.far_field_every == 0 || load.rate_changed;
  return pb;
}

void FcmModel::respond(const coupling::CoupledResult& r, const std::vector<ActivePair>& pairs,
                       HydroResponse& out) const {
  out.velocity = r.velocities;
  out.angular_velocity = r.angular_velocities;
  out.stress = {};
  Mat3& stresslets = out.stress[Contribution::hydrodynamic];
  for (const Mat3& s : r.stresslets) stresslets += s;
  out.stress[Contribution::lubrication] = r.subgrid_stress;
  out.contact_change_on_j = r.contact_change_on_j;
  for (std::size_t k = 0; k < r.contact_change_on_j.size(); ++k)
    add_contact_change_virial(pairs[k].geometry(), r.contact_change_on_j[k], out.stress);
  out.iterations = r.iterations;
  out.residual = r.residual;
}

HydroResponse& FcmModel::solve(const HydroLoad& load, double rate) {
  const coupling::CoupledProblem pb = assemble(load, rate);
  try {
    mobility_->solve(pb, subgrid_ ? &*subgrid_ : nullptr, result_);
  } catch (const NumericalError& e) {
    throw NumericalError("numerical failure at " + load.where + ": " + e.what());
  }
  stokes_solves_ = result_.stokes_solves;
  ++evaluated_steps_;
  total_stokes_solves_ += stokes_solves_;
  respond(result_, load.pairs, out_);
  return out_;
}

std::pair<HydroResponse&, HydroResponse&> FcmModel::solve_parts(const HydroLoad& load) {
  const coupling::CoupledProblem pb = assemble(load, 0.0);
  try {
    mobility_->solve_parts(pb, subgrid_ ? &*subgrid_ : nullptr, result_, force_result_);
  } catch (const NumericalError& e) {
    throw NumericalError("numerical failure at " + load.where + ": " + e.what());
  }
  stokes_solves_ = result_.stokes_solves + force_result_.stokes_solves;
  ++evaluated_steps_;
  total_stokes_solves_ += stokes_solves_;
  respond(result_, load.pairs, out_);
  respond(force_result_, load.pairs, force_out_);
  return {out_, force_out_};
}

Simulation fcm_simulation(SimulationState state, const Box& box, const SimulationParams& params,
                          const FcmParams& fcm) {
  auto model = std::make_unique<FcmModel>(state.particles, box, params, fcm);
  return Simulation(std::move(state), box, params, std::move(model));
}

FcmModel& fcm_model(Simulation& sim) { return dynamic_cast<FcmModel&>(sim.model()); }
const FcmModel& fcm_model(const Simulation& sim) { return dynamic_cast<const FcmModel&>(sim.model()); }

}  // namespace suspend

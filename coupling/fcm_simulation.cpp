#include "coupling/fcm_simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.hpp"

namespace suspend {

using std::numbers::pi;

namespace {
coupling::KrylovParams krylov_params(const FcmParams& f) {
  coupling::KrylovParams k;
  k.tolerance = f.krylov_tolerance;
  k.max_iterations = f.max_iterations;
  k.warm_start = f.warm_start;
  k.preconditioner_cutoff = f.preconditioner_cutoff;
  k.far_field_every = f.far_field_every;
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

FcmSimulation::FcmSimulation(SimulationState state, const Box& box, const SimulationParams& params,
                             const FcmParams& fcm)
    : state_(std::move(state)), box_(box), params_(params), fcm_(fcm) {
  suspend::validate(params_.contact);
  params_.time_step.validate();
  if (!(params_.max_overlap > 0.0)) throw InputError("run.max_overlap must be > 0");
  fcm_.validate();
  box_.set_strain(state_.strain);
  const Particles& p = state_.particles;
  if (p.size() == 0) throw InputError("fcm: no particles");
  a_min_ = *std::min_element(p.radius.begin(), p.radius.end());
  species_radius_ = p.radius;
  std::sort(species_radius_.begin(), species_radius_.end());
  species_radius_.erase(std::unique(species_radius_.begin(), species_radius_.end()), species_radius_.end());
  species_.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    species_[i] = static_cast<int>(std::lower_bound(species_radius_.begin(), species_radius_.end(), p.radius[i]) -
                                   species_radius_.begin());

  // Grid: whole cells per side, spacing as close to h as possible.
  const double h = fcm_.grid_spacing > 0.0 ? fcm_.grid_spacing : 0.5 * a_min_;
  std::array<int, 3> grid{};
  for (int d = 0; d < 3; ++d) grid[d] = std::max(8, static_cast<int>(std::lround(box_.length()[d] / h)));
  fcm::SolverOptions so;
  so.truncation_widths = fcm_.truncation_widths;
  mobility_.emplace(box_.length(), grid, so,
                    krylov_params(fcm_));
  if (fcm_.subgrid) {
    coupling::FcmPairTableParams tp;
    tp.grid_spacing = box_.length().x() / grid[0];
    tp.truncation_widths = fcm_.truncation_widths;
    tp.ds = fcm_.table_spacing;
    subgrid_.emplace(species_radius_,
                     coupling::SubgridParams{fcm_.subgrid_cutoff, fcm_.subgrid_taper_start,
                                             fcm_.subgrid_model_taper_start},
                     params_.resistance.lubrication, tp, fcm_.cache_dir);
  }
  if (params_.time_step.implicit_contacts && !subgrid_)
    throw InputError("run.time_step.contacts = implicit needs hydrodynamics.fcm.subgrid = true");
  if (params_.integrator != Integrator::overdamped)
    throw InputError("hydrodynamics.model = fcm needs run.integrator = overdamped");
  params_.flow.validate();
  if (params_.flow.wave_amplitude != 0.0)
    throw InputError("hydrodynamics.model = fcm needs a simple shear (flow.type = wavy is pairwise only)");
  if (params_.flow.control == FlowControl::rate || state_.shear_rate == 0.0)
    state_.shear_rate = params_.flow.control == FlowControl::rate
                            ? params_.flow.rate(state_.time, state_.accumulated_strain)
                            : params_.flow.shear_rate;
  rate_ = state_.shear_rate;
  contacts_ = ContactStage(std::max(interaction_range(params_.contact), subgrid_ ? subgrid_->range() : 0.0),
                           params_.skin, p, state_.contacts);
  state_.contacts.clear();
  mobility_->set_warm_start_state(state_.warm_start, p.size(), params_.flow.control == FlowControl::stress);
  state_.warm_start.clear();
}

SimulationState FcmSimulation::state_with_contacts() const {
  SimulationState s = state_;
  s.contacts = contacts_.histories();
  s.warm_start = mobility_->warm_start_state();
  return s;
}

void FcmSimulation::fail(const std::string& what) const {
  std::ostringstream s;
  s << "numerical failure at step " << state_.step << ", strain " << state_.strain << ": " << what;
  throw NumericalError(s.str());
}

void FcmSimulation::evaluate() {
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  const TimeStepParams& ts = params_.time_step;
  double t0 = omp_get_wtime();
  // Contacts see the image velocity of the last step's rate (their velocities are that step's).
  const auto overlap = contacts_.evaluate(p, box_, state_.shear_rate * box_.length().y(), params_.contact,
                                          state_.last_dt, ts.implicit_contacts, params_.max_overlap * a_min_);
  contact_seconds_ += omp_get_wtime() - t0;
  if (overlap) fail(*overlap);
  const PairSums& sums = contacts_.sums();
  const std::vector<ActivePair>& pairs = contacts_.pairs();
  // Implicit contacts: the step precedes the solve (time_step_control.hpp), from the last step's speeds and this
  // step's contacts.
  if (ts.implicit_contacts)
    dt_ = overdamped_time_step(ts, params_.contact, state_.shear_rate,
                               max_nonaffine_speed(p, hydro::WavyShear{state_.shear_rate, 0.0, 0, box_.length().y()}),
                               a_min_, state_.last_dt, sums.mean_compliance());
  if (ts.implicit_contacts) dt_ = std::min(dt_, params_.flow.max_time_step());

  t0 = omp_get_wtime();
  if (subgrid_) {
    subgrid_->assemble(pairs, species_);
    if (ts.implicit_contacts)
      subgrid_->add_contact_steps(pairs, contacts_.stiffness(), dt_, p.position, box_.length().y());
  }
  subgrid_seconds_ += omp_get_wtime() - t0;
  solve_velocities();
  ++evaluated_steps_;
  total_stokes_solves_ += result_.stokes_solves;
  double max_speed = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    p.velocity[i] = result_.velocities[i];
    p.angular_velocity[i] = result_.angular_velocities[i];
    max_speed = std::max(max_speed, (p.velocity[i] - ambient_velocity(p.position[i])).norm());
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!p.velocity[i].allFinite() || !p.angular_velocity[i].allFinite()) {
      std::ostringstream s;
      s << "non-finite velocity of particle " << i << " (contact force " << sums.force[i].transpose() << ")";
      fail(s.str());
    }

  const double volume = box_.volume();
  stress_ = sums.virial;
  for (std::size_t k = 0; k < result_.contact_change_on_j.size(); ++k) {
    add_contact_change_virial(pairs[k].geometry, result_.contact_change_on_j[k], stress_);
    contacts_.add_contact_change(k, result_.contact_change_on_j[k]);
  }
  for (auto& m : stress_.part) m /= volume;
  fcm::MobilityResult fcm_part;
  fcm_part.stresslets = result_.stresslets;
  stress_[Contribution::hydrodynamic] = mobility_->solver().bulk_stress(fcm_part, rate_);
  stress_[Contribution::lubrication] = result_.subgrid_stress / volume;

  if (!ts.implicit_contacts) dt_ = overdamped_time_step(ts, params_.contact, rate_, max_speed, a_min_, state_.last_dt);
  dt_ = std::min(dt_, params_.flow.max_time_step());
  evaluated_ = true;
}

double FcmSimulation::hydrodynamic_shear_stress(const coupling::CoupledResult& r, double rate) const {
  fcm::MobilityResult fcm_part;
  fcm_part.stresslets = r.stresslets;
  StressTensors changes;
  for (std::size_t k = 0; k < r.contact_change_on_j.size(); ++k)
    add_contact_change_virial(contacts_.pairs()[k].geometry, r.contact_change_on_j[k], changes);
  return mobility_->solver().bulk_stress(fcm_part, rate)(0, 1) * box_.volume() + r.subgrid_stress(0, 1) +
         changes.total()(0, 1);
}

void FcmSimulation::solve_velocities() {
  const Particles& p = state_.particles;
  const std::size_t n = p.size();
  const PairSums& sums = contacts_.sums();
  coupling::CoupledProblem pb{p.position, p.radius, sums.force, sums.torque, rate_, box_.shear_offset()};
  // Full solves at multiples of far_field_every (by step number, so a restart keeps the schedule).
  pb.refresh_far_field = fcm_.far_field_every <= 1 || state_.step % fcm_.far_field_every == 0;
  // The lagged far field holds for the rate of its full solve: an imposed rate that changed since the last step
  // (oscillation, reversal) refreshes it. Stress control solves unit-rate and force parts, which do not depend on it.
  if (params_.flow.control == FlowControl::rate && params_.flow.rate(state_.time, state_.accumulated_strain) !=
                                                       state_.shear_rate)
    pb.refresh_far_field = true;
  try {
    if (params_.flow.control == FlowControl::rate) {
      pb.shear_rate = rate_ = params_.flow.rate(state_.time, state_.accumulated_strain);
      mobility_->solve(pb, subgrid_ ? &*subgrid_ : nullptr, result_);
      return;
    }
    mobility_->solve_parts(pb, subgrid_ ? &*subgrid_ : nullptr, result_, force_result_);
  } catch (const NumericalError& e) {
    fail(e.what());
  }
  // Sigma_xy V = gammadot (shear part, which includes 2 E_inf V) + force part + the contacts' virial.
  const double sigma_h = hydrodynamic_shear_stress(result_, 1.0);
  const double sigma_c = hydrodynamic_shear_stress(force_result_, 0.0) + sums.virial.total()(0, 1);
  rate_ = (params_.flow.stress(state_.time, state_.accumulated_strain) * box_.volume() - sigma_c) / sigma_h;
  if (!std::isfinite(rate_)) fail("the stress control gave a non-finite shear rate");
  for (std::size_t i = 0; i < n; ++i) {
    result_.velocities[i] = rate_ * result_.velocities[i] + force_result_.velocities[i];
    result_.angular_velocities[i] = rate_ * result_.angular_velocities[i] + force_result_.angular_velocities[i];
    result_.stresslets[i] = rate_ * result_.stresslets[i] + force_result_.stresslets[i];
  }
  result_.subgrid_stress = rate_ * result_.subgrid_stress + force_result_.subgrid_stress;
  for (std::size_t k = 0; k < result_.contact_change_on_j.size(); ++k)
    result_.contact_change_on_j[k] = rate_ * result_.contact_change_on_j[k] + force_result_.contact_change_on_j[k];
  result_.iterations += force_result_.iterations;
  result_.stokes_solves += force_result_.stokes_solves;
  result_.residual = std::max(result_.residual, force_result_.residual);
}

void FcmSimulation::advance() {
  if (!evaluated_) evaluate();
  contacts_.store_histories();
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  nonaffine_.resize(n);
  const double ly = box_.length().y();
  for (std::size_t i = 0; i < n; ++i) {
    nonaffine_[i] = (p.velocity[i] - ambient_velocity(p.position[i])) * dt_;
    p.position[i] += p.velocity[i] * dt_;
  }
  const double dstrain = rate_ * dt_;
  state_.strain += dstrain;
  state_.accumulated_strain += std::abs(dstrain);
  state_.time += dt_;
  state_.last_dt = dt_;
  state_.shear_rate = rate_;
  ++state_.step;
  box_.set_strain(state_.strain);
  for (std::size_t i = 0; i < n; ++i) {
    const int crossings = box_.wrap(p.position[i]);
    p.velocity[i].x() -= crossings * rate_ * ly;  // paper 000, eq. 16d
  }
  contacts_.record_motion(nonaffine_, std::abs(dstrain));
  evaluated_ = false;
}

}  // namespace suspend

#include "dem/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/error.hpp"
#include "dem/integrate/pair_motion.hpp"
#include "dem/integrate/pairwise_models.hpp"

namespace suspend {

void SimulationParams::validate() const {
  suspend::validate(contact);
  if (lubrication) resistance.validate();
  time_step.validate();
  if (!(max_overlap > 0.0)) throw InputError("run.max_overlap must be > 0");
  flow.validate();
  if (flow.control == FlowControl::stress) {
    if (integrator != Integrator::overdamped)
      throw InputError("flow.control = stress needs run.integrator = overdamped (the rate follows from the "
                       "instantaneous force balance)");
    if (flow.wave_amplitude != 0.0)
      throw InputError("flow.control = stress is available for simple shear only (flow.type = simple_shear)");
  }
  if (integrator == Integrator::inertial && !(stokes_number > 0.0 && std::isfinite(stokes_number)))
    throw InputError("run.stokes_number must be > 0 for run.integrator = inertial");
  if (time_step.implicit_contacts && integrator != Integrator::overdamped)
    throw InputError("run.time_step.contacts = implicit needs run.integrator = overdamped");
}

Simulation::Simulation(SimulationState state, const Box& box, const SimulationParams& params)
    : Simulation(std::move(state), box, params, nullptr) {}

Simulation::Simulation(SimulationState state, const Box& box, const SimulationParams& params,
                       std::unique_ptr<HydrodynamicModel> model)
    : state_(std::move(state)), box_(box), params_(params),
      model_(model ? std::move(model) : make_pairwise_model(state_.particles, params)),
      contacts_(std::max(interaction_range(params.contact), model_->pair_range()), params.skin, state_.particles,
                state_.contacts) {
  params_.validate();
  const bool inertial = params_.integrator == Integrator::inertial;
  // The integrator asks the model for the one interface it uses.
  auto* inertial_model = inertial ? dynamic_cast<InertialModel*>(model_.get()) : nullptr;
  if (!inertial) overdamped_ = dynamic_cast<OverdampedModel*>(model_.get());
  if (inertial ? !inertial_model : !overdamped_)
    throw InputError(inertial ? "run.integrator = inertial: this hydrodynamic model is overdamped only"
                              : "this hydrodynamic model needs run.integrator = inertial");
  box_.set_strain(state_.strain);
  const Particles& p = state_.particles;
  const std::size_t n = p.size();
  a_min_ = *std::min_element(p.radius.begin(), p.radius.end());
  state_.contacts.clear();
  if (params_.flow.control == FlowControl::rate || state_.shear_rate == 0.0)
    state_.shear_rate = params_.flow.control == FlowControl::rate
                            ? params_.flow.rate(state_.time, state_.accumulated_strain)
                            : params_.flow.shear_rate;
  rate_ = state_.shear_rate;
  model_->set_warm_start_state(state_.warm_start, n, params_.flow.control == FlowControl::stress);
  state_.warm_start.clear();
  if (inertial) verlet_.emplace(*inertial_model, p, params_.stokes_number, state_.verlet, flow(rate_));
  state_.verlet.clear();  // the integrator's now (state_with_contacts gives it back)
}

SimulationState Simulation::state_with_contacts() const {
  SimulationState s = state_;
  s.contacts = contacts_.histories();
  s.warm_start = model_->warm_start_state();
  if (verlet_) s.verlet = verlet_->saved();
  return s;
}

void Simulation::fail(const std::string& what) const {
  std::ostringstream s;
  s << "numerical failure at step " << state_.step << ", strain " << state_.strain << ": " << what;
  throw NumericalError(s.str());
}

HydroLoad Simulation::load(const ImplicitContacts& implicit) const {
  std::ostringstream where;
  where << "step " << state_.step << ", strain " << state_.strain;
  const PairSums& sums = contacts_.sums();
  // A model that keeps anything per rate (the FCM lagged far field) must know when the imposed rate changed.
  const bool rate_changed = params_.flow.control == FlowControl::rate && rate_ != state_.shear_rate;
  return {state_.particles, contacts_.pairs(), sums.force, sums.torque, box_, implicit, state_.step, rate_changed,
          where.str()};
}

double Simulation::overdamped_velocities(const HydroLoad& load) {
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  const HydroResponse* response = nullptr;
  if (params_.flow.control == FlowControl::rate) {
    response = &overdamped_->solve(load, rate_);
  } else {
    // Sigma_xy = gammadot Sigma_H + Sigma_C from the unit-rate and the force-driven parts; the rate that meets the
    // target combines them.
    auto [shear, forced] = overdamped_->solve_parts(load);
    const double volume = box_.volume();
    const double sigma_h = 1.0 + shear.stress.total()(0, 1) / volume;
    const double sigma_c = (contacts_.sums().virial.total()(0, 1) + forced.stress.total()(0, 1)) / volume;
    rate_ = (params_.flow.stress(state_.time, state_.accumulated_strain) - sigma_c) / sigma_h;
    shear.combine(rate_, forced);
    response = &shear;
  }
  iterations_ = response->iterations;
  residual_ = response->residual;
  for (std::size_t i = 0; i < n; ++i) {
    p.velocity[i] = response->velocity[i];
    p.angular_velocity[i] = response->angular_velocity[i];
  }
  finish_stress(response->stress);
  contact_change_ = &response->contact_change_on_j;
  return nonaffine_bounding_speed(p, flow(rate_), params_.time_step.fastest_of, speeds_);
}

double Simulation::inertial_velocities(const HydroLoad& load) {
  const ExplicitResponse& hydro = verlet_->velocities(load, rate_, flow(rate_), state_.last_dt, state_.particles);
  iterations_ = 0;
  residual_ = 0.0;
  finish_stress(hydro.stress);
  contact_change_ = nullptr;
  return nonaffine_bounding_speed(state_.particles, flow(rate_), params_.time_step.fastest_of, speeds_);
}

void Simulation::finish_stress(const StressTensors& hydrodynamic) {
  // Contact virial + the model's sums (hydrodynamic, lubrication; with implicit contacts the contacts' change over
  // the step, whose forces evaluate() adds to the contact records once the step's solve is final).
  stress_ = contacts_.sums().virial;
  for (std::size_t c = 0; c < contribution_count; ++c) stress_.part[c] += hydrodynamic.part[c];
  for (auto& m : stress_.part) m /= box_.volume();
  // The fluid's 2 eta <E_inf>: the wave averages to zero over whole periods.
  stress_[Contribution::hydrodynamic] += flow(rate_).ambient_stress();
}

PairBound Simulation::pair_rate(double rate) const {
  const TimeStepParams& ts = params_.time_step;
  if (ts.mode == TimeStepParams::Mode::fixed || ts.bound != TimeStepParams::Bound::pairs) return {};
  const PairMotionLimits limits{contact_displacement(ts, params_.contact, contacts_.sums().mean_compliance()),
                                ts.max_displacement, contact_range(params_.contact), ts.gap_change};
  PairBound bound;
  bound.rate = pair_motion_rate(contacts_.pairs(), state_.particles, rate * box_.length().y(), contacts_.records(),
                                limits, bound_rank(state_.particles.size(), ts.fastest_of), &pair_rates_, &bound.limit);
  return bound;
}

StepBound Simulation::next_time_step(double max_speed) const {
  // Fixed, or bounded strain increment, non-affine displacement and the fastest contact or hydrodynamic time
  // scale (overdamped: drag relaxation 6 pi a / k; inertial: sqrt(m / k) and m / R). Implicit contacts: the step
  // chosen before the solve.
  const TimeStepParams& ts = params_.time_step;
  StepBound step = step_;
  if (ts.mode == TimeStepParams::Mode::fixed) {
    step = {ts.fixed, StepLimit::fixed};
  } else if (verlet_) {
    step = {std::abs(rate_) > 0.0 ? ts.max / std::abs(rate_) : ts.max, StepLimit::strain};
    if (max_speed > 0.0) step.at_most(ts.max_displacement / max_speed, StepLimit::particles);
    step.at_most(verlet_->stability_time_step(stiffness_scale(params_.contact), ts.stability),
                 StepLimit::contact_stiffness);
  } else if (!ts.implicit_contacts) {
    step.dt = overdamped_time_step(ts, params_.contact, rate_, max_speed, a_min_, state_.last_dt, 0.0,
                                   pair_rate(rate_), &step.limit);
  }
  step.at_most(params_.flow.max_time_step(state_.time), StepLimit::flow);
  return step;
}

void Simulation::evaluate() {
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  if (verlet_) verlet_->set_contact_velocities(p);  // the contact laws see the half-step velocities (eq. 15c)
  // 1. Contacts, with the image velocity of the last step's rate (their velocities are that step's).
  const double t0 = omp_get_wtime();
  const auto overlap = contacts_.evaluate(p, box_, state_.shear_rate * box_.length().y(), params_.contact,
                                          state_.last_dt, params_.time_step.implicit_contacts,
                                          params_.max_overlap * a_min_);
  contact_seconds_ += omp_get_wtime() - t0;
  if (overlap) fail(*overlap);
  // 2. Implicit contacts: the step precedes the solve (time_step_control.hpp), from the last step's speeds and
  // this step's contacts.
  ImplicitContacts implicit;
  if (params_.time_step.implicit_contacts) {
    step_.dt = overdamped_time_step(
        params_.time_step, params_.contact, state_.shear_rate,
        nonaffine_bounding_speed(p, flow(state_.shear_rate), params_.time_step.fastest_of, speeds_), a_min_,
        state_.last_dt, contacts_.sums().mean_compliance(), pair_rate(state_.shear_rate), &step_.limit);
    step_.at_most(params_.flow.max_time_step(state_.time), StepLimit::flow);
    implicit = {&contacts_.stiffness(), step_.dt};
  }
  // 3-4. Hydrodynamics and flow control (imposed rate now; imposed stress inside, from the model's two parts),
  // then the stress.
  rate_ = params_.flow.control == FlowControl::rate ? params_.flow.rate(state_.time, state_.accumulated_strain)
                                                    : state_.shear_rate;
  double max_speed = verlet_ ? inertial_velocities(load(implicit)) : overdamped_velocities(load(implicit));
  // Implicit contacts: the step was chosen from the last step's motion. When this step's own motion needs a much
  // shorter one (the rate under imposed stress jumps as a force chain lets go, a contact opens), solve again with it.
  const TimeStepParams& ts = params_.time_step;
  for (int again = 0; implicit.enabled() && ts.mode == TimeStepParams::Mode::adaptive && again < 4; ++again) {
    StepBound needed;
    needed.dt =
        overdamped_time_step(ts, params_.contact, rate_, max_speed, a_min_, std::numeric_limits<double>::infinity(),
                             contacts_.sums().mean_compliance(), pair_rate(rate_), &needed.limit);
    needed.at_most(params_.flow.max_time_step(state_.time), StepLimit::flow);
    if (!(step_.dt > step_overshoot * needed.dt)) break;
    step_ = needed;
    implicit.dt = step_.dt;
    max_speed = overdamped_velocities(load(implicit));
  }
  if (contact_change_)
    for (std::size_t k = 0; k < contact_change_->size(); ++k) contacts_.add_contact_change(k, (*contact_change_)[k]);
  // 5. Checks.
  if (!std::isfinite(rate_)) fail("the stress control gave a non-finite shear rate");
  for (std::size_t i = 0; i < n; ++i)
    if (!p.velocity[i].allFinite() || !p.angular_velocity[i].allFinite()) {
      std::ostringstream s;
      s << "non-finite velocity of particle " << i << " (contact force " << contacts_.sums().force[i].transpose()
        << ")";
      fail(s.str());
    }
  // 6. Time step.
  step_ = next_time_step(max_speed);
  evaluated_ = true;
}

void Simulation::advance() {
  if (!evaluated_) evaluate();
  contacts_.store_histories();
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  nonaffine_.resize(n);
  const double ly = box_.length().y();
  for (std::size_t i = 0; i < n; ++i) {
    // Inertial: x^{n+2} = x^{n+1} + dt u^{n+3/2} (eqs. 15a-b).
    const Vec3 u = verlet_ ? verlet_->half_step(i, p, step_.dt) : p.velocity[i];
    // Drift against the affine simple shear (the list accounts for that); a wave counts as drift.
    nonaffine_[i] = (u - Vec3(rate_ * p.position[i].y(), 0.0, 0.0)) * step_.dt;
    p.position[i] += u * step_.dt;
  }
  const double dstrain = rate_ * step_.dt;
  state_.strain += dstrain;
  state_.accumulated_strain += std::abs(dstrain);
  state_.time += step_.dt;
  state_.last_dt = step_.dt;
  state_.shear_rate = rate_;
  ++state_.step;
  step_limits_.add(step_.limit);
  box_.set_strain(state_.strain);
  for (std::size_t i = 0; i < n; ++i) {
    const int crossings = box_.wrap(p.position[i]);
    p.velocity[i].x() -= crossings * rate_ * ly;  // paper 000, eq. 16d
    if (verlet_) verlet_->subtract_velocity_x(i, crossings * rate_ * ly);
  }
  contacts_.record_motion(nonaffine_, std::abs(dstrain));
  evaluated_ = false;
}

}  // namespace suspend

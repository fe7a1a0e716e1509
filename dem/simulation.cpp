#include "dem/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/error.hpp"
#include "dem/hydro/stokes_drag.hpp"
#include "dem/integrate/pair_motion.hpp"
#include "dem/integrate/pairwise_models.hpp"

namespace suspend {

using std::numbers::pi;

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
  if (inertial)
    inertial_ = dynamic_cast<InertialModel*>(model_.get());
  else
    overdamped_ = dynamic_cast<OverdampedModel*>(model_.get());
  if (inertial ? !inertial_ : !overdamped_)
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
  if (inertial) {
    mass_.resize(n);
    moment_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double a = p.radius[i];
      mass_[i] = params_.stokes_number * (4.0 / 3.0) * pi * a * a * a;
      moment_[i] = 0.4 * mass_[i] * a * a;
    }
    if (state_.verlet.empty()) {
      // Start from rest relative to the imposed flow with zero acceleration: with last_dt = 0 the first
      // evaluation gives u^0 = U_inf and a^0 = F(x^0, U_inf) / m, as eq. 15 needs.
      const hydro::WavyShear f = flow(rate_);
      state_.verlet.assign(12 * n, 0.0);
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 u = hydro::faxen_velocity(p.radius[i], p.position[i], f), w = f.angular_velocity(p.position[i]);
        for (int k = 0; k < 3; ++k) state_.verlet[12 * i + k] = u[k], state_.verlet[12 * i + 3 + k] = w[k];
      }
    } else if (state_.verlet.size() != 12 * n) {
      throw InputError("inertial state: 12 numbers per particle expected, got " + std::to_string(state_.verlet.size()));
    }
  }
}

SimulationState Simulation::state_with_contacts() const {
  SimulationState s = state_;
  s.contacts = contacts_.histories();
  s.warm_start = model_->warm_start_state();
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
  double max_speed = 0.0;
  const hydro::WavyShear f = flow(rate_);
  for (std::size_t i = 0; i < n; ++i) {
    p.velocity[i] = response->velocity[i];
    p.angular_velocity[i] = response->angular_velocity[i];
    max_speed = std::max(max_speed, (p.velocity[i] - f.velocity(p.position[i])).norm());
  }
  finish_stress(response->stress);
  contact_change_ = &response->contact_change_on_j;
  return max_speed;
}

double Simulation::inertial_velocities(const HydroLoad& load) {
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  const hydro::WavyShear f = flow(rate_);
  const std::vector<double>& v = state_.verlet;
  // Hydrodynamic force and torque at the half-step velocities (explicit, paper 000 eq. 15c).
  disturbance_.resize(6 * static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      disturbance_[6 * i + k] = v[12 * i + k] - f.velocity(p.position[i])[k];
      disturbance_[6 * i + 3 + k] = v[12 * i + 3 + k] - f.angular_velocity(p.position[i])[k];
    }
  const ExplicitResponse& hydro = inertial_->explicit_forces(load, rate_, disturbance_, mass_, moment_);
  relaxation_rate_ = hydro.relaxation_rate;
  iterations_ = 0;
  residual_ = 0.0;
  acceleration_.resize(6 * n);
  double max_speed = 0.0;
  const double half = 0.5 * state_.last_dt;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a_lin = (contacts_.sums().force[i] + hydro.force.segment<3>(6 * i)) / mass_[i];
    const Vec3 a_ang = (contacts_.sums().torque[i] + hydro.force.segment<3>(6 * i + 3)) / moment_[i];
    for (int k = 0; k < 3; ++k) acceleration_[6 * i + k] = a_lin[k], acceleration_[6 * i + 3 + k] = a_ang[k];
    p.velocity[i] = Vec3(v[12 * i], v[12 * i + 1], v[12 * i + 2]) + half * a_lin;  // eq. 15d
    p.angular_velocity[i] = Vec3(v[12 * i + 3], v[12 * i + 4], v[12 * i + 5]) + half * a_ang;
    max_speed = std::max(max_speed, (p.velocity[i] - f.velocity(p.position[i])).norm());
  }
  finish_stress(hydro.stress);
  contact_change_ = nullptr;
  return max_speed;
}

void Simulation::finish_stress(const StressTensors& hydrodynamic) {
  // Contact virial + the model's sums (hydrodynamic, lubrication; with implicit contacts the contacts' change over
  // the step, whose forces evaluate() adds to the contact records once the step's solve is final).
  stress_ = contacts_.sums().virial;
  for (std::size_t c = 0; c < contribution_count; ++c) stress_.part[c] += hydrodynamic.part[c];
  for (auto& m : stress_.part) m /= box_.volume();
  // The fluid's 2 eta <E_inf>: the wave averages to zero over whole periods.
  stress_[Contribution::hydrodynamic](0, 1) += rate_;
  stress_[Contribution::hydrodynamic](1, 0) += rate_;
}

double Simulation::pair_rate(double rate) const {
  const TimeStepParams& ts = params_.time_step;
  if (ts.mode == TimeStepParams::Mode::fixed || ts.bound != TimeStepParams::Bound::pairs) return 0.0;
  const PairMotionLimits limits{contact_displacement(ts, params_.contact, contacts_.sums().mean_compliance()),
                                ts.max_displacement, contact_range(params_.contact), ts.gap_change};
  return pair_motion_rate(contacts_.pairs(), state_.particles, rate * box_.length().y(), contacts_.records(), limits);
}

double Simulation::next_time_step(double max_speed) const {
  // Fixed, or bounded strain increment, non-affine displacement and the fastest contact or hydrodynamic time
  // scale (overdamped: drag relaxation 6 pi a / k; inertial: sqrt(m / k) and m / R).
  const TimeStepParams& ts = params_.time_step;
  double dt = dt_;
  if (ts.mode == TimeStepParams::Mode::fixed) {
    dt = ts.fixed;
  } else if (params_.integrator == Integrator::inertial) {
    const double k = stiffness_scale(params_.contact);
    dt = std::abs(rate_) > 0.0 ? ts.max / std::abs(rate_) : ts.max;
    if (max_speed > 0.0) dt = std::min(dt, ts.max_displacement / max_speed);
    const double m_min = *std::min_element(mass_.begin(), mass_.end());
    dt = std::min(dt, ts.stability * std::sqrt(m_min / k));
    if (relaxation_rate_ > 0.0) dt = std::min(dt, ts.stability / relaxation_rate_);
  } else if (!ts.implicit_contacts) {
    dt = overdamped_time_step(ts, params_.contact, rate_, max_speed, a_min_, state_.last_dt, 0.0, pair_rate(rate_));
  }
  return std::min(dt, params_.flow.max_time_step());
}

void Simulation::evaluate() {
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  const bool inertial = params_.integrator == Integrator::inertial;
  if (inertial)  // the contact laws see the half-step velocities (eq. 15c)
    for (std::size_t i = 0; i < n; ++i) {
      const double* v = state_.verlet.data() + 12 * i;
      p.velocity[i] = Vec3(v[0], v[1], v[2]);
      p.angular_velocity[i] = Vec3(v[3], v[4], v[5]);
    }
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
    dt_ = overdamped_time_step(params_.time_step, params_.contact, state_.shear_rate,
                               max_nonaffine_speed(p, flow(state_.shear_rate)), a_min_, state_.last_dt,
                               contacts_.sums().mean_compliance(), pair_rate(state_.shear_rate));
    dt_ = std::min(dt_, params_.flow.max_time_step());
    implicit = {&contacts_.stiffness(), dt_};
  }
  // 3-4. Hydrodynamics and flow control (imposed rate now; imposed stress inside, from the model's two parts),
  // then the stress.
  rate_ = params_.flow.control == FlowControl::rate ? params_.flow.rate(state_.time, state_.accumulated_strain)
                                                    : state_.shear_rate;
  double max_speed = inertial ? inertial_velocities(load(implicit)) : overdamped_velocities(load(implicit));
  // Implicit contacts: the step was chosen from the last step's motion. When this step's own motion needs a much
  // shorter one (the rate under imposed stress jumps as a force chain lets go, a contact opens), solve again with it.
  const TimeStepParams& ts = params_.time_step;
  for (int again = 0; implicit.enabled() && ts.mode == TimeStepParams::Mode::adaptive && again < 4; ++again) {
    const double needed = std::min(
        overdamped_time_step(ts, params_.contact, rate_, max_speed, a_min_, std::numeric_limits<double>::infinity(),
                             contacts_.sums().mean_compliance(), pair_rate(rate_)),
        params_.flow.max_time_step());
    if (!(dt_ > step_overshoot * needed)) break;
    dt_ = needed;
    implicit.dt = dt_;
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
  dt_ = next_time_step(max_speed);
  evaluated_ = true;
}

void Simulation::advance() {
  if (!evaluated_) evaluate();
  contacts_.store_histories();
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  const bool inertial = params_.integrator == Integrator::inertial;
  nonaffine_.resize(n);
  const double ly = box_.length().y();
  for (std::size_t i = 0; i < n; ++i) {
    Vec3 u = p.velocity[i];
    if (inertial) {  // u^{n+3/2} = u^{n+1} + (dt/2) a^{n+1}; x^{n+2} = x^{n+1} + dt u^{n+3/2} (eqs. 15a-b)
      double* v = state_.verlet.data() + 12 * i;
      const double* a = acceleration_.data() + 6 * i;
      for (int k = 0; k < 3; ++k) {
        v[k] = p.velocity[i][k] + 0.5 * dt_ * a[k];
        v[3 + k] = p.angular_velocity[i][k] + 0.5 * dt_ * a[3 + k];
        v[6 + k] = a[k];
        v[9 + k] = a[3 + k];
      }
      u = Vec3(v[0], v[1], v[2]);
    }
    // Drift against the affine simple shear (the list accounts for that); a wave counts as drift.
    nonaffine_[i] = (u - Vec3(rate_ * p.position[i].y(), 0.0, 0.0)) * dt_;
    p.position[i] += u * dt_;
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
    if (inertial) state_.verlet[12 * i] -= crossings * rate_ * ly;
  }
  contacts_.record_motion(nonaffine_, std::abs(dstrain));
  evaluated_ = false;
}

}  // namespace suspend

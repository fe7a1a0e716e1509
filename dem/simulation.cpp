#include "dem/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/capacity.hpp"
#include "core/error.hpp"
#include "dem/hydro/stokes_drag.hpp"

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

PairwiseSimulation::PairwiseSimulation(SimulationState state, const Box& box, const SimulationParams& params)
    : state_(std::move(state)), box_(box), params_(params),
      contacts_(std::max(interaction_range(params.contact),
                         params.lubrication ? params.resistance.lubrication.outer_cutoff : 0.0),
                params.skin, state_.particles, state_.contacts) {
  params_.validate();
  if (params_.time_step.implicit_contacts && !params_.lubrication)
    throw InputError("run.time_step.contacts = implicit needs the resistance solve: hydrodynamics.lubrication.enabled "
                     "= true (or hydrodynamics.model = fcm)");
  box_.set_strain(state_.strain);
  const Particles& p = state_.particles;
  const std::size_t n = p.size();
  a_min_ = *std::min_element(p.radius.begin(), p.radius.end());
  for (double a : p.radius) radius_cubed_ += a * a * a;
  state_.contacts.clear();
  if (params_.flow.control == FlowControl::rate || state_.shear_rate == 0.0)
    state_.shear_rate = params_.flow.control == FlowControl::rate
                            ? params_.flow.rate(state_.time, state_.accumulated_strain)
                            : params_.flow.shear_rate;
  rate_ = state_.shear_rate;
  if (params_.flow.control == FlowControl::stress) zero_.assign(n, Vec3::Zero());  // the force-free problem's input
  // Lubrication is tabulated per pair of distinct radii.
  species_radius_ = p.radius;
  std::sort(species_radius_.begin(), species_radius_.end());
  species_radius_.erase(std::unique(species_radius_.begin(), species_radius_.end()), species_radius_.end());
  species_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    species_[i] = static_cast<int>(std::lower_bound(species_radius_.begin(), species_radius_.end(), p.radius[i]) -
                                   species_radius_.begin());
  if (params_.lubrication && params_.integrator == Integrator::inertial) {
    // Explicit forces (paper 000 eq. 15): no resistance matrix, no warm start.
    explicit_.emplace(species_radius_, params_.resistance.lubrication, params_.resistance.lubrication_stress);
    state_.warm_start.clear();
  } else if (params_.lubrication) {
    solver_.emplace(species_radius_, params_.resistance);
    if (params_.flow.control == FlowControl::stress) force_solver_.emplace(species_radius_, params_.resistance);
    const std::size_t w = state_.warm_start.size();
    auto restore = [&](ResistanceSolver& s, std::size_t from) {
      s.set_warm_start(Eigen::Map<const Eigen::VectorXd>(state_.warm_start.data() + from,
                                                         static_cast<Eigen::Index>(6 * n)));
    };
    if (w >= 6 * n) restore(*solver_, 0);
    if (force_solver_ && w == 12 * n) restore(*force_solver_, 6 * n);
    state_.warm_start.clear();
  }
  if (params_.integrator == Integrator::inertial) {
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

SimulationState PairwiseSimulation::state_with_contacts() const {
  SimulationState s = state_;
  s.contacts = contacts_.histories();
  if (solver_) {
    const Eigen::VectorXd& dv = solver_->disturbance();
    s.warm_start.assign(dv.data(), dv.data() + dv.size());
    if (force_solver_ && force_solver_->disturbance().size() == dv.size()) {
      const Eigen::VectorXd& dc = force_solver_->disturbance();
      s.warm_start.insert(s.warm_start.end(), dc.data(), dc.data() + dc.size());
    }
  }
  return s;
}

void PairwiseSimulation::fail(const std::string& what) const {
  std::ostringstream s;
  s << "numerical failure at step " << state_.step << ", strain " << state_.strain << ": " << what;
  throw NumericalError(s.str());
}

void PairwiseSimulation::contact_forces(double image_velocity) {
  Particles& p = state_.particles;
  if (const auto overlap = contacts_.evaluate(p, box_, image_velocity, params_.contact, state_.last_dt,
                                               params_.time_step.implicit_contacts, params_.max_overlap * a_min_))
    fail(*overlap);
}

double PairwiseSimulation::overdamped_velocities() {
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  const double volume = box_.volume();
  std::ostringstream where;
  where << "step " << state_.step << ", strain " << state_.strain;
  ImplicitContacts implicit;
  if (params_.time_step.implicit_contacts) implicit = {&contacts_.stiffness(), dt_};
  const PairSums& sums = contacts_.sums();
  const std::vector<ActivePair>& pairs = contacts_.pairs();
  if (solver_ && params_.flow.control == FlowControl::rate) {
    solver_->solve(p, species_, pairs, flow(rate_), sums.force, sums.torque, solve_, where.str(), implicit);
  } else if (solver_) {
    // Rate-driven problem at unit rate and force-driven problem at zero rate; velocities, stress and the implicit
    // contact changes are linear in both.
    solver_->solve(p, species_, pairs, flow(1.0), zero_, zero_, solve_, where.str(), implicit);
    force_solver_->solve(p, species_, pairs, flow(0.0), sums.force, sums.torque, force_solve_, where.str(),
                         implicit);
    const double sigma_h = 1.0 + solve_.stress.total()(0, 1) / volume;
    const double sigma_c = (sums.virial.total()(0, 1) + force_solve_.stress.total()(0, 1)) / volume;
    rate_ = (params_.flow.stress(state_.time, state_.accumulated_strain) - sigma_c) / sigma_h;
    for (std::size_t i = 0; i < n; ++i) {
      solve_.velocity[i] = rate_ * solve_.velocity[i] + force_solve_.velocity[i];
      solve_.angular_velocity[i] = rate_ * solve_.angular_velocity[i] + force_solve_.angular_velocity[i];
    }
    for (std::size_t c = 0; c < contribution_count; ++c)
      solve_.stress.part[c] = rate_ * solve_.stress.part[c] + force_solve_.stress.part[c];
    for (std::size_t k = 0; k < solve_.contact_change_on_j.size(); ++k)
      solve_.contact_change_on_j[k] = rate_ * solve_.contact_change_on_j[k] + force_solve_.contact_change_on_j[k];
  } else if (params_.flow.control == FlowControl::stress) {
    // Drag only: the hydrodynamic stress is 2 E_inf + the Stokes stresslets, the rest is the contacts'.
    const double sigma_h = 1.0 + (10.0 / 3.0) * pi * radius_cubed_ / volume;
    rate_ = (params_.flow.stress(state_.time, state_.accumulated_strain) - sums.virial.total()(0, 1) / volume) /
            sigma_h;
  }
  double max_speed = 0.0;
  const hydro::WavyShear f = flow(rate_);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = p.radius[i];
    if (solver_) {
      p.velocity[i] = solve_.velocity[i];
      p.angular_velocity[i] = solve_.angular_velocity[i];
    } else {
      p.velocity[i] = hydro::faxen_velocity(a, p.position[i], f) + sums.force[i] / (6.0 * pi * a);
      p.angular_velocity[i] = f.angular_velocity(p.position[i]) + sums.torque[i] / (8.0 * pi * a * a * a);
    }
    max_speed = std::max(max_speed, (p.velocity[i] - f.velocity(p.position[i])).norm());
  }
  return max_speed;
}

double PairwiseSimulation::inertial_velocities() {
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
  if (explicit_) {
    explicit_->evaluate(p, species_, contacts_.pairs(), f, disturbance_, mass_, moment_, explicit_out_);
    relaxation_rate_ = explicit_out_.relaxation_rate;
    solve_.stress = explicit_out_.stress;
    solve_.iterations = 0;
  } else {
    hydro_force_.resize(6 * static_cast<Eigen::Index>(n));
    relaxation_rate_ = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double a = p.radius[i];
      const hydro::StokesResistance r = hydro::stokes_resistance(a);
      const Vec3 du = disturbance_.segment<3>(6 * i) - (a * a / 6.0) * f.velocity_laplacian(p.position[i]);
      hydro_force_.segment<3>(6 * i) = -r.translation * du;
      hydro_force_.segment<3>(6 * i + 3) = -r.rotation * disturbance_.segment<3>(6 * i + 3);
      relaxation_rate_ = std::max({relaxation_rate_, r.translation / mass_[i], r.rotation / moment_[i]});
    }
  }
  const Eigen::VectorXd& hydro_force = explicit_ ? explicit_out_.force : hydro_force_;
  acceleration_.resize(6 * n);
  double max_speed = 0.0;
  const double half = 0.5 * state_.last_dt;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a_lin = (contacts_.sums().force[i] + hydro_force.segment<3>(6 * i)) / mass_[i];
    const Vec3 a_ang = (contacts_.sums().torque[i] + hydro_force.segment<3>(6 * i + 3)) / moment_[i];
    for (int k = 0; k < 3; ++k) acceleration_[6 * i + k] = a_lin[k], acceleration_[6 * i + 3 + k] = a_ang[k];
    p.velocity[i] = Vec3(v[12 * i], v[12 * i + 1], v[12 * i + 2]) + half * a_lin;          // eq. 15d
    p.angular_velocity[i] = Vec3(v[12 * i + 3], v[12 * i + 4], v[12 * i + 5]) + half * a_ang;
    max_speed = std::max(max_speed, (p.velocity[i] - f.velocity(p.position[i])).norm());
  }
  return max_speed;
}

void PairwiseSimulation::finish_stress(double rate) {
  const Particles& p = state_.particles;
  stress_ = contacts_.sums().virial;
  if (params_.lubrication) {
    // Hydrodynamic and lubrication sums; with implicit contacts also the contacts' change over the step.
    for (std::size_t c = 0; c < contribution_count; ++c) stress_.part[c] += solve_.stress.part[c];
    for (std::size_t k = 0; k < solve_.contact_change_on_j.size(); ++k)
      contacts_.add_contact_change(k, solve_.contact_change_on_j[k]);
  } else {
    const hydro::WavyShear f = flow(rate);
    Mat3& h = stress_[Contribution::hydrodynamic];
    for (std::size_t i = 0; i < p.size(); ++i) h += hydro::stokes_stresslet(p.radius[i], p.position[i], f);
  }
  for (auto& m : stress_.part) m /= box_.volume();
  // The fluid's 2 eta <E_inf>: the wave averages to zero over whole periods.
  stress_[Contribution::hydrodynamic](0, 1) += rate;
  stress_[Contribution::hydrodynamic](1, 0) += rate;
}

void PairwiseSimulation::evaluate() {
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  const bool inertial = params_.integrator == Integrator::inertial;
  if (inertial)  // the contact laws see the half-step velocities (eq. 15c)
    for (std::size_t i = 0; i < n; ++i) {
      const double* v = state_.verlet.data() + 12 * i;
      p.velocity[i] = Vec3(v[0], v[1], v[2]);
      p.angular_velocity[i] = Vec3(v[3], v[4], v[5]);
    }
  // Contacts see the image velocity of the last step's rate (their velocities are that step's).
  contact_forces(state_.shear_rate * box_.length().y());
  // Implicit contacts: the step precedes the solve (time_step_control.hpp), from the last step's speeds and this
  // step's contacts.
  if (params_.time_step.implicit_contacts) {
    dt_ = overdamped_time_step(params_.time_step, params_.contact, state_.shear_rate,
                               max_nonaffine_speed(p, flow(state_.shear_rate)), a_min_, state_.last_dt,
                               contacts_.sums().mean_compliance());
    dt_ = std::min(dt_, params_.flow.max_time_step());
  }
  rate_ = params_.flow.control == FlowControl::rate ? params_.flow.rate(state_.time, state_.accumulated_strain)
                                                    : state_.shear_rate;
  const double max_speed = inertial ? inertial_velocities() : overdamped_velocities();
  if (!std::isfinite(rate_)) fail("the stress control gave a non-finite shear rate");
  for (std::size_t i = 0; i < n; ++i)
    if (!p.velocity[i].allFinite() || !p.angular_velocity[i].allFinite()) {
      std::ostringstream s;
      s << "non-finite velocity of particle " << i << " (contact force " << contacts_.sums().force[i].transpose()
        << ")";
      fail(s.str());
    }
  finish_stress(rate_);

  // Time step: fixed, or bounded strain increment, non-affine displacement and the fastest contact or
  // hydrodynamic time scale (overdamped: drag relaxation 6 pi a / k; inertial: sqrt(m / k) and m / R).
  const TimeStepParams& ts = params_.time_step;
  if (ts.mode == TimeStepParams::Mode::fixed) {
    dt_ = ts.fixed;
  } else if (inertial) {
    const double k = stiffness_scale(params_.contact);
    dt_ = std::abs(rate_) > 0.0 ? ts.max / std::abs(rate_) : ts.max;
    if (max_speed > 0.0) dt_ = std::min(dt_, ts.max_displacement / max_speed);
    const double m_min = *std::min_element(mass_.begin(), mass_.end());
    dt_ = std::min(dt_, ts.stability * std::sqrt(m_min / k));
    if (relaxation_rate_ > 0.0) dt_ = std::min(dt_, ts.stability / relaxation_rate_);
  } else if (!ts.implicit_contacts) {
    dt_ = overdamped_time_step(ts, params_.contact, rate_, max_speed, a_min_, state_.last_dt);
  }
  dt_ = std::min(dt_, params_.flow.max_time_step());
  evaluated_ = true;
}

void PairwiseSimulation::advance() {
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

#include "dem/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.hpp"

namespace suspend {

using std::numbers::pi;

void TimeStepParams::validate() const {
  if (mode == Mode::fixed && !(fixed > 0.0)) throw InputError("run.time_step.fixed must be > 0");
  if (!(max_displacement > 0.0)) throw InputError("run.time_step.max_displacement must be > 0");
  if (!(max > 0.0)) throw InputError("run.time_step.max must be > 0");
}

void SimulationParams::validate() const {
  suspend::validate(contact);
  if (lubrication) resistance.validate();
  time_step.validate();
  if (!(max_overlap > 0.0)) throw InputError("run.max_overlap must be > 0");
}

PairwiseSimulation::PairwiseSimulation(SimulationState state, const Box& box, const SimulationParams& params)
    : state_(std::move(state)), box_(box), params_(params),
      range_(std::max(interaction_range(params.contact),
                      params.lubrication ? params.resistance.lubrication.outer_cutoff : 0.0)),
      list_(range_, params.skin) {
  params_.validate();
  box_.set_strain(state_.strain);
  const Particles& p = state_.particles;
  const auto [a_min, a_max] = std::minmax_element(p.radius.begin(), p.radius.end());
  a_min_ = *a_min;
  for (double a : p.radius) radius_cubed_ += a * a * a;
  history_ = ContactHistory(p.size(), ContactHistory::capacity_for(*a_min, *a_max));
  history_.restore(state_.contacts);
  state_.contacts.clear();
  // Lubrication is tabulated per pair of distinct radii.
  species_radius_ = p.radius;
  std::sort(species_radius_.begin(), species_radius_.end());
  species_radius_.erase(std::unique(species_radius_.begin(), species_radius_.end()), species_radius_.end());
  species_.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    species_[i] = static_cast<int>(std::lower_bound(species_radius_.begin(), species_radius_.end(), p.radius[i]) -
                                   species_radius_.begin());
  if (params_.lubrication) {
    solver_.emplace(species_radius_, params_.resistance);
    if (!state_.warm_start.empty())
      solver_->set_warm_start(Eigen::Map<const Eigen::VectorXd>(state_.warm_start.data(),
                                                               static_cast<Eigen::Index>(state_.warm_start.size())));
    state_.warm_start.clear();
  }
}

SimulationState PairwiseSimulation::state_with_contacts() const {
  SimulationState s = state_;
  s.contacts = history_.entries();
  if (solver_) {
    const Eigen::VectorXd& dv = solver_->disturbance();
    s.warm_start.assign(dv.data(), dv.data() + dv.size());
  }
  return s;
}

void PairwiseSimulation::fail(const std::string& what) const {
  std::ostringstream s;
  s << "numerical failure at step " << state_.step << ", strain " << state_.strain << ": " << what;
  throw NumericalError(s.str());
}

void PairwiseSimulation::evaluate() {
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  list_.update(p.position, p.radius, box_);
  compact_active_pairs(list_.pairs(), p, box_, range_, active_);
  active_index_.resize(active_.size());
  for (std::size_t k = 0; k < active_.size(); ++k) active_index_[k] = {active_[k].i, active_[k].j};
  pair_history_.resize(active_.size());
  history_.gather(active_index_, pair_history_);
  const double image_velocity = params_.shear_rate * box_.length().y();
  with_law(params_.contact, [&](const auto& law) {
    accumulate_pair_forces(active_, p, image_velocity, law, state_.last_dt, pair_history_, sums_, pair_force_,
                           scratch_);
  });

  const double a_min = a_min_;
  if (sums_.max_overlap > params_.max_overlap * a_min) {
    std::ostringstream s;
    s << "overlap " << sums_.max_overlap << " a_1 between particles " << sums_.max_overlap_i << " and "
      << sums_.max_overlap_j << " exceeds the bound " << params_.max_overlap * a_min
      << " (run.max_overlap x smallest radius); reduce the time step or stiffen the contacts";
    fail(s.str());
  }

  const Vec3 omega_inf(0.0, 0.0, -0.5 * params_.shear_rate);
  double max_speed = 0.0;
  if (solver_) {
    const hydro::WavyShear flow{params_.shear_rate, 0.0, 0, box_.length().y()};
    std::ostringstream where;
    where << "step " << state_.step << ", strain " << state_.strain;
    solver_->solve(p, species_, active_, flow, sums_.force, sums_.torque, solve_, where.str());
    for (std::size_t i = 0; i < n; ++i) {
      p.velocity[i] = solve_.velocity[i];
      p.angular_velocity[i] = solve_.angular_velocity[i];
      max_speed = std::max(max_speed, (p.velocity[i] - ambient_velocity(p.position[i])).norm());
    }
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const double a = p.radius[i];
      const Vec3 du = sums_.force[i] / (6.0 * pi * a);
      p.velocity[i] = ambient_velocity(p.position[i]) + du;
      p.angular_velocity[i] = omega_inf + sums_.torque[i] / (8.0 * pi * a * a * a);
      max_speed = std::max(max_speed, du.norm());
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!p.velocity[i].allFinite() || !p.angular_velocity[i].allFinite()) {
      std::ostringstream s;
      s << "non-finite velocity of particle " << i << " (contact force " << sums_.force[i].transpose() << ")";
      fail(s.str());
    }

  // Stress: fluid + Stokes stresslets (hydrodynamic) and pair virials, per unit volume.
  Mat3 e_inf = Mat3::Zero();
  e_inf(0, 1) = e_inf(1, 0) = 0.5 * params_.shear_rate;
  const double volume = box_.volume();
  stress_ = sums_.virial;
  if (solver_) {
    stress_[Contribution::hydrodynamic] = solve_.stress[Contribution::hydrodynamic];
    stress_[Contribution::lubrication] = solve_.stress[Contribution::lubrication];
  } else {
    stress_[Contribution::hydrodynamic] = (20.0 / 3.0) * pi * radius_cubed_ * e_inf;
  }
  for (auto& m : stress_.part) m /= volume;
  stress_[Contribution::hydrodynamic] += 2.0 * e_inf;

  // Time step: fixed, or bounded non-affine displacement and the contact relaxation time 6 pi a / k.
  if (params_.time_step.mode == TimeStepParams::Mode::fixed) {
    dt_ = params_.time_step.fixed;
  } else {
    dt_ = params_.time_step.max;
    if (max_speed > 0.0) dt_ = std::min(dt_, params_.time_step.max_displacement / max_speed);
    dt_ = std::min(dt_, params_.time_step.stability * 6.0 * pi * a_min / stiffness_scale(params_.contact));
  }
  evaluated_ = true;
}

void PairwiseSimulation::advance() {
  if (!evaluated_) evaluate();
  history_.scatter(active_index_, pair_history_);
  Particles& p = state_.particles;
  const std::size_t n = p.size();
  nonaffine_.resize(n);
  const double ly = box_.length().y();
  for (std::size_t i = 0; i < n; ++i) {
    nonaffine_[i] = (p.velocity[i] - ambient_velocity(p.position[i])) * dt_;
    p.position[i] += p.velocity[i] * dt_;
  }
  const double dstrain = params_.shear_rate * dt_;
  state_.strain += dstrain;
  state_.time += dt_;
  state_.last_dt = dt_;
  ++state_.step;
  box_.set_strain(state_.strain);
  for (std::size_t i = 0; i < n; ++i) {
    const int crossings = box_.wrap(p.position[i]);
    p.velocity[i].x() -= crossings * params_.shear_rate * ly;  // paper 000, eq. 16d
  }
  list_.record_motion(nonaffine_, dstrain);
  evaluated_ = false;
}

}  // namespace suspend

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
  contact.validate();
  time_step.validate();
  if (!(max_overlap > 0.0)) throw InputError("run.max_overlap must be > 0");
}

PairwiseSimulation::PairwiseSimulation(SimulationState state, const Box& box, const SimulationParams& params)
    : state_(std::move(state)), box_(box), params_(params), law_{params.contact}, list_(0.0, params.skin) {
  params_.validate();
  box_.set_strain(state_.strain);
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
  compact_active_pairs(list_.pairs(), p, box_, 0.0, active_);
  accumulate_pair_forces(active_, n, law_, sums_, scratch_);

  const double a_min = *std::min_element(p.radius.begin(), p.radius.end());
  if (sums_.max_overlap > params_.max_overlap * a_min) {
    std::ostringstream s;
    s << "overlap " << sums_.max_overlap << " a_1 between particles " << sums_.max_overlap_i << " and "
      << sums_.max_overlap_j << " exceeds the bound " << params_.max_overlap * a_min
      << " (run.max_overlap x smallest radius); reduce the time step or stiffen the contacts";
    fail(s.str());
  }

  const Vec3 omega_inf(0.0, 0.0, -0.5 * params_.shear_rate);
  double max_speed = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = p.radius[i];
    const Vec3 du = sums_.force[i] / (6.0 * pi * a);
    p.velocity[i] = ambient_velocity(p.position[i]) + du;
    p.angular_velocity[i] = omega_inf + sums_.torque[i] / (8.0 * pi * a * a * a);
    if (!p.velocity[i].allFinite() || !p.angular_velocity[i].allFinite()) {
      std::ostringstream s;
      s << "non-finite velocity of particle " << i << " (force " << sums_.force[i].transpose() << ")";
      fail(s.str());
    }
    max_speed = std::max(max_speed, du.norm());
  }

  // Stress: fluid + Stokes stresslets (hydrodynamic) and pair virials, per unit volume.
  Mat3 e_inf = Mat3::Zero();
  e_inf(0, 1) = e_inf(1, 0) = 0.5 * params_.shear_rate;
  double a3 = 0.0;
  for (double a : p.radius) a3 += a * a * a;
  const double volume = box_.volume();
  stress_ = sums_.virial;
  for (auto& m : stress_.part) m /= volume;
  stress_[Contribution::hydrodynamic] = 2.0 * e_inf + (20.0 / 3.0) * pi * a3 / volume * e_inf;

  // Time step: fixed, or bounded non-affine displacement and the contact relaxation time 6 pi a / k.
  if (params_.time_step.mode == TimeStepParams::Mode::fixed) {
    dt_ = params_.time_step.fixed;
  } else {
    dt_ = params_.time_step.max;
    if (max_speed > 0.0) dt_ = std::min(dt_, params_.time_step.max_displacement / max_speed);
    dt_ = std::min(dt_, params_.time_step.stability * 6.0 * pi * a_min / params_.contact.kn);
  }
  evaluated_ = true;
}

void PairwiseSimulation::advance() {
  if (!evaluated_) evaluate();
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
  ++state_.step;
  box_.set_strain(state_.strain);
  for (std::size_t i = 0; i < n; ++i) {
    const int crossings = box_.wrap(p.position[i]);
    p.velocity[i].x() -= crossings * params_.shear_rate * ly;  // paper 000, eq. 16d
  }
  list_.record_motion(nonaffine_, dstrain);
  evaluated_ = false;
}

std::vector<Vec3> PairwiseSimulation::pair_forces() const {
  std::vector<Vec3> f;
  f.reserve(active_.size());
  for (const ActivePair& pr : active_) f.push_back(law_(pr.geometry).total_on_j());
  return f;
}

}  // namespace suspend

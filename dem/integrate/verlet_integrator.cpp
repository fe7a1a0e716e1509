#include "dem/integrate/verlet_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "dem/hydro/stokes_drag.hpp"

namespace suspend {

VerletIntegrator::VerletIntegrator(InertialModel& model, const Particles& p, double stokes_number,
                                   const std::vector<double>& saved, const AmbientFlow& flow)
    : model_(model) {
  const std::size_t n = p.size();
  mass_.resize(n);
  moment_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = p.radius[i];
    mass_[i] = stokes_number * (4.0 / 3.0) * std::numbers::pi * a * a * a;
    moment_[i] = 0.4 * mass_[i] * a * a;
  }
  if (saved.empty()) {
    state_.assign(12 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 u = hydro::faxen_velocity(p.radius[i], p.position[i], flow), w = flow.angular_velocity(p.position[i]);
      for (int k = 0; k < 3; ++k) state_[12 * i + k] = u[k], state_[12 * i + 3 + k] = w[k];
    }
  } else if (saved.size() != 12 * n) {
    throw InputError("inertial state: 12 numbers per particle expected, got " + std::to_string(saved.size()));
  } else {
    state_ = saved;
  }
}

void VerletIntegrator::set_contact_velocities(Particles& p) const {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double* v = state_.data() + 12 * i;
    p.velocity[i] = Vec3(v[0], v[1], v[2]);
    p.angular_velocity[i] = Vec3(v[3], v[4], v[5]);
  }
}

const ExplicitResponse& VerletIntegrator::velocities(const HydroLoad& load, double rate, const AmbientFlow& flow,
                                                     double last_dt, Particles& p) {
  const std::size_t n = p.size();
  const std::vector<double>& v = state_;
  // Hydrodynamic force and torque at the half-step velocities (explicit, paper 000 eq. 15c).
  disturbance_.resize(6 * static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      disturbance_[6 * i + k] = v[12 * i + k] - flow.velocity(p.position[i])[k];
      disturbance_[6 * i + 3 + k] = v[12 * i + 3 + k] - flow.angular_velocity(p.position[i])[k];
    }
  const ExplicitResponse& hydro = model_.explicit_forces(load, rate, disturbance_, mass_, moment_);
  relaxation_rate_ = hydro.relaxation_rate;
  acceleration_.resize(6 * n);
  const double half = 0.5 * last_dt;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a_lin = (load.force[i] + hydro.force.segment<3>(6 * i)) / mass_[i];
    const Vec3 a_ang = (load.torque[i] + hydro.force.segment<3>(6 * i + 3)) / moment_[i];
    for (int k = 0; k < 3; ++k) acceleration_[6 * i + k] = a_lin[k], acceleration_[6 * i + 3 + k] = a_ang[k];
    p.velocity[i] = Vec3(v[12 * i], v[12 * i + 1], v[12 * i + 2]) + half * a_lin;  // eq. 15d
    p.angular_velocity[i] = Vec3(v[12 * i + 3], v[12 * i + 4], v[12 * i + 5]) + half * a_ang;
  }
  return hydro;
}

double VerletIntegrator::stability_time_step(double stiffness, double stability) const {
  const double m_min = *std::min_element(mass_.begin(), mass_.end());
  double dt = stability * std::sqrt(m_min / stiffness);
  if (relaxation_rate_ > 0.0) dt = std::min(dt, stability / relaxation_rate_);
  return dt;
}

Vec3 VerletIntegrator::half_step(std::size_t i, const Particles& p, double dt) {
  double* v = state_.data() + 12 * i;
  const double* a = acceleration_.data() + 6 * i;
  for (int k = 0; k < 3; ++k) {
    v[k] = p.velocity[i][k] + 0.5 * dt * a[k];
    v[3 + k] = p.angular_velocity[i][k] + 0.5 * dt * a[3 + k];
    v[6 + k] = a[k];
    v[9 + k] = a[3 + k];
  }
  return Vec3(v[0], v[1], v[2]);
}

}  // namespace suspend

// Shared helpers for the contact-law tests: random rotations, rotated pair configurations, numerical gradients.
#pragma once
#include <Eigen/Geometry>
#include <random>

#include "core/vec.hpp"
#include "dem/contact/adhesion.hpp"
#include "dem/contact/hertz_adhesive.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"

namespace suspend::test {

// Paper 004's Hertz adhesive contact (eq. 16) with round numbers: roughness 0.01, eps_bar 0.05, k_n 1e5 (and the
// constant adhesion F_adh 2 of round_adhesion).
inline HertzAdhesiveParams round_hertz_adhesive() {
  HertzAdhesiveParams p;
  p.roughness = 0.01;
  p.eps_bar = 0.05;
  p.kn = 1.0e5;
  return p;
}
inline Adhesion round_adhesion() { return Adhesion::constant(2.0); }

inline Mat3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q.toRotationMatrix();
}

inline Vec3 random_vector(std::mt19937_64& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

inline RelativeMotion rotated(const Mat3& R, const RelativeMotion& m) {
  return {R * m.u_i, R * m.u_j, R * m.omega_i, R * m.omega_j};
}
inline PairHistory rotated(const Mat3& R, const PairHistory& h) {
  return {R * h.tangential_stretch, R * h.rolling_stretch, h.in_contact};
}

// Energy-based normal force on j along n: -dE/dr by central differences at separation r.
template <class Law>
double numerical_normal_force(const Law& law, double r, double a_i, double a_j, double step = 1e-7) {
  const Vec3 n(0.3, -0.4, std::sqrt(1.0 - 0.25));
  const auto at = [&](double s) { return law.energy(PairGeometry::from(s * n, a_i, a_j)); };
  return -(at(r + step) - at(r - step)) / (2.0 * step);
}

// Total angular momentum balance of a pair about any point: tau_i + tau_j + d x F_j = 0 (F_i = -F_j).
inline Vec3 angular_momentum_residual(const PairGeometry& g, const PairForce& f) {
  return f.torque_i + f.torque_j + g.d.cross(f.total_on_j());
}

// Power delivered to the pair by its forces and torques (F_i = -F_j).
inline double power(const PairForce& f, const RelativeMotion& m) {
  return f.total_on_j().dot(m.u_j - m.u_i) + f.torque_i.dot(m.omega_i) + f.torque_j.dot(m.omega_j);
}

}  // namespace suspend::test

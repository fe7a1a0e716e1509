// Gaussian envelopes of the Force Coupling Method (Maxey & Patel 2001; Lomholt & Maxey 2003).
//   Delta(r) = (2 pi sigma^2)^(-3/2) exp(-|r|^2 / (2 sigma^2))
// Monopole width sigma_M = a / sqrt(pi): an isolated sphere translates at U = F / (6 pi eta a).
// Dipole width sigma_D = a / (6 sqrt(pi))^(1/3): the same envelope gives Omega = T / (8 pi eta a^3) and
// S = (20/3) pi eta a^3 E exactly (Lomholt & Maxey 2003, eqs. 2.8-2.10). Units: lengths in a_1, eta = 1.
#pragma once
#include <cmath>
#include <numbers>

namespace suspend::fcm {

inline double monopole_width(double radius) { return radius / std::sqrt(std::numbers::pi); }
inline double dipole_width(double radius) { return radius / std::cbrt(6.0 * std::sqrt(std::numbers::pi)); }

// Exact isolated-sphere mobilities of the FCM envelopes (eta = 1): U = F/(6 pi a), Omega = T/(8 pi a^3),
// E = -S / ((20/3) pi a^3). Used as the Jacobi preconditioner of the rigidity solve and by the direct sum.
inline double translational_self_mobility(double radius) { return 1.0 / (6.0 * std::numbers::pi * radius); }
inline double rotational_self_mobility(double radius) {
  return 1.0 / (8.0 * std::numbers::pi * radius * radius * radius);
}
inline double stresslet_self_mobility(double radius) {
  return 1.0 / (20.0 / 3.0 * std::numbers::pi * radius * radius * radius);
}

}  // namespace suspend::fcm

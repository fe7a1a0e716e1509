// Coulomb friction limit of the stick/slide spring (paper 000, text after eq. 4 and eq. 5):
//   |F_t| <= mu_C |F_n|,
// with F_n the full normal contact force (spring + dashpot). Dimensionless. mu = 0 gives frictionless contacts.
#pragma once
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace suspend {

struct CoulombFrictionParams {
  double mu = 1.0;  // mu_C, paper 000 table 1 (frictional case)
  void validate() const {
    if (!(mu >= 0.0)) throw InputError("contact.mu = " + std::to_string(mu) + " must be >= 0");
  }
};

struct CoulombFriction {
  CoulombFrictionParams p;
  void validate() const { p.validate(); }
  // Largest tangential force the contact can carry for a signed normal force f_n (positive = repulsive).
  double limit(double f_n) const { return p.mu * std::abs(f_n); }
};

}  // namespace suspend

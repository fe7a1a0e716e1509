// Critical-load friction (paper 002 section 3.2; Seto et al. 2013, Mari et al. 2014 eq. 8):
//   F_n <  F_CL : the contact is frictionless (F_t = 0, stretch reset),
//   F_n >= F_CL : |F_t| <= mu (F_n - F_CL),
// with F_n the signed normal contact force (spring + dashpot, positive = repulsive). Friction only under a large
// enough load is what turns the rheology from frictionless at low stress to frictional at high stress (shear
// thickening). Units: F_CL in eta_0 gammadot a_1^2; its inverse sets the dimensionless rate of paper 002 Fig. 4.
#pragma once
#include <string>

#include "core/error.hpp"

namespace suspend {

struct CriticalLoadFrictionParams {
  double mu = 1.0;             // sliding friction coefficient above the threshold
  double critical_load = 1.0;  // F_CL, the normal force that must be exceeded before friction acts
  void validate() const {
    if (!(mu >= 0.0)) throw InputError("contact.mu = " + std::to_string(mu) + " must be >= 0");
    if (!(critical_load >= 0.0))
      throw InputError("contact.critical_load = " + std::to_string(critical_load) + " must be >= 0");
  }
};

struct CriticalLoadFriction {
  CriticalLoadFrictionParams p;
  void validate() const { p.validate(); }
  double limit(double f_n) const { return f_n > p.critical_load ? p.mu * (f_n - p.critical_load) : 0.0; }
};

}  // namespace suspend

// Linear soft repulsion between overlapping spheres: the simplest honest contact law.
// F_j = k_n * delta * n for overlap delta = -(gap) > 0, zero otherwise (a frictionless, undamped linear spring;
// paper 000 eq. 4 with k_t = gamma_n = 0). Potential energy (k_n/2) delta^2, so F_j = -dE/dr_j.
// Units: k_n in eta_0 gammadot a_1 (the stiffness k-hat of paper 000 eq. 12 when a_0 = a_1).
#pragma once
#include <string>

#include "core/error.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

struct SoftRepulsionParams {
  double kn = 1.0e4;
  void validate() const {
    if (!(kn > 0.0)) throw InputError("contact.kn = " + std::to_string(kn) + " must be > 0");
  }
};

struct SoftRepulsion {
  SoftRepulsionParams p;
  void validate() const { p.validate(); }
  double range() const { return 0.0; }  // acts only on overlap
  PairForce operator()(const PairGeometry& g) const {
    PairForce f;
    const double delta = -g.gap();
    if (delta > 0.0) {
      f[Contribution::contact_normal] = p.kn * delta * g.n;
      f.normal_stiffness = p.kn;
    }
    return f;
  }
  double energy(const PairGeometry& g) const {
    const double delta = -g.gap();
    return delta > 0.0 ? 0.5 * p.kn * delta * delta : 0.0;
  }
};

}  // namespace suspend

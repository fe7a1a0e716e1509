// Critical-load friction, a tangential sub-model (paper 002 section 3.2; Seto et al. 2013, Mari et al. 2014 eq. 8):
//   L <  F_CL : the contact is frictionless (F_t = 0, stretch reset),
//   L >= F_CL : |F_t| <= mu (L - F_CL),
// with L the load of the normal sub-model (NormalContact::load: the signed spring + dashpot force of the linear
// laws, positive = repulsive; the elastic force F_n + F_adh of Hertz). Friction only under a large enough load is
// what turns the rheology from frictionless at low stress to frictional at high stress (shear thickening).
// Units: F_CL in eta_0 gammadot a_1^2; its inverse sets the dimensionless rate of paper 002 Fig. 4.
#pragma once
#include <string_view>

#include "core/range.hpp"
#include "dem/contact/friction_coefficient.hpp"

namespace suspend {

struct CriticalLoadFrictionParams {
  double mu = 1.0;             // sliding friction coefficient above the threshold
  double critical_load = 1.0;  // F_CL, the load that must be exceeded before friction acts
};

struct CriticalLoadFriction {
  static constexpr std::string_view name = "critical_load";
  CriticalLoadFrictionParams p;
  void validate() const {
    require(p.mu, Range::non_negative(), "contact.mu");
    require(p.critical_load, Range::non_negative(), "contact.critical_load");
  }
  double limit(double load) const { return load > p.critical_load ? p.mu * (load - p.critical_load) : 0.0; }
  double coefficient() const { return p.mu; }

  template <class Reader>
  static CriticalLoadFriction read(Reader& r, double default_mu) {
    CriticalLoadFriction f;
    f.p.mu = read_friction_coefficient(r, default_mu);
    f.p.critical_load = r.number("critical_load", f.p.critical_load, Range::non_negative());
    return f;
  }
  template <class Writer>
  void write(Writer& w) const {
    w.text("friction", name);
    w.number("critical_load", p.critical_load);
    w.number("mu", p.mu);
  }
};

}  // namespace suspend

// Coulomb friction, a tangential sub-model (paper 000, text after eq. 4 and eq. 5; paper 004 eq. 16):
//   |F_t| <= mu |L|,
// L the load of the normal sub-model composed with it (NormalContact::load: the full spring + dashpot force of the
// linear laws, the elastic force F_n + F_adh of Hertz). Dimensionless. Case key `mu` (or `mu_s`,
// friction_coefficient.hpp); mu = 0 is read as no friction (NoFriction).
#pragma once
#include <cmath>
#include <string_view>

#include "core/range.hpp"
#include "dem/contact/friction_coefficient.hpp"

namespace suspend {

struct CoulombFrictionParams {
  double mu = 1.0;
};

struct CoulombFriction {
  static constexpr std::string_view name = "coulomb";
  CoulombFrictionParams p;
  void validate() const { require(p.mu, Range::non_negative(), "contact.mu"); }
  // Largest tangential force the contact can carry under a signed load (positive = repulsive).
  double limit(double load) const { return p.mu * std::abs(load); }
  double coefficient() const { return p.mu; }

  template <class Reader>
  static CoulombFriction read(Reader& r, double default_mu) { return {{read_friction_coefficient(r, default_mu)}}; }
  template <class Writer>
  void write(Writer& w) const {
    w.text("friction", name);
    w.number("mu", p.mu);
  }
};

}  // namespace suspend

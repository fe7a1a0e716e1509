// Coulomb friction, a tangential sub-model (paper 000, text after eq. 4 and eq. 5; paper 004 eq. 16):
//   |F_t| <= mu |L|,
// L the load of the normal sub-model composed with it (NormalContact::load: the full spring + dashpot force of the
// linear laws, the elastic force F_n + F_adh of Hertz). Dimensionless. The case key of mu is the normal law's
// (`mu`, or `mu_s` for hertz_adhesive); mu = 0 is read as no friction (NoFriction).
#pragma once
#include <cmath>
#include <string>
#include <string_view>

#include "core/range.hpp"

namespace suspend {

struct CoulombFrictionParams {
  double mu = 1.0;
};

struct CoulombFriction {
  static constexpr std::string_view name = "coulomb";
  CoulombFrictionParams p;
  void validate(std::string_view mu_key = "mu") const {
    require(p.mu, Range::non_negative(), "contact." + std::string(mu_key));
  }
  // Largest tangential force the contact can carry under a signed load (positive = repulsive).
  double limit(double load) const { return p.mu * std::abs(load); }
  double coefficient() const { return p.mu; }

  template <class Reader>
  static CoulombFriction read(Reader& r, std::string_view mu_key, double default_mu) {
    return {{r.number(std::string(mu_key), default_mu, Range::non_negative())}};
  }
  template <class Writer>
  void write(Writer& w, std::string_view mu_key) const {
    w.text("friction", name);
    w.number(mu_key, p.mu);
  }
};

}  // namespace suspend

// Soft repulsion, a normal sub-model: the simplest honest contact law.
// F_j = k_n * delta * n for overlap delta = -(gap) > 0, zero otherwise (paper 000 eq. 4a without its dashpot; with
// no other sub-model a frictionless, undamped linear spring). Composed friction's default k_t = (2/7) k_n.
// Potential energy (k_n/2) delta^2, so F_j = -dE/dr_j.
// Units: k_n in eta_0 gammadot a_1 (the stiffness k-hat of paper 000 eq. 12 when a_0 = a_1, io/units.hpp).
#pragma once
#include <string_view>

#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

struct SoftRepulsionParams {
  double kn = 1.0e4;
};

struct SoftRepulsion {
  static constexpr std::string_view name = "soft_repulsion";
  static constexpr std::string_view documentation = "docs/contact.md, section 'Soft repulsion'";
  static constexpr std::string_view stiffness_keys = "contact.k_hat";
  static constexpr std::string_view default_friction = "none";
  static constexpr double default_mu = 1.0;
  static constexpr std::string_view default_adhesion = "none";
  static constexpr double default_g_adh = 0.0;

  SoftRepulsionParams p;

  void validate() const { require(p.kn, Range::positive(), "contact.k_hat"); }
  double range() const { return 0.0; }  // acts only on overlap
  double stiffness_scale() const { return p.kn; }
  double secant_stiffness() const { return p.kn; }
  double default_tangential_stiffness() const { return 2.0 / 7.0 * p.kn; }
  double adhesion_force() const { return 0.0; }

  // Whether the pair is in contact, its normal force on j and the load friction acts against.
  NormalContact apply(const PairGeometry& g, const RelativeMotion&, PairForce& f) const {
    const double delta = -g.gap();
    if (!(delta > 0.0)) return {};
    const double f_n = p.kn * delta;
    f.normal_stiffness = p.kn;
    return {true, f_n, f_n};
  }
  double energy(const PairGeometry& g) const {
    const double delta = -g.gap();
    return delta > 0.0 ? 0.5 * p.kn * delta * delta : 0.0;
  }

  template <class Reader>
  static SoftRepulsion read(Reader& r) {
    SoftRepulsion s;
    s.p.kn = r.number("k_hat", s.p.kn, Range::positive());
    return s;
  }
  template <class Writer>
  void write(Writer& w) const {
    w.number("k_hat", p.kn);
  }
};

}  // namespace suspend

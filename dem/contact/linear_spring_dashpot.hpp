// Linear spring, the normal sub-model of paper 000's spring-dashpot (eq. 4a; Luding 2008).
//
// Contact while the spheres overlap: delta = -(gap) = a_i + a_j - r > 0. Force ON j (n from i to j):
//   F_n n,  F_n = k_n delta - gamma_n (u_j - u_i) . n          (eq. 4a, sign flipped to "on j")
// The dashpot -gamma_n v_n is the viscous damping sub-model (normal_damping.hpp, key gamma_n as before). F_n is
// signed (positive = repulsive): a fast separation can make it attractive, exactly as eq. 4a; it is the load of the
// friction sub-models (CoulombFriction uses |F_n| as paper 000, CriticalLoadFriction F_n - F_CL as paper 002). The
// tangential spring composed with it (eq. 4b) has stiffness k_t (key kt, default (2/7) k_n, paper 000 table 1).
// Energy of the elastic normal spring: (k_n/2) delta^2.
// Units: k_n, k_t in eta_0 gammadot a_1 (so k_n is k-hat of paper 000 eq. 12 when a_0 = a_1), forces in
// eta_0 gammadot a_1^2.
#pragma once
#include <string_view>

#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

// Default: paper 000 table 1 (k-hat = 4e5; its k_t/k_n = 2/7 is the tangential default, and its damping group
// gamma_n gammadot / k_n = 1e-7 is given with damping: viscous, gamma_n 0.04).
struct LinearSpringParams {
  double kn = 4.0e5;
};

struct LinearSpringDashpot {
  static constexpr std::string_view name = "linear_spring";
  static constexpr std::string_view documentation = "docs/contact.md, section 'Linear spring-dashpot + Coulomb stick/slide'";
  static constexpr std::string_view stiffness_keys = "contact.k_hat";
  static constexpr std::string_view default_friction = "coulomb";
  static constexpr double default_mu = 1.0;  // paper 000 table 1 (frictional case)
  static constexpr std::string_view default_adhesion = "none";
  static constexpr double default_g_adh = 0.0;

  LinearSpringParams p;

  void validate() const { require(p.kn, Range::positive(), "contact.k_hat"); }
  double range() const { return 0.0; }
  double stiffness_scale() const { return p.kn; }
  double secant_stiffness() const { return p.kn; }
  double default_tangential_stiffness() const { return 2.0 / 7.0 * p.kn; }
  double adhesion_force() const { return 0.0; }

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
  static LinearSpringDashpot read(Reader& r) {
    LinearSpringDashpot s;
    s.p.kn = r.number("k_hat", s.p.kn, Range::positive());
    return s;
  }
  template <class Writer>
  void write(Writer& w) const {
    w.number("k_hat", p.kn);
  }
};

}  // namespace suspend

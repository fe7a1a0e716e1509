// Twisting (torsion) resistance, a sub-model that composes with every normal law (Luding, Granular Matter 10, 235
// (2008), section 2.3, the torsion sibling of the rolling resistance of paper 000 Appendix B).
//
//   u_o = a_ij (omega_i - omega_j) . n                    (the twisting velocity along n; a_ij = 2 a_i a_j/(a_i + a_j))
//   xi_o += u_o dt,   F_o = -k_o xi_o,   |F_o| <= mu_o |L|  (stick/slide of a spring about n, L the normal load)
//   T_i = a_ij F_o n,  T_j = -T_i                         (a pair of opposite torques about the normal)
// F_o is a pseudo-force: no force and no stresslet, only the torques. T_i opposes the spin of i relative to j about
// n, and the torques do work -k_o xi_o u_o: the spring stores energy while it sticks and dissipates while it slides.
// u_o is unchanged by a rigid rotation of the pair (omega_i = omega_j) and by the swap i <-> j (n -> -n), so the
// stretch is one signed scalar per pair (PairHistory::twisting_stretch) with no orientation to carry.
// Case block `twisting: {k_twist, mu_twist}`; absent means no twisting resistance. Defaults: k_o = the normal law's
// secant stiffness / 100 (as the rolling spring), mu_o = 0.1 (as mu_r; Luding gives no value).
// Units: k_o in eta_0 gammadot a_1 (like k_n), mu_o dimensionless.
#pragma once
#include <cmath>
#include <string_view>

#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

struct TwistingResistance {
  static constexpr std::string_view name = "twisting";
  bool active = false;
  double stiffness = 0.0;  // k_o
  double mu = 0.1;         // mu_o

  void validate() const {
    if (!active) return;
    require(stiffness, Range::positive(), "contact.twisting.k_twist");
    require(mu, Range::non_negative(), "contact.twisting.mu_twist");
  }

  static double twisting_velocity(const PairGeometry& g, const RelativeMotion& m) {
    return g.harmonic_radius() * (m.omega_i - m.omega_j).dot(g.n);
  }
  // Updates the twisting stretch and adds the twisting torques for a contact carrying the load `load`.
  void apply(const PairGeometry& g, const RelativeMotion& m, double load, double dt, double& xi,
             PairForce& out) const {
    if (!active) return;
    xi += twisting_velocity(g, m) * dt;
    const double limit = mu * std::abs(load);
    if (stiffness * std::abs(xi) > limit) xi = std::copysign(limit / stiffness, xi);  // slides at the cap
    const Vec3 torque_i = (g.harmonic_radius() * -stiffness * xi) * g.n;
    out.torque_i += torque_i;
    out.torque_j -= torque_i;
  }

  template <class Reader>
  static TwistingResistance read(Reader& r, double default_stiffness) {
    TwistingResistance t;
    t.active = true;
    t.stiffness = r.number("k_twist", default_stiffness, Range::positive());
    t.mu = r.number("mu_twist", t.mu, Range::non_negative());
    return t;
  }
  template <class Writer>
  void write(Writer& w) const {
    w.number("k_twist", stiffness);
    w.number("mu_twist", mu);
  }
};

}  // namespace suspend

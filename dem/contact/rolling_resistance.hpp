// Rolling resistance (paper 000, Appendix B; Luding 2008 sec. 2.3).
//
//   u_r = a_ij (n x omega_i - n x omega_j),  a_ij = 2 a_i a_j / (a_i + a_j)        (rolling velocity, as written)
//   xi_r: stretch of the rolling spring, updated like eq. 5 with u_r and k_r (stick_slide.hpp),
//   F_r* = k_r xi_r, |F_r*| <= mu_r |F_n|                                          (B.1a, own Coulomb-like limit)
//   T_i = a_ij n x F_r*,  T_j = -T_i                                                (B.1b-c)
// F_r* is a pseudo-force: it only produces the pair of opposite torques, no force and no stresslet. With n from i
// to j, T_i opposes omega_i - omega_j (checked in tests/unit/test_contact_rolling.cpp), and the torques do work
// -k_r xi_r . u_r: the spring stores energy while sticking and dissipates while rolling at the limit.
// u_r is unchanged by a rigid rotation of the pair (omega_i = omega_j), as it must be.
// Units: k_r in eta_0 gammadot a_1 (like k_n), mu_r dimensionless.
#pragma once
#include <string>

#include "core/error.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/stick_slide.hpp"

namespace suspend {

struct RollingResistanceParams {
  double kr = 4.0e3;   // rolling stiffness k_r, with k_r / k_n << 1 (Appendix B; our default: k_n / 100)
  double mu_r = 0.1;   // rolling friction coefficient (our default; the paper gives none)
  void validate() const {
    if (!(kr > 0.0)) throw InputError("contact.rolling.kr = " + std::to_string(kr) + " must be > 0");
    if (!(mu_r >= 0.0)) throw InputError("contact.rolling.mu_r = " + std::to_string(mu_r) + " must be >= 0");
  }
};

struct RollingResistance {
  RollingResistanceParams p;
  void validate() const { p.validate(); }

  static Vec3 rolling_velocity(const PairGeometry& g, const RelativeMotion& m) {
    return g.harmonic_radius() * g.n.cross(m.omega_i - m.omega_j);
  }
  // Updates the rolling stretch and adds the rolling torques for a contact carrying normal force f_n.
  void apply(const PairGeometry& g, const RelativeMotion& m, double f_n, double dt, Vec3& xi_r,
             PairForce& out) const {
    // stick_slide returns -k_r xi_r (capped); the pseudo-force of eq. B.1a is its negative.
    const StickSlideResult s = stick_slide(xi_r, g.n, rolling_velocity(g, m), dt, p.kr, p.mu_r * std::abs(f_n));
    const Vec3 torque_i = g.harmonic_radius() * g.n.cross(-s.force_on_j);
    out.torque_i += torque_i;
    out.torque_j -= torque_i;
  }
};

// The "no rolling resistance" alternative, so a law composes rolling at compile time.
struct NoRolling {
  void validate() const {}
  void apply(const PairGeometry&, const RelativeMotion&, double, double, Vec3&, PairForce&) const {}
};

}  // namespace suspend

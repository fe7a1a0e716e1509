// Rolling resistance (paper 000, Appendix B; Luding 2008 sec. 2.3).
//
//   u_r = a_ij (n x omega_i - n x omega_j),  a_ij = 2 a_i a_j / (a_i + a_j)        (rolling velocity, as written)
//   xi_r: stretch of the rolling spring, updated like eq. 5 with u_r and k_r (stick_slide.hpp),
//   F_r* = k_r xi_r, |F_r*| <= mu_r |L|                                            (B.1a, own Coulomb-like limit)
//   T_i = a_ij n x F_r*,  T_j = -T_i                                                (B.1b-c)
// F_r* is a pseudo-force: it only produces the pair of opposite torques, no force and no stresslet. With n from i
// to j, T_i opposes omega_i - omega_j (checked in tests/unit/test_contact_rolling.cpp), and the torques do work
// -k_r xi_r . u_r: the spring stores energy while sticking and dissipates while rolling at the limit.
// u_r is unchanged by a rigid rotation of the pair (omega_i = omega_j), as it must be.
// L is the load of the normal sub-model (NormalContact::load; F_n in the paper's linear spring). A rolling sub-model
// composes with every normal and friction sub-model (contact_model.hpp); its default stiffness is the normal law's
// secant stiffness / 100 (k_n / 100 for the linear spring, Appendix B's k_r / k_n << 1).
// Units: k_r in eta_0 gammadot a_1 (like k_n), mu_r dimensionless.
#pragma once
#include <string>
#include <string_view>

#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/stick_slide.hpp"

namespace suspend {

struct RollingResistanceParams {
  double kr = 4.0e3;   // rolling stiffness k_r, with k_r / k_n << 1 (Appendix B; our default: k_n / 100)
  double mu_r = 0.1;   // rolling friction coefficient (our default; the paper gives none)
  void validate() const {
    require(kr, Range::positive(), "contact.rolling.kr");
    require(mu_r, Range::non_negative(), "contact.rolling.mu_r");
  }
};

struct RollingResistance {
  static constexpr std::string_view name = "rolling";
  RollingResistanceParams p;
  void validate() const { p.validate(); }

  static Vec3 rolling_velocity(const PairGeometry& g, const RelativeMotion& m) {
    return g.harmonic_radius() * g.n.cross(m.omega_i - m.omega_j);
  }
  // Updates the rolling stretch and adds the rolling torques for a contact carrying the load `load`.
  void apply(const PairGeometry& g, const RelativeMotion& m, double load, double dt, Vec3& xi_r,
             PairForce& out) const {
    // stick_slide returns -k_r xi_r (capped); the pseudo-force of eq. B.1a is its negative.
    const StickSlideResult s = stick_slide(xi_r, g.n, rolling_velocity(g, m), dt, p.kr, p.mu_r * std::abs(load));
    const Vec3 torque_i = g.harmonic_radius() * g.n.cross(-s.force_on_j);
    out.torque_i += torque_i;
    out.torque_j -= torque_i;
  }

  // The `rolling` block of a case: {kr, mu_r}; kr defaults to the normal law's secant stiffness / 100.
  template <class Reader>
  static RollingResistance read(Reader& r, double default_kr) {
    RollingResistance out;
    out.p.kr = r.number("kr", default_kr, Range::positive());
    out.p.mu_r = r.number("mu_r", out.p.mu_r, Range::non_negative());
    return out;
  }
  template <class Writer>
  void write(Writer& w) const {
    w.number("kr", p.kr);
    w.number("mu_r", p.mu_r);
  }
};

// The "no rolling resistance" alternative, so a law composes rolling at compile time.
struct NoRolling {
  static constexpr std::string_view name = "none";
  void validate() const {}
  void apply(const PairGeometry&, const RelativeMotion&, double, double, Vec3&, PairForce&) const {}
};

}  // namespace suspend

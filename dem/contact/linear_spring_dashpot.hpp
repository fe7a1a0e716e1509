// Linear spring-dashpot normal force + stick/slide tangential spring (paper 000 eqs. 4-5; Luding 2008).
//
// Contact while the spheres overlap: delta = -(gap) = a_i + a_j - r > 0. Forces ON j (n from i to j):
//   normal      F_n n,  F_n = k_n delta - gamma_n (u_j - u_i) . n          (eq. 4a, sign flipped to "on j")
//   tangential  F_t = -k_t xi,  |F_t| <= Friction::limit(F_n)                (eqs. 4b, 5)
//   torques     (l_i n) x (-F_t) on i, (-l_j n) x F_t on j                  (eqs. 4d-4e; lever arms of paper 004
//               eq. 11, l_i + l_j = r, instead of a_i, a_j: equal to O(delta) and conserving angular momentum)
// xi integrates the tangential velocity at the contact point and is rotated onto the current tangent plane each
// step (stick_slide.hpp). F_n is signed (positive = repulsive): a fast separation can make it attractive, exactly as
// eq. 4a; CoulombFriction then uses |F_n| (paper 000) and CriticalLoadFriction uses F_n - F_CL (paper 002).
// Rolling is optional and composed at compile time (RollingResistance or NoRolling).
// Contact ends when delta <= 0: the history is reset (xi(t_0) = 0 at the next contact).
// Energy of the elastic normal spring: (k_n/2) delta^2. The dashpot only dissipates: its power on the pair is
// -gamma_n ((u_j - u_i) . n)^2 <= 0.
// Units: k_n, k_t in eta_0 gammadot a_1 (so k_n is k-hat of paper 000 eq. 12 when a_0 = a_1),
//        gamma_n in eta_0 a_1 (gamma_n gammadot / k_n is the paper's damping group), forces in eta_0 gammadot a_1^2.
#pragma once
#include <string>

#include "core/error.hpp"
#include "dem/contact/coulomb_friction.hpp"
#include "dem/contact/critical_load_friction.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"
#include "dem/contact/rolling_resistance.hpp"
#include "dem/contact/stick_slide.hpp"

namespace suspend {

// Defaults: paper 000 table 1 (k-hat = 4e5, k_t/k_n = 2/7, gamma_n gammadot / k_n = 1e-7).
struct LinearSpringParams {
  double kn = 4.0e5;
  double kt = 2.0 / 7.0 * 4.0e5;
  double gamma_n = 1.0e-7 * 4.0e5;
  void validate() const {
    if (!(kn > 0.0)) throw InputError("contact.kn = " + std::to_string(kn) + " must be > 0");
    if (!(kt > 0.0)) throw InputError("contact.kt = " + std::to_string(kt) + " must be > 0");
    if (!(gamma_n >= 0.0)) throw InputError("contact.gamma_n = " + std::to_string(gamma_n) + " must be >= 0");
  }
};

template <class Friction, class Rolling = NoRolling>
struct LinearSpringDashpot {
  LinearSpringParams p;
  Friction friction;
  Rolling rolling;

  void validate() const {
    p.validate();
    friction.validate();
    rolling.validate();
  }

  // Largest gap at which the law acts (the driver's neighbour cutoff must cover it).
  double range() const { return 0.0; }

  PairForce operator()(const PairGeometry& g, const RelativeMotion& m, double dt, PairHistory& h) const {
    PairForce f;
    const double delta = -g.gap();
    if (!(delta > 0.0)) {
      h.reset();
      return f;
    }
    h.in_contact = true;
    const double f_n = p.kn * delta - p.gamma_n * (m.u_j - m.u_i).dot(g.n);
    f[Contribution::contact_normal] = f_n * g.n;

    const Vec3 u_c = m.contact_velocity(g);
    const Vec3 u_t = u_c - u_c.dot(g.n) * g.n;
    const double limit = friction.limit(f_n);
    const StickSlideResult t = stick_slide(h.tangential_stretch, g.n, u_t, dt, p.kt, limit);
    f.add_tangential(g, t.force_on_j, Contribution::contact_tangential);
    f.normal_stiffness = p.kn;
    f.tangential_stiffness = t.sliding || !(limit > 0.0) ? 0.0 : p.kt;
    f.sliding = t.sliding && limit > 0.0;

    rolling.apply(g, m, f_n, dt, h.rolling_stretch, f);
    return f;
  }

  // Elastic energy of the normal spring (the part that has a potential).
  double energy(const PairGeometry& g) const {
    const double delta = -g.gap();
    return delta > 0.0 ? 0.5 * p.kn * delta * delta : 0.0;
  }
};

using LinearSpringCoulomb = LinearSpringDashpot<CoulombFriction>;
using LinearSpringCoulombRolling = LinearSpringDashpot<CoulombFriction, RollingResistance>;
using LinearSpringCriticalLoad = LinearSpringDashpot<CriticalLoadFriction>;
using LinearSpringCriticalLoadRolling = LinearSpringDashpot<CriticalLoadFriction, RollingResistance>;

}  // namespace suspend

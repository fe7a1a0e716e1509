// A contact model composed of sub-models (as LAMMPS's granular pair style composes its own): a normal law
// (SoftRepulsion, LinearSpringDashpot, HertzAdhesive), a friction law acting through a tangential stick/slide
// spring (NoFriction, CoulombFriction, CriticalLoadFriction) and an optional rolling resistance (NoRolling,
// RollingResistance). Any normal composes with any friction and rolling.
//
// Per pair and step, forces ON j (n from i to j):
//   normal      the normal law adds F_n n (and adhesion) and returns the load L friction acts against;
//   tangential  F_t = -k_t xi, |F_t| <= Friction::limit(L)     (paper 000 eqs. 4b, 5; paper 004 eqs. 15-16),
//               k_t the normal law's tangential stiffness, xi integrated by stick_slide.hpp;
//   torques     (l_i n) x (-F_t) on i, (-l_j n) x F_t on j     (paper 000 eqs. 4d-4e, lever arms of paper 004 eq. 11);
//   rolling     Rolling::apply with the same load (paper 000 Appendix B).
// Contact ends when the normal law says so: the history is reset (xi(t_0) = 0 at the next contact). A model without
// friction, rolling or a normal law that keeps history keeps no history at all. A normal law with hysteresis (JKR)
// declares `static constexpr bool keeps_history = true` and takes the pair history in apply(g, m, f, h), keeping
// its state in h.normal_state.
#pragma once
#include <type_traits>

#include "dem/contact/coulomb_friction.hpp"
#include "dem/contact/critical_load_friction.hpp"
#include "dem/contact/hertz_adhesive.hpp"
#include "dem/contact/linear_spring_dashpot.hpp"
#include "dem/contact/no_friction.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"
#include "dem/contact/rolling_resistance.hpp"
#include "dem/contact/soft_repulsion.hpp"
#include "dem/contact/stick_slide.hpp"

namespace suspend {

// A normal law whose force depends on the pair's past (NormalContact apply(g, m, f, PairHistory&)).
template <class Normal>
concept NormalWithHistory = Normal::keeps_history;

template <class Normal, class Friction = NoFriction, class Rolling = NoRolling>
struct ContactModel {
  using normal_type = Normal;
  using friction_type = Friction;
  using rolling_type = Rolling;
  static constexpr bool has_friction = !std::is_same_v<Friction, NoFriction>;
  static constexpr bool has_rolling = !std::is_same_v<Rolling, NoRolling>;
  static constexpr bool has_history = has_friction || has_rolling || NormalWithHistory<Normal>;

  Normal normal;
  Friction friction{};
  Rolling rolling{};

  void validate() const {
    normal.validate();
    friction.validate(Normal::friction_key);  // the key the case names it by (mu or mu_s)
    rolling.validate();
  }
  double range() const { return normal.range(); }

  PairForce operator()(const PairGeometry& g, const RelativeMotion& m, double dt, PairHistory& h) const {
    PairForce f;
    NormalContact c;
    if constexpr (NormalWithHistory<Normal>)
      c = normal.apply(g, m, f, h);
    else
      c = normal.apply(g, m, f);
    if (!c.active || !has_history) {
      h.reset();
      return f;
    }
    h.in_contact = true;
    if constexpr (has_friction) {
      const Vec3 u_c = m.contact_velocity(g);
      const Vec3 u_t = u_c - u_c.dot(g.n) * g.n;
      const double limit = friction.limit(c.load);
      const double kt = normal.tangential_stiffness();
      const StickSlideResult t = stick_slide(h.tangential_stretch, g.n, u_t, dt, kt, limit);
      f.add_tangential(g, t.force_on_j, Contribution::contact_tangential);
      f.sliding = t.sliding && limit > 0.0;
      if (f.sliding) {  // the consistent tangent of the cap: stiffness across the slip (pair_geometry.hpp)
        f.tangential_stiffness = kt * limit / t.trial;
        f.slip_direction = t.force_on_j / limit;
      } else {
        f.tangential_stiffness = limit > 0.0 ? kt : 0.0;
      }
    }
    rolling.apply(g, m, c.load, dt, h.rolling_stretch, f);
    return f;
  }

  // Elastic energy of the normal law (the part that has a potential).
  double energy(const PairGeometry& g) const { return normal.energy(g); }
};

// The laws the papers use, by their usual names.
using LinearSpringCoulomb = ContactModel<LinearSpringDashpot, CoulombFriction>;
using LinearSpringCoulombRolling = ContactModel<LinearSpringDashpot, CoulombFriction, RollingResistance>;
using LinearSpringCriticalLoad = ContactModel<LinearSpringDashpot, CriticalLoadFriction>;
using LinearSpringCriticalLoadRolling = ContactModel<LinearSpringDashpot, CriticalLoadFriction, RollingResistance>;
using HertzAdhesiveCoulomb = ContactModel<HertzAdhesive, CoulombFriction>;

}  // namespace suspend

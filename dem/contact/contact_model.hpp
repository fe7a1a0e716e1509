// A contact model composed of sub-models, each a separate choice with its own keys (as LAMMPS's granular pair style
// composes normal, damping, tangential, rolling and twisting models):
//   normal      the elastic normal law (SoftRepulsion, LinearSpringDashpot, HertzAdhesive, JkrAdhesion): when the
//               pair is in contact, its normal force and load (pair_geometry.hpp NormalContact)
//   damping     NormalDamping (none, viscous, viscoelastic), added to the normal force and the load
//   adhesion    Adhesion (none, constant, dmt), an attraction while in contact; JKR carries its own
//   tangential  a linear spring of stiffness k_t (key kt; default the normal law's default_tangential_stiffness) with
//               a friction rule (NoFriction, CoulombFriction, CriticalLoadFriction) capping it:
//               F_t = -k_t xi, |F_t| <= Friction::limit(L)     (paper 000 eqs. 4b, 5; paper 004 eqs. 15-16),
//               xi integrated by stick_slide.hpp; torques (l_i n) x (-F_t) on i, (-l_j n) x F_t on j (paper 000
//               eqs. 4d-4e, lever arms of paper 004 eq. 11)
//   rolling     NoRolling or RollingResistance (paper 000 Appendix B), with the same load
//   twisting    TwistingResistance (Luding 2008 section 2.3), with the same load
// Forces are ON j (n from i to j). The friction and rolling rules are types (the contact law's variant,
// contact_law.hpp, lists every product, so the pair loop calls them directly); damping, adhesion and twisting are
// values with a cheap branch per contact. Any choice composes with any other, except that JKR takes adhesion: none.
// Contact ends when the normal law says so: the history is reset (xi(t_0) = 0 at the next contact). A model whose
// sub-models keep no history keeps none at all. A normal law with hysteresis (JKR) declares
// `static constexpr bool keeps_history = true` and takes the pair history in apply(g, m, f, h), keeping its state in
// h.normal_state.
#pragma once
#include <type_traits>

#include <cmath>
#include <limits>

#include "dem/contact/adhesion.hpp"
#include "dem/contact/coulomb_friction.hpp"
#include "dem/contact/critical_load_friction.hpp"
#include "dem/contact/hertz_adhesive.hpp"
#include "dem/contact/linear_spring_dashpot.hpp"
#include "dem/contact/no_friction.hpp"
#include "dem/contact/normal_damping.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"
#include "dem/contact/rolling_resistance.hpp"
#include "dem/contact/soft_repulsion.hpp"
#include "dem/contact/stick_slide.hpp"
#include "dem/contact/twisting_resistance.hpp"

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
  // History kept by the types alone; an active twisting (a value) keeps it as well, at run time.
  static constexpr bool has_history = has_friction || has_rolling || NormalWithHistory<Normal>;

  Normal normal;
  Friction friction{};
  Rolling rolling{};
  Adhesion adhesion{};
  NormalDamping damping{};
  TwistingResistance twisting{};
  double kt = std::numeric_limits<double>::quiet_NaN();  // k_t; NaN: the normal law's default

  double tangential_stiffness() const { return std::isnan(kt) ? normal.default_tangential_stiffness() : kt; }
  // F_adh of the a_1 pair, the scale of sigma* (0 without adhesion).
  double adhesion_force() const { return normal.adhesion_force() + adhesion.scale(); }

  void validate() const {
    normal.validate();
    friction.validate();
    rolling.validate();
    adhesion.validate();
    damping.validate();
    twisting.validate();
    if (has_friction) require(tangential_stiffness(), Range::positive(), "contact.kt");
  }
  double range() const { return normal.range(); }

  // Forced inline: the pair drivers call it once per pair in their hot loop, and grown by the sub-models it would
  // otherwise become a call per pair (13% of the force loop, bench_pairwise BM_ContactForces).
  [[gnu::always_inline]] PairForce operator()(const PairGeometry& g, const RelativeMotion& m, double dt,
                                              PairHistory& h) const {
    PairForce f;
    NormalContact c;
    if constexpr (NormalWithHistory<Normal>)
      c = normal.apply(g, m, f, h);
    else
      c = normal.apply(g, m, f);
    if (!c.active) {
      h.reset();
      return f;
    }
    if (damping.active()) {
      const double d = damping.resistance(g, m, f.normal_stiffness);
      c.force -= d;
      c.load -= d;
    }
    f[Contribution::contact_normal] = c.force * g.n;
    adhesion.apply(g, f);
    if (!has_history && !twisting.active) {
      h.reset();
      return f;
    }
    h.in_contact = true;
    if constexpr (has_friction) {
      const Vec3 u_c = m.contact_velocity(g);
      const Vec3 u_t = u_c - u_c.dot(g.n) * g.n;
      const double limit = friction.limit(c.load);
      const double k = tangential_stiffness();
      const StickSlideResult t = stick_slide(h.tangential_stretch, g.n, u_t, dt, k, limit);
      f.add_tangential(g, t.force_on_j, Contribution::contact_tangential);
      f.sliding = t.sliding && limit > 0.0;
      if (f.sliding) {  // the consistent tangent of the cap: stiffness across the slip (pair_geometry.hpp)
        f.tangential_stiffness = k * limit / t.trial;
        f.slip_direction = t.force_on_j / limit;
      } else {
        f.tangential_stiffness = limit > 0.0 ? k : 0.0;
      }
    }
    rolling.apply(g, m, c.load, dt, h.rolling_stretch, f);
    twisting.apply(g, m, c.load, dt, h.twisting_stretch, f);
    return f;
  }

  // The potential of the conservative parts: the normal law's elastic energy and the adhesion's.
  double energy(const PairGeometry& g) const { return normal.energy(g) + adhesion.energy(g, normal.range()); }
};

// The laws the papers use, by their usual names.
using LinearSpringCoulomb = ContactModel<LinearSpringDashpot, CoulombFriction>;
using LinearSpringCoulombRolling = ContactModel<LinearSpringDashpot, CoulombFriction, RollingResistance>;
using LinearSpringCriticalLoad = ContactModel<LinearSpringDashpot, CriticalLoadFriction>;
using LinearSpringCriticalLoadRolling = ContactModel<LinearSpringDashpot, CriticalLoadFriction, RollingResistance>;
using HertzAdhesiveCoulomb = ContactModel<HertzAdhesive, CoulombFriction>;

}  // namespace suspend

// The contact model of a run: one contact law composed with optional surface forces, chosen at set-up.
//
//   ContactLaw = std::variant<ComposedLaw<SoftRepulsion>, ComposedLaw<LinearSpring...>, ComposedLaw<HertzAdhesive>>
// Every alternative has the same call shape, PairForce law(geometry, motion, dt, history), returns forces ON j by
// contribution and torques on i and j (pair_geometry.hpp), and updates the pair history in place (in_contact false
// when the pair carries no history any more). A driver visits the variant once per step (with_law or
// evaluate_pairs) and loops over pairs inside, so the inner loop calls the concrete law directly: no virtual call,
// no per-pair dispatch (STYLE.md habit 6).
#pragma once
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <cstddef>
#include <utility>
#include <variant>

#include "dem/contact/hertz_adhesive.hpp"
#include "dem/contact/linear_spring_dashpot.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"
#include "dem/contact/soft_repulsion.hpp"
#include "dem/contact/surface_forces.hpp"

namespace suspend {

template <class Contact>
struct ComposedLaw {
  Contact contact;
  SurfaceForces surface;

  void validate() const {
    contact.validate();
    surface.validate();
  }
  // Largest surface gap at which the pair interacts: the neighbour list must reach at least this far.
  double range() const { return std::max(contact.range(), surface.range()); }

  PairForce operator()(const PairGeometry& g, const RelativeMotion& m, double dt, PairHistory& h) const {
    PairForce f;
    if constexpr (requires { contact(g, m, dt, h); }) {
      f = contact(g, m, dt, h);
    } else {  // history-free contact laws
      f = contact(g);
      h.reset();
    }
    surface.add_to(g, f);
    return f;
  }
  double energy(const PairGeometry& g) const { return contact.energy(g) + surface.energy(g); }
};

using ContactLaw =
    std::variant<ComposedLaw<SoftRepulsion>, ComposedLaw<LinearSpringCoulomb>, ComposedLaw<LinearSpringCoulombRolling>,
                 ComposedLaw<LinearSpringCriticalLoad>, ComposedLaw<LinearSpringCriticalLoadRolling>,
                 ComposedLaw<HertzAdhesive>>;

inline void validate(const ContactLaw& law) {
  std::visit([](const auto& l) { l.validate(); }, law);
}
inline double interaction_range(const ContactLaw& law) {
  return std::visit([](const auto& l) { return l.range(); }, law);
}

// A linear stiffness scale of the law (eta_0 gammadot a_1): the explicit time step must resolve 6 pi eta a / k.
// Hertz: dF/d delta = (3/2) k_n sqrt(delta) at the largest compression h_r, stiffened by the supplementary wall.
inline double stiffness_scale(const ContactLaw& law) {
  return std::visit(
      [](const auto& l) -> double {
        const auto& c = l.contact;
        if constexpr (std::is_same_v<std::decay_t<decltype(c)>, HertzAdhesive>) {
          const HertzAdhesiveParams& p = c.params();
          return 1.5 * p.kn * std::sqrt(p.roughness) * (1.0 + p.repulsion_stiffness * std::sqrt(p.repulsion_onset));
        } else {
          return c.p.kn;
        }
      },
      law);
}

// Calls fn(concrete_law) once: a driver templated on the law writes its pair loop inside fn.
template <class Fn>
decltype(auto) with_law(const ContactLaw& law, Fn&& fn) {
  return std::visit(std::forward<Fn>(fn), law);
}

// Evaluates pairs k in [begin, end) with one visit: pair(k) returns a PairState, history(k) the pair's history
// (updated in place), sink(k, const PairForce&) consumes the result. Threaded drivers call it on disjoint chunks.
struct PairState {
  PairGeometry geometry;
  RelativeMotion motion;
};
template <class PairFn, class HistoryFn, class SinkFn>
void evaluate_pairs(const ContactLaw& law, std::size_t begin, std::size_t end, double dt, PairFn&& pair,
                    HistoryFn&& history, SinkFn&& sink) {
  std::visit(
      [&](const auto& l) {
        for (std::size_t k = begin; k < end; ++k) {
          const PairState s = pair(k);
          sink(k, l(s.geometry, s.motion, dt, history(k)));
        }
      },
      law);
}

// The constant adhesion force F_adh of the Hertz-adhesive law (paper 004 eq. 16), 0 for laws without adhesion:
// it sets the stress scale sigma* = 6 pi Sigma_xy a_1^2 / F_adh and G_adh = F_adh / (6 pi eta a_1^2 gammadot).
inline double adhesion_force(const ContactLaw& law) {
  return std::visit(
      [](const auto& l) -> double {
        if constexpr (std::is_same_v<std::decay_t<decltype(l.contact)>, HertzAdhesive>)
          return l.contact.pull_off_force();
        else
          return 0.0;
      },
      law);
}

}  // namespace suspend

// The contact model of a run: a composed contact model (contact_model.hpp) plus optional surface forces, chosen at
// set-up from the registered sub-models below.
//
//   ContactLaw = std::variant<ComposedLaw<ContactModel<N, F, R>>...> over every normal law N, friction F, rolling R
// Every alternative has the same call shape, PairForce law(geometry, motion, dt, history), returns forces ON j by
// contribution and torques on i and j (pair_geometry.hpp), and updates the pair history in place (in_contact false
// when the pair carries no history any more). A driver visits the variant once per step (with_law) and
// loops over pairs inside, so the inner loop calls the concrete law directly: no virtual call,
// no per-pair dispatch in the hot loop.
//
// A new normal or friction law: its file (a struct with name, documentation, parameters, apply, energy, read and
// write, as hertz_adhesive.hpp), one line in NormalLaws or FrictionLaws below, and its test. The case reader and
// writer (io/contact_case.cpp) and every driver follow from the lists. Damping, adhesion and twisting are values
// inside every model (normal_damping.hpp, adhesion.hpp, twisting_resistance.hpp): a new model of one of them is a
// branch in its file.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <variant>
#include <vector>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/jkr_adhesion.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"
#include "dem/contact/surface_forces.hpp"

namespace suspend {

template <class... T>
struct TypeList {};

// The registered sub-models: one line each.
using NormalLaws = TypeList<SoftRepulsion, LinearSpringDashpot, HertzAdhesive, JkrAdhesion>;
using FrictionLaws = TypeList<NoFriction, CoulombFriction, CriticalLoadFriction>;
using RollingLaws = TypeList<NoRolling, RollingResistance>;

// Contact parameters that differ per pair of species (a symmetric species x species table), empty when every pair
// takes the law's own. Same law, friction and rolling for every pair; only their parameters differ.
template <class Contact>
struct SpeciesPairTable {
  int species = 0;
  std::vector<Contact> table;                 // table[s_i * species + s_j]
  std::vector<std::array<int, 2>> given;      // the pairs a case set, in its order (to write it back)
  bool empty() const { return table.empty(); }
  const Contact& of(int s_i, int s_j) const { return table[static_cast<std::size_t>(s_i * species + s_j)]; }
};

template <class Contact>
struct ComposedLaw {
  Contact contact;  // every species pair without its own parameters
  SurfaceForces surface;
  SpeciesPairTable<Contact> pairs{};

  // Gives the species pair (s_i, s_j) its own parameters; the others keep `contact`.
  void set_pair(int s_i, int s_j, const Contact& c, int species) {
    if (pairs.empty()) {
      pairs.species = species;
      pairs.table.assign(static_cast<std::size_t>(species * species), contact);
    }
    pairs.table[static_cast<std::size_t>(s_i * species + s_j)] = c;
    pairs.table[static_cast<std::size_t>(s_j * species + s_i)] = c;
    pairs.given.push_back({s_i, s_j});
  }
  const Contact& contact_of(int s_i, int s_j) const { return pairs.empty() ? contact : pairs.of(s_i, s_j); }

  void validate() const {
    contact.validate();
    for (const Contact& c : pairs.table) c.validate();
    surface.validate();
  }
  // Largest gap at which the contact law of any species pair acts.
  double contact_range() const {
    double r = contact.range();
    for (const Contact& c : pairs.table) r = std::max(r, c.range());
    return r;
  }
  // Largest surface gap at which the pair interacts: the neighbour list must reach at least this far.
  double range() const { return std::max(contact_range(), surface.range()); }
  double stiffness_scale() const {
    double k = contact.normal.stiffness_scale();
    for (const Contact& c : pairs.table) k = std::max(k, c.normal.stiffness_scale());
    return k;
  }

  // A pair of species s_i, s_j (the pair drivers' call, once per pair of their hot loop: forced inline, as the
  // contact model's own call).
  [[gnu::always_inline]] PairForce operator()(int s_i, int s_j, const PairGeometry& g, const RelativeMotion& m,
                                              double dt, PairHistory& h) const {
    PairForce f = contact_of(s_i, s_j)(g, m, dt, h);
    surface.add_to(g, f);
    return f;
  }
  // A pair of species 0 (or of a law without a species table).
  [[gnu::always_inline]] PairForce operator()(const PairGeometry& g, const RelativeMotion& m, double dt,
                                              PairHistory& h) const {
    return (*this)(0, 0, g, m, dt, h);
  }
  double energy(const PairGeometry& g) const { return contact.energy(g) + surface.energy(g); }
};

namespace detail {
template <class... Lists>
struct Concat {
  using type = TypeList<>;
};
template <class... A>
struct Concat<TypeList<A...>> {
  using type = TypeList<A...>;
};
template <class... A, class... B, class... Rest>
struct Concat<TypeList<A...>, TypeList<B...>, Rest...> : Concat<TypeList<A..., B...>, Rest...> {};

template <class N, class F, class Rs>
struct WithRolling;
template <class N, class F, class... R>
struct WithRolling<N, F, TypeList<R...>> {
  using type = TypeList<ComposedLaw<ContactModel<N, F, R>>...>;
};
template <class N, class Fs, class Rs>
struct WithFriction;
template <class N, class... F, class Rs>
struct WithFriction<N, TypeList<F...>, Rs> : Concat<typename WithRolling<N, F, Rs>::type...> {};
template <class Ns, class Fs, class Rs>
struct Product;
template <class... N, class Fs, class Rs>
struct Product<TypeList<N...>, Fs, Rs> : Concat<typename WithFriction<N, Fs, Rs>::type...> {};

template <class L>
struct AsVariant;
template <class... T>
struct AsVariant<TypeList<T...>> {
  using type = std::variant<T...>;
};
}  // namespace detail

using ContactLaw = detail::AsVariant<detail::Product<NormalLaws, FrictionLaws, RollingLaws>::type>::type;

inline void validate(const ContactLaw& law) {
  std::visit([](const auto& l) { l.validate(); }, law);
}
inline double interaction_range(const ContactLaw& law) {
  return std::visit([](const auto& l) { return l.range(); }, law);
}

// A linear stiffness scale of the law (eta_0 gammadot a_1): the explicit time step must resolve 6 pi eta a / k.
// With a species-pair table: the stiffest pair's.
inline double stiffness_scale(const ContactLaw& law) {
  return std::visit([](const auto& l) { return l.stiffness_scale(); }, law);
}

// Calls fn(concrete_law) once: a driver templated on the law writes its pair loop inside fn.
template <class Fn>
decltype(auto) with_law(const ContactLaw& law, Fn&& fn) {
  return std::visit(std::forward<Fn>(fn), law);
}

// The adhesion force F_adh of the a_1 pair (paper 004 eq. 16; JKR's pull-off), 0 without adhesion: it sets the
// stress scale sigma* = 6 pi Sigma_xy a_1^2 / F_adh and G_adh = F_adh / (6 pi eta a_1^2 gammadot). With a
// species-pair table, the case's own F_adh (the paper's scale is that of the a_1 spheres, species 0).
inline double adhesion_force(const ContactLaw& law) {
  return std::visit([](const auto& l) { return l.contact.adhesion_force(); }, law);
}

}  // namespace suspend

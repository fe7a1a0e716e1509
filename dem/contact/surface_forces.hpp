// Non-contact surface forces added on top of any contact law: electrostatic repulsion (paper 000 eq. 6) and
// van der Waals attraction (eq. 7), each optional. Conservative, no history, no torque.
#pragma once
#include <algorithm>
#include <optional>

#include "dem/contact/electrostatic_repulsion.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/van_der_waals.hpp"

namespace suspend {

struct SurfaceForces {
  std::optional<ElectrostaticRepulsion> repulsion;
  std::optional<VanDerWaals> attraction;

  void validate() const {
    if (repulsion) repulsion->validate();
    if (attraction) attraction->validate();
  }
  // Largest gap at which a surface force acts (0 when none is set).
  double range() const {
    return std::max(repulsion ? repulsion->range() : 0.0, attraction ? attraction->range() : 0.0);
  }
  void add_to(const PairGeometry& g, PairForce& f) const {
    if (repulsion) f[Contribution::repulsion] += repulsion->magnitude(g.gap(), g.harmonic_radius()) * g.n;
    if (attraction) f[Contribution::adhesion] -= attraction->magnitude(g.gap(), g.harmonic_radius()) * g.n;
  }
  double energy(const PairGeometry& g) const {
    return (repulsion ? repulsion->energy(g) : 0.0) + (attraction ? attraction->energy(g) : 0.0);
  }
};

}  // namespace suspend

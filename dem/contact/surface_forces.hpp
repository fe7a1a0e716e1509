// Non-contact surface forces added on top of any contact law: electrostatic repulsion (paper 000 eq. 6) and
// van der Waals attraction (eq. 7), each optional. Conservative, no history, no torque.
#pragma once
#include <algorithm>
#include <optional>
#include <string>

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
  // Each force present, in the order of a case: fn(force) with the force's own name, read and write.
  template <class Fn>
  void for_each(Fn&& fn) const {
    if (repulsion) fn(*repulsion);
    if (attraction) fn(*attraction);
  }
  // Reads the blocks a case gives (r.has(name), r.child(name)); each force reads its own keys.
  template <class Reader>
  static SurfaceForces read(Reader& r) {
    SurfaceForces s;
    auto block = [&]<class Force>(std::optional<Force>& out) {
      if (!r.has(std::string(Force::name))) return;
      auto c = r.child(std::string(Force::name));
      out = Force::read(c);
      c.finish();
    };
    block(s.repulsion);
    block(s.attraction);
    return s;
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

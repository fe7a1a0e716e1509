// Electrostatic (screened double-layer) repulsion (paper 000, eq. 6).
//
//   F_j = F_ER (a-bar / a_0) exp(-h / lambda_D) n   for gap h >= 0,
//   F_j = F_ER (a-bar / a_0) n                      for h < 0 (constant through overlap),
// force ON j, n from i to j (eq. 6a gives the force on i, -F_j), a-bar = 2 a_i a_j / (a_i + a_j).
// Truncated (not shifted) beyond h = cutoff; paper 000 Fig. 3 lets it act below 20 lambda_D, our default.
// Energy (zero at infinity): F_ER (a-bar/a_0) lambda_D exp(-h/lambda_D) for h >= 0, continued linearly,
// F_ER (a-bar/a_0) (lambda_D - h), for h < 0; F_j = -dE/dr_j. Goes to Contribution::repulsion; no torque.
// Units: lengths in a_1 with a_0 = a_1 = 1 (so a-bar/a_0 = a-bar), F_ER in eta_0 gammadot a_1^2: for equal spheres
// F_ER is the contact force, gamma-hat of paper 000 eq. 14 when gammadot is the reference rate.
#pragma once
#include <cmath>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

// Defaults: paper 000 table 3 (lambda_D = 0.02 a_0, gamma-hat = 1).
struct ElectrostaticRepulsionParams {
  double force = 1.0;           // F_ER
  double debye_length = 0.02;   // lambda_D
  double cutoff_in_debye = 20;  // acts for gap < cutoff_in_debye * lambda_D
  void validate() const {
    if (!(force >= 0.0)) throw InputError("repulsion.force = " + std::to_string(force) + " must be >= 0");
    if (!(debye_length > 0.0))
      throw InputError("repulsion.debye_length = " + std::to_string(debye_length) + " must be > 0");
    if (!(cutoff_in_debye > 0.0))
      throw InputError("repulsion.cutoff_in_debye = " + std::to_string(cutoff_in_debye) + " must be > 0");
  }
};

struct ElectrostaticRepulsion {
  static constexpr std::string_view name = "repulsion";  // its block in the contact section of a case
  ElectrostaticRepulsionParams p;
  void validate() const { p.validate(); }

  // The `repulsion` block: {force, debye_length, cutoff_in_debye}.
  template <class Reader>
  static ElectrostaticRepulsion read(Reader& r) {
    ElectrostaticRepulsion out;
    out.p.force = r.number("force", out.p.force, Range::non_negative());
    out.p.debye_length = r.number("debye_length", out.p.debye_length, Range::positive());
    out.p.cutoff_in_debye = r.number("cutoff_in_debye", out.p.cutoff_in_debye, Range::positive());
    return out;
  }
  template <class Writer>
  void write(Writer& w) const {
    w.number("force", p.force);
    w.number("debye_length", p.debye_length);
    w.number("cutoff_in_debye", p.cutoff_in_debye);
  }
  double range() const { return p.cutoff_in_debye * p.debye_length; }

  // Magnitude on j along +n (repulsive) at gap h, for harmonic radius a_bar.
  double magnitude(double h, double a_bar) const {
    if (h >= range()) return 0.0;
    return p.force * a_bar * (h >= 0.0 ? std::exp(-h / p.debye_length) : 1.0);
  }
  PairForce operator()(const PairGeometry& g) const {
    PairForce f;
    f[Contribution::repulsion] = magnitude(g.gap(), g.harmonic_radius()) * g.n;
    return f;
  }
  double energy(const PairGeometry& g) const {
    const double h = g.gap();
    if (h >= range()) return 0.0;
    const double scale = p.force * g.harmonic_radius();
    return h >= 0.0 ? scale * p.debye_length * std::exp(-h / p.debye_length) : scale * (p.debye_length - h);
  }
};

}  // namespace suspend

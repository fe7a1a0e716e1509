// Regularised van der Waals attraction (paper 000, eq. 7).
//
//   F_j = -A a-bar / (12 (h^2 + eps^2)) n   for gap h >= 0,
//   F_j = -A a-bar / (12 eps^2) n           for h < 0,
// force ON j, n from i to j (attractive: j is pulled towards i; eq. 7a gives the force on i, +A.. n).
// a-bar = 2 a_i a_j / (a_i + a_j); eps = epsilon_rel * a-bar (paper: "generally eps ~ 0.01 a-bar") removes the
// contact singularity. Truncated (not shifted) beyond h = cutoff (paper 000 Fig. 3: below 4 a_0, our default).
// Energy (zero at infinity): -(A a-bar / (12 eps)) (pi/2 - atan(h/eps)) for h >= 0, continued linearly with slope
// A a-bar / (12 eps^2) for h < 0; F_j = -dE/dr_j. Goes to Contribution::adhesion; no torque.
// Units: A (Hamaker constant) in eta_0 gammadot a_1^3, lengths in a_1.
#pragma once
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

// Defaults: paper 000 table 3 ratio F^R / F^A = 19 at contact with F_ER = 1: A a-bar / (12 eps^2) = 1/19 for
// equal unit spheres, eps = 0.01, so A = 12e-4 / 19.
struct VanDerWaalsParams {
  double hamaker = 12.0e-4 / 19.0;  // A
  double epsilon_rel = 0.01;        // eps / a-bar
  double cutoff = 4.0;              // acts for gap < cutoff (in a_1)
  void validate() const {
    if (!(hamaker >= 0.0)) throw InputError("attraction.hamaker = " + std::to_string(hamaker) + " must be >= 0");
    if (!(epsilon_rel > 0.0))
      throw InputError("attraction.epsilon = " + std::to_string(epsilon_rel) + " must be > 0");
    if (!(cutoff > 0.0)) throw InputError("attraction.cutoff = " + std::to_string(cutoff) + " must be > 0");
  }
};

struct VanDerWaals {
  static constexpr std::string_view name = "attraction";  // its block in the contact section of a case
  VanDerWaalsParams p;
  void validate() const { p.validate(); }

  // The `attraction` block: {hamaker, epsilon, cutoff}.
  template <class Reader>
  static VanDerWaals read(Reader& r) {
    VanDerWaals out;
    out.p.hamaker = r.number("hamaker", out.p.hamaker, Range::non_negative());
    out.p.epsilon_rel = r.number("epsilon", out.p.epsilon_rel, Range::positive());
    out.p.cutoff = r.number("cutoff", out.p.cutoff, Range::positive());
    return out;
  }
  template <class Writer>
  void write(Writer& w) const {
    w.number("hamaker", p.hamaker);
    w.number("epsilon", p.epsilon_rel);
    w.number("cutoff", p.cutoff);
  }
  double range() const { return p.cutoff; }

  // Magnitude on j along -n (attractive) at gap h, for harmonic radius a_bar.
  double magnitude(double h, double a_bar) const {
    if (h >= p.cutoff) return 0.0;
    const double eps = p.epsilon_rel * a_bar;
    const double h2 = h >= 0.0 ? h * h : 0.0;
    return p.hamaker * a_bar / (12.0 * (h2 + eps * eps));
  }
  PairForce operator()(const PairGeometry& g) const {
    PairForce f;
    f[Contribution::adhesion] = -magnitude(g.gap(), g.harmonic_radius()) * g.n;
    return f;
  }
  double energy(const PairGeometry& g) const {
    const double h = g.gap();
    if (h >= p.cutoff) return 0.0;
    const double a_bar = g.harmonic_radius();
    const double eps = p.epsilon_rel * a_bar;
    const double scale = p.hamaker * a_bar / (12.0 * eps);
    if (h >= 0.0) return -scale * (0.5 * std::numbers::pi - std::atan(h / eps));
    return -scale * 0.5 * std::numbers::pi + scale * h / eps;
  }
};

}  // namespace suspend

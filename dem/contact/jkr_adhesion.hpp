// JKR adhesive elastic contact with hysteresis (Johnson, Kendall & Roberts, Proc. R. Soc. Lond. A 324, 301
// (1971)), a normal sub-model. E* is the effective modulus (1/E* = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j), W the
// work of adhesion (energy per area; 2 gamma for like surfaces), R* = a_i a_j / (a_i + a_j), delta = -h the
// overlap of the surfaces. On the bonded branch, with c = sqrt(2 pi W / E*) and contact radius a:
//   delta = a^2 / R* - c sqrt(a)
//   F_n   = 4 E* a^3 / (3 R*) - 2 E* c a^(3/2)      (= Hertz - sqrt(8 pi W E* a^3); positive = repulsive, on j: F_n n)
// Hysteresis, kept in the pair history's normal_state (the contact radius a, > 0 while bonded):
//   approach    no force while h > 0; the pair bonds when the surfaces touch (h <= 0), jumping to the stable root
//               (at delta = 0: a^(3/2) = c R*, F_n = -(4/3) pi W R*);
//   retraction  the bond holds through tension past h = 0 (a neck) while delta >= delta_c =
//               -(3/4) (pi^2 W^2 R* / E*^2)^(1/3), where a reaches a_s = (pi W R*^2 / (8 E*))^(1/3) and
//               d delta / d a = 0; beyond it the neck snaps (F_n = -(5/6) pi W R* just before). On the way the
//               tension peaks at -F_n = (3/2) pi W R*, the JKR pull-off force (at a^(3/2) = 3 c R* / 4).
// The stable root is found by Newton's method in sqrt(a), started to its right: f(x) = x^4 / R* - c x - delta is
// convex and increasing there, so the iterates fall monotonically onto it.
// Split: the Hertz part 4 E* a^3 / (3 R*) goes to contact_normal, -2 E* c a^(3/2) to adhesion.
// Friction (a friction sub-model composed with it): its load is F_n + 2 F_po, F_po = (3/2) pi W R* (Thornton &
// Yin, Powder Technol. 65, 153 (1991): JKR contacts slide at mu (F_n + 2 F_po)); k_t = (2/7) 2 E* a_0 with a_0 =
// (9 pi W R*^2 / (2 E*))^(1/3) the zero-load radius of the a_1 pair (R* = a_1 / 2), a constant as in the Hertz law.
// The neighbour range reaches -delta_c of pairs with R* up to 5 a_1; the time-step scale is 2 E* (2 a_0).
// Energy along the bonded branch (delta >= delta_c; it has no history, so it does not know whether a pair between
// delta_c and 0 is bonded): U(a) = 8 E* a^5 / (15 R*^2) - (4/3) E* c a^(7/2) / R* + E* c^2 a^2 / 2, U(0) = 0,
// F_n = dU / d delta.
// Units: lengths in a_1, E* and W in eta_0 gammadot_ref (W: per a_1), forces in eta_0 gammadot_ref a_1^2.
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

#include "core/error.hpp"
#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"

namespace suspend {

struct JkrParams {
  double modulus = 1.0e4;          // E*
  double work_of_adhesion = 1.0;   // W
  void validate() const {
    require(modulus, Range::positive(), "contact.modulus");
    require(work_of_adhesion, Range::non_negative(), "contact.work_of_adhesion");
  }
};

class JkrAdhesion {
 public:
  static constexpr std::string_view name = "jkr";
  static constexpr std::string_view documentation = "docs/contact.md, section 'JKR adhesion'";
  static constexpr std::string_view stiffness_keys = "contact.modulus";
  static constexpr std::string_view default_friction = "none";
  static constexpr double default_mu = 1.0;
  static constexpr std::string_view default_adhesion = "none";  // its adhesion is its own
  static constexpr double default_g_adh = 0.0;
  static constexpr bool keeps_history = true;
  static constexpr double max_reduced_radius = 5.0;  // R* the neighbour range covers

  JkrAdhesion() : JkrAdhesion(JkrParams{}) {}
  explicit JkrAdhesion(const JkrParams& p)
      : p_(p), c_(std::sqrt(2.0 * std::numbers::pi * p.work_of_adhesion / p.modulus)) {
    p_.validate();
  }
  const JkrParams& params() const { return p_; }
  void validate() const { p_.validate(); }

  double pull_off_force(double r) const { return 1.5 * std::numbers::pi * p_.work_of_adhesion * r; }
  // delta_c < 0: the overlap at which a bonded pair of reduced radius r snaps.
  double snap_overlap(double r) const {
    const double w = p_.work_of_adhesion, e = p_.modulus;
    return -0.75 * std::cbrt(std::numbers::pi * std::numbers::pi * w * w * r / (e * e));
  }
  double zero_load_radius(double r) const {
    return std::cbrt(9.0 * std::numbers::pi * p_.work_of_adhesion * r * r / (2.0 * p_.modulus));
  }
  // The stable root a(delta) of a bonded pair (delta >= snap_overlap(r)).
  double contact_radius(double delta, double r) const {
    // x = sqrt(a): f(x) = x^4 / r - c x - delta; start where x^4 / r >= 2 c x and >= 2 delta (so f >= 0), which is
    // also right of the turning point x_s^3 = c r / 4.
    double x = std::max(std::cbrt(2.0 * r * c_), std::sqrt(std::sqrt(2.0 * r * std::max(delta, 0.0))));
    for (int k = 0; k < 200; ++k) {
      const double f = x * x * x * x / r - c_ * x - delta, slope = 4.0 * x * x * x / r - c_;
      if (!(slope > 0.0)) break;
      const double step = f / slope;
      x -= step;
      if (std::abs(step) <= 1e-15 * x) break;
    }
    return x * x;
  }

  double range() const { return -snap_overlap(max_reduced_radius); }
  double stiffness_scale() const { return 2.0 * p_.modulus * 2.0 * zero_load_radius(0.5); }
  double secant_stiffness() const { return 2.0 * p_.modulus * zero_load_radius(0.5); }
  double default_tangential_stiffness() const { return 2.0 / 7.0 * secant_stiffness(); }
  double adhesion_force() const { return pull_off_force(0.5); }

  NormalContact apply(const PairGeometry& g, const RelativeMotion&, PairForce& f, PairHistory& h) const {
    const double r = 0.5 * g.harmonic_radius();  // R*
    const double delta = -g.gap();
    const bool bonded = h.normal_state > 0.0;
    if (!(delta >= (bonded ? snap_overlap(r) : 0.0))) {
      h.normal_state = 0.0;
      return {};
    }
    const double a = contact_radius(delta, r);
    if (!(a > 0.0)) {  // W = 0 at delta = 0: Hertz without a contact
      h.normal_state = 0.0;
      return {};
    }
    h.normal_state = a;
    const double e = p_.modulus, sqrt_a = std::sqrt(a);
    const double hertz = 4.0 * e * a * a * a / (3.0 * r), adhesion = 2.0 * e * c_ * a * sqrt_a;
    f[Contribution::adhesion] = -adhesion * g.n;
    // dF/d delta = (dF/da) / (d delta/da), infinite at the snap; a negative tangent (the neck) is left to the force.
    const double dfda = 4.0 * e * a * a / r - 3.0 * e * c_ * sqrt_a, ddda = 2.0 * a / r - 0.5 * c_ / sqrt_a;
    f.normal_stiffness = ddda > 0.0 ? std::max(dfda / ddda, 0.0) : 0.0;
    return {true, hertz - adhesion + 2.0 * pull_off_force(r), hertz};
  }

  double energy(const PairGeometry& g) const {
    const double r = 0.5 * g.harmonic_radius(), delta = -g.gap();
    if (!(delta >= snap_overlap(r))) return 0.0;
    const double a = contact_radius(delta, r), e = p_.modulus;
    return 8.0 * e * std::pow(a, 5) / (15.0 * r * r) - 4.0 / 3.0 * e * c_ * std::pow(a, 3.5) / r +
           0.5 * e * c_ * c_ * a * a;
  }

  template <class Reader>
  static JkrAdhesion read(Reader& rd) {
    JkrParams p;
    p.modulus = rd.number("modulus", p.modulus, Range::positive());
    p.work_of_adhesion = rd.number("work_of_adhesion", p.work_of_adhesion, Range::non_negative());
    return JkrAdhesion(p);
  }
  template <class Writer>
  void write(Writer& w) const {
    w.number("modulus", p_.modulus);
    w.number("work_of_adhesion", p_.work_of_adhesion);
  }

 private:
  JkrParams p_;
  double c_;
};

}  // namespace suspend

// Hertz contact at a roughness height, the normal sub-model of paper 004's adhesive contact (section II D, eqs.
// 14-18). Its constant adhesion -F_adh (eq. 14) is the adhesion sub-model (adhesion.hpp), `adhesion: constant` with
// paper 004's g_adh = 0.9 by default for this law; `adhesion: none` is Hertz without adhesion.
//
// Contact while the surface gap h is below the roughness height h_r: compression delta = h_r - h > 0
// (no overlap needed; the spheres' hydrodynamic surfaces stay apart by h). Forces ON j (n from i to j):
//   normal      F_n n,  F_n = k_n delta^(3/2) - F_adh          (eq. 14; positive = repulsive)
//               the Hertz part goes to contact_normal, -F_adh n (the adhesion sub-model) to adhesion
//   tangential  (a friction sub-model composed with it, contact_model.hpp) F_t = -k_t Y (Y = tangential stretch,
//               eq. 15); its load is the elastic force F_n + F_adh = k_n delta^(3/2): Coulomb friction slides at
//               mu_s (F_n + F_adh) (eq. 16), critical-load friction acts once F_n + F_adh exceeds F_CL.
//               default k_t = (2/7) k_n sqrt(delta_bar), delta_bar = eps_bar h_r the typical compression
//               (eqs. 17-18): the classic 2/7 tangential/normal ratio applied to the Hertz secant stiffness
//               F/delta = k_n sqrt(delta) at the typical compression, so k_t is a constant [force/length].
//   torques     at the contact point, lever arms of eq. 11.
//   rolling     (optional sub-model) default k_r = k_n sqrt(delta_bar) / 100, the secant stiffness over 100 as for
//               the linear spring; its limit mu_r (F_n + F_adh).
// Zero-force compression delta_0 = (F_adh / k_n)^(2/3); pull-off force F_adh (the tension at delta -> 0+, where
// friction vanishes too). No hysteresis: the contact ends as soon as delta <= 0 (paper 004 after eq. 16).
//
// Supplementary repulsion near hydrodynamic contact. Paper 004 (end of section II D) only says that "a
// supplementary repulsive force is activated as particles approach hydrodynamic contact" to prevent overlap under
// high stress; it gives neither formula nor parameters. Our choice, documented in docs/contact.md:
//   F_s = k_s (h_s - h)^(3/2) n on j for h < h_s, with h_s = repulsion_onset * h_r and k_s = repulsion_stiffness
//   * k_n (defaults 0.1 and 100: inactive at the typical compression 0.05 h_r, and it multiplies the stiffness of
//   the last tenth of the roughness by 100). It is conservative, goes to contact_normal, and does not enter the
//   friction limit (eq. 16 involves eq. 14 only). repulsion_stiffness = 0 switches it off.
// Energy: (2/5) k_n delta^(5/2) + (2/5) k_s (h_s - h)^(5/2) (the adhesion adds -F_adh delta); F_j = -dE/dr_j.
// Units: lengths in a_1, forces in eta_0 gammadot a_1^2, k_n in eta_0 gammadot a_1^(1/2), k_t in eta_0 gammadot a_1.
#pragma once
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>

#include "core/error.hpp"
#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

// Defaults: paper 004 FDM/FCM set-up: h_r = 5e-3 a_1, eps_bar = 5e-2, Gamma-bar = 1 (k_n from eq. 17 with
// gammadot_0 = 1); the adhesion's G_adh with Gamma-bar x G_adh = 0.9 (section II E 2) and mu_s = 0.5 are this law's
// defaults for the adhesion and friction sub-models.
struct HertzAdhesiveParams {
  double roughness = 5.0e-3;                                                   // h_r
  double eps_bar = 5.0e-2;                                                     // delta_bar / h_r
  double kn = 6.0 * std::numbers::pi / std::pow(5.0e-2 * 5.0e-3, 1.5);         // Gamma-bar = 1
  double repulsion_onset = 0.1;      // h_s / h_r
  double repulsion_stiffness = 1.0e2;  // k_s / k_n
  // Paper 004's group as the case gave it (NaN when k_n was set directly): written back as given, since recomputed
  // from k_n it moves in the last digit and a resolved case must read back to itself.
  double gamma_bar = std::numeric_limits<double>::quiet_NaN();
  void validate() const {
    require(roughness, Range::positive(), "contact.roughness");
    require(eps_bar, Range::positive(), "contact.eps_bar");
    // k_n is what gamma_bar (with eps_bar, roughness) sets (paper 004 eq. 17).
    require(kn, Range::positive(), "contact.gamma_bar (through the Hertz stiffness k_n it sets)");
    require(repulsion_stiffness, Range::non_negative(), "contact.repulsion_stiffness");
    require(repulsion_onset, Range::closed(0.0, 1.0), "contact.repulsion_onset");
  }
};

// Paper 004's dimensionless group -> parameters, forces in eta_0 gammadot_0 a_1^2 (a_1 = 1):
// Gamma-bar = 6 pi / (k_n (eps_bar h_r)^(3/2)) (eq. 17).
inline HertzAdhesiveParams hertz_from_groups(double gamma_bar, double eps_bar, double roughness) {
  require(gamma_bar, Range::positive(), "contact.gamma_bar");
  HertzAdhesiveParams p;
  p.roughness = roughness;
  p.eps_bar = eps_bar;
  p.kn = 6.0 * std::numbers::pi / (gamma_bar * std::pow(eps_bar * roughness, 1.5));
  p.gamma_bar = gamma_bar;
  p.validate();
  return p;
}

class HertzAdhesive {
 public:
  static constexpr std::string_view name = "hertz_adhesive";
  static constexpr std::string_view documentation = "docs/contact.md, section 'Hertz + constant adhesion at roughness height'";
  static constexpr std::string_view stiffness_keys =
      "contact.gamma_bar, eps_bar, roughness and repulsion_stiffness";
  static constexpr std::string_view default_friction = "coulomb";
  static constexpr double default_mu = 0.5;  // paper 004's mu_s
  static constexpr std::string_view default_adhesion = "constant";
  static constexpr double default_g_adh = 0.9;  // paper 004 section II E 2

  HertzAdhesive() : HertzAdhesive(HertzAdhesiveParams{}) {}
  explicit HertzAdhesive(const HertzAdhesiveParams& params)
      : p_(params), kt_(2.0 / 7.0 * params.kn * std::sqrt(params.eps_bar * params.roughness)),
        h_s_(params.repulsion_onset * params.roughness), k_s_(params.repulsion_stiffness * params.kn) {
    p_.validate();
  }
  const HertzAdhesiveParams& params() const { return p_; }
  void validate() const { p_.validate(); }

  // delta_0 under a constant adhesion force f_adh.
  double zero_force_compression(double f_adh) const { return std::pow(f_adh / p_.kn, 2.0 / 3.0); }
  double range() const { return p_.roughness; }
  // dF/d delta = (3/2) k_n sqrt(delta) at the largest compression h_r, stiffened by the supplementary wall.
  double stiffness_scale() const {
    return 1.5 * p_.kn * std::sqrt(p_.roughness) * (1.0 + p_.repulsion_stiffness * std::sqrt(p_.repulsion_onset));
  }
  double secant_stiffness() const { return p_.kn * std::sqrt(p_.eps_bar * p_.roughness); }  // at delta_bar
  double default_tangential_stiffness() const { return kt_; }  // eq. 18
  double adhesion_force() const { return 0.0; }  // the adhesion sub-model's

  NormalContact apply(const PairGeometry& g, const RelativeMotion&, PairForce& f) const {
    const double gap = g.gap();
    const double delta = p_.roughness - gap;
    if (!(delta > 0.0)) return {};
    const double elastic = p_.kn * delta * std::sqrt(delta);
    const double s = h_s_ - gap;
    const double supplementary = s > 0.0 ? k_s_ * s * std::sqrt(s) : 0.0;
    // dF_n/d(delta): the Hertz tangent 1.5 k_n sqrt(delta), and the supplementary wall's while it acts.
    f.normal_stiffness = 1.5 * (p_.kn * std::sqrt(delta) + (s > 0.0 ? k_s_ * std::sqrt(s) : 0.0));
    return {true, elastic, elastic + supplementary};
  }

  double energy(const PairGeometry& g) const {
    const double gap = g.gap();
    const double delta = p_.roughness - gap;
    if (!(delta > 0.0)) return 0.0;
    const double s = h_s_ - gap;
    const double e_s = s > 0.0 ? 0.4 * k_s_ * s * s * std::sqrt(s) : 0.0;
    return 0.4 * p_.kn * delta * delta * std::sqrt(delta) + e_s;
  }

  // Paper 004: Gamma-bar = 6 pi eta a_1^2 gammadot / (k_n (eps_bar h_r)^(3/2)) (eq. 17).
  template <class Reader>
  static HertzAdhesive read(Reader& r) {
    const double roughness = r.number("roughness", 5.0e-3, Range::positive());
    const double eps_bar = r.number("eps_bar", 5.0e-2, Range::positive());
    const double gamma_bar = r.number("gamma_bar", 1.0, Range::positive());
    HertzAdhesiveParams p = hertz_from_groups(gamma_bar, eps_bar, roughness);
    p.repulsion_onset = r.number("repulsion_onset", p.repulsion_onset, Range::closed(0.0, 1.0));
    p.repulsion_stiffness = r.number("repulsion_stiffness", p.repulsion_stiffness, Range::non_negative());
    return HertzAdhesive(p);
  }
  template <class Writer>
  void write(Writer& w) const {
    w.number("roughness", p_.roughness);
    w.number("eps_bar", p_.eps_bar);
    w.number("gamma_bar", std::isnan(p_.gamma_bar)
                              ? 6.0 * std::numbers::pi / (p_.kn * std::pow(p_.eps_bar * p_.roughness, 1.5))
                              : p_.gamma_bar);
    w.number("repulsion_onset", p_.repulsion_onset);
    w.number("repulsion_stiffness", p_.repulsion_stiffness);
  }

 private:
  HertzAdhesiveParams p_;
  double kt_, h_s_, k_s_;
};

}  // namespace suspend

// Adhesion, a sub-model that composes with the normal laws that have none of their own (contact_model.hpp): while
// the pair is in contact (as its normal law decides) it adds an attraction -F_adh n on j, to the adhesion
// contribution. It does not enter the load of friction, rolling and twisting (paper 004 eq. 16: mu_s (F_n + F_adh),
// the elastic force). Models:
//   none       nothing (the default of every law but hertz_adhesive)
//   constant   F_adh the same for every pair (paper 004 eq. 14), given as G_adh = F_adh / (6 pi) (key g_adh; paper
//              004 section II E 1, G_adh = F_adh / (6 pi eta a_1^2 gammadot_0)); the default of hertz_adhesive, with
//              paper 004's g_adh = 0.9
//   dmt        F_adh = 2 pi W R*, R* = a_i a_j / (a_i + a_j) (Derjaguin, Muller & Toporov, J. Colloid Interface
//              Sci. 53, 314 (1975)), W the work of adhesion (key work_of_adhesion): the pull-off force of stiff,
//              small spheres, so a bidisperse suspension's large pairs stick harder
// Contact ends where the normal law ends it, so the pull-off force is F_adh (no hysteresis: for a bonded neck use
// law: jkr, whose adhesion is its own and which takes adhesion: none). constant with g_adh = 0 and dmt with W = 0
// are none.
// The adhesive stress scale sigma* = 6 pi Sigma_xy a_1^2 / F_adh uses F_adh of the a_1 pair (R* = a_1 / 2 for dmt).
// Units: F_adh in eta_0 gammadot_ref a_1^2, W in eta_0 gammadot_ref (per a_1).
#pragma once
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

struct Adhesion {
  enum class Model { none, constant, dmt };
  static constexpr std::string_view key = "adhesion";
  static constexpr std::string_view names[] = {"none", "constant", "dmt"};

  Model model = Model::none;
  double parameter = 0.0;  // F_adh (constant) or W (dmt)
  // constant: G_adh as the case gave it (NaN when F_adh was set directly), written back as given: recomputed from
  // F_adh it can move in the last digit, and a resolved case must read back to itself.
  double g_adh = std::numeric_limits<double>::quiet_NaN();

  static Adhesion constant(double f_adh) { return {f_adh > 0.0 ? Model::constant : Model::none, f_adh}; }
  static Adhesion constant_group(double g) {
    Adhesion a = constant(6.0 * std::numbers::pi * g);
    a.g_adh = g;
    return a;
  }
  static Adhesion dmt(double work) { return {work > 0.0 ? Model::dmt : Model::none, work}; }
  bool active() const { return model != Model::none; }
  std::string_view name() const { return names[static_cast<int>(model)]; }

  void validate() const {
    require(parameter, Range::non_negative(),
            model == Model::dmt ? "contact.work_of_adhesion" : "contact.g_adh (through the adhesion force 6 pi g_adh)");
  }
  // The attraction of the pair g, in contact.
  double force(const PairGeometry& g) const { return force_at(g.harmonic_radius()); }
  // F_adh of the a_1 pair (harmonic radius a_1), the scale of sigma*; 0 without adhesion.
  double scale() const { return active() ? force_at(1.0) : 0.0; }
  void apply(const PairGeometry& g, PairForce& f) const {
    if (active()) f[Contribution::adhesion] = -force(g) * g.n;
  }
  // Its potential, F_adh (onset - gap) below the gap `onset` where the normal law's contact begins (0, or h_r).
  double energy(const PairGeometry& g, double onset) const {
    const double gap = g.gap();
    return active() && gap < onset ? -force(g) * (onset - gap) : 0.0;
  }

  static std::vector<std::string> choices() { return {std::begin(names), std::end(names)}; }

  template <class Reader>
  static Adhesion read(Reader& r, std::string_view law_default, double default_g_adh) {
    const std::string model = r.choice(std::string(key), std::string(law_default), choices());
    if (model == names[1]) return constant_group(r.number("g_adh", default_g_adh, Range::non_negative()));
    if (r.has("g_adh")) r.fail("g_adh", "the constant adhesion group; give it only with adhesion: constant");
    if (model == names[2]) return dmt(r.number("work_of_adhesion", Range::non_negative()));
    return {};
  }
  template <class Writer>
  void write(Writer& w, std::string_view law_default) const {
    if (!active() && law_default == names[0]) return;
    w.text(key, name());
    if (model == Model::constant) w.number("g_adh", std::isnan(g_adh) ? parameter / (6.0 * std::numbers::pi) : g_adh);
    if (model == Model::dmt) w.number("work_of_adhesion", parameter);
  }

 private:
  // 2 pi W R* = pi W a_ij for DMT, of a pair of harmonic radius a_ij; the constant force otherwise.
  double force_at(double harmonic_radius) const {
    return model == Model::dmt ? std::numbers::pi * parameter * harmonic_radius : parameter;
  }
};

}  // namespace suspend

// Normal damping, a sub-model that composes with every normal law (contact_model.hpp). While the pair is in contact
// it adds to the normal force on j (n from i to j, v_n = (u_j - u_i) . n the separation speed):
//   none          nothing (the default)
//   viscous       F_d = -gamma_n v_n                     (the dashpot of paper 000 eq. 4a; Luding 2008 eq. 3)
//   viscoelastic  F_d = -A (dF_el / d delta) v_n        (Brilliantov, Spahn, Hertzsch & Poeschel, Phys. Rev. E 53,
//                 5382 (1996): for Hertz, F_d = -(3/2) A k_n sqrt(delta) v_n; A the dissipation time of the
//                 material. The tangent stiffness is the normal law's own, PairForce::normal_stiffness, so the
//                 same key damps a linear spring by A k_n and a Hertz contact in proportion to its contact radius.)
// The damping force joins the normal force (contribution contact_normal) and the load of friction, rolling and
// twisting (paper 000: the load is the full spring + dashpot force). It only dissipates: its power on the pair is
// -c v_n^2 <= 0 with c = gamma_n or A dF_el/d delta >= 0.
// Case keys: `damping: none | viscous | viscoelastic`, with `gamma_n` (viscous) or `dissipation_time` (viscoelastic).
// Giving gamma_n alone means viscous (the linear spring's former key); viscous with gamma_n = 0 is none.
// Units: gamma_n in eta_0 a_1 (gamma_n gammadot / k_n is paper 000's damping group), A in 1 / gammadot_ref.
#pragma once
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "core/range.hpp"
#include "dem/contact/pair_geometry.hpp"

namespace suspend {

struct NormalDamping {
  enum class Model { none, viscous, viscoelastic };
  static constexpr std::string_view key = "damping";
  static constexpr std::string_view names[] = {"none", "viscous", "viscoelastic"};

  Model model = Model::none;
  double coefficient = 0.0;  // gamma_n (viscous) or the dissipation time A (viscoelastic)

  static NormalDamping viscous(double gamma_n) { return {gamma_n > 0.0 ? Model::viscous : Model::none, gamma_n}; }
  static NormalDamping viscoelastic(double time) { return {time > 0.0 ? Model::viscoelastic : Model::none, time}; }
  bool active() const { return model != Model::none; }
  std::string_view name() const { return names[static_cast<int>(model)]; }
  std::string_view coefficient_key() const { return model == Model::viscoelastic ? "dissipation_time" : "gamma_n"; }

  void validate() const { require(coefficient, Range::non_negative(), "contact." + std::string(coefficient_key())); }

  // gamma_n v_n or A k(delta) v_n: the force the model subtracts from the normal force on j.
  double resistance(const PairGeometry& g, const RelativeMotion& m, double normal_stiffness) const {
    const double v_n = (m.u_j - m.u_i).dot(g.n);
    return model == Model::viscous ? coefficient * v_n : coefficient * normal_stiffness * v_n;
  }

  static std::vector<std::string> choices() { return {std::begin(names), std::end(names)}; }

  template <class Reader>
  static NormalDamping read(Reader& r) {
    const bool gamma_given = r.has("gamma_n");
    const std::string model = r.choice(std::string(key), gamma_given ? "viscous" : "none", choices());
    if (model == names[1]) return viscous(r.number("gamma_n", 0.0, Range::non_negative()));
    if (gamma_given) r.fail("gamma_n", "the viscous damping coefficient; give it only with damping: viscous");
    if (model == names[2]) return viscoelastic(r.number("dissipation_time", 0.0, Range::non_negative()));
    if (r.has("dissipation_time"))
      r.fail("dissipation_time", "the viscoelastic dissipation time; give it only with damping: viscoelastic");
    return {};
  }
  template <class Writer>
  void write(Writer& w) const {
    if (!active()) return;
    w.text(key, name());
    w.number(coefficient_key(), coefficient);
  }
};

}  // namespace suspend

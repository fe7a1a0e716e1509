#include "io/contact_case.hpp"

#include <cmath>
#include <numbers>

#include "io/units.hpp"

namespace suspend::io {

namespace {
using std::numbers::pi;

LinearSpringParams read_spring(SchemaReader& r) {
  LinearSpringParams p;
  p.kn = stiffness_from_k_hat(r.number("k_hat", p.kn, Range::positive()));
  p.kt = r.number("kt", 2.0 / 7.0 * p.kn, Range::positive());
  p.gamma_n = r.number("gamma_n", 0.0, Range::non_negative());
  return p;
}

template <class Contact>
ContactLaw compose(Contact c, SurfaceForces s) {
  return ComposedLaw<Contact>{std::move(c), std::move(s)};
}

SurfaceForces read_surface_forces(SchemaReader& r) {
  SurfaceForces s;
  if (r.has("repulsion")) {
    SchemaReader e = r.child("repulsion");
    ElectrostaticRepulsionParams p;
    p.force = e.number("force", p.force, Range::non_negative());
    p.debye_length = e.number("debye_length", p.debye_length, Range::positive());
    p.cutoff_in_debye = e.number("cutoff_in_debye", p.cutoff_in_debye, Range::positive());
    e.finish();
    s.repulsion = ElectrostaticRepulsion{p};
  }
  if (r.has("attraction")) {
    SchemaReader v = r.child("attraction");
    VanDerWaalsParams p;
    p.hamaker = v.number("hamaker", p.hamaker, Range::non_negative());
    p.epsilon_rel = v.number("epsilon", p.epsilon_rel, Range::positive());
    p.cutoff = v.number("cutoff", p.cutoff, Range::positive());
    v.finish();
    s.attraction = VanDerWaals{p};
  }
  return s;
}

}  // namespace

ContactLaw read_contact(SchemaReader r) {
  const std::string law = r.choice("law", "soft_repulsion", {"soft_repulsion", "linear_spring", "hertz_adhesive"});
  const SurfaceForces surface = read_surface_forces(r);
  ContactLaw out;
  if (law == "soft_repulsion") {
    SoftRepulsion s;
    s.p.kn = stiffness_from_k_hat(r.number("k_hat", 1.0e4, Range::positive()));
    out = compose(s, surface);
  } else if (law == "linear_spring") {
    const LinearSpringParams spring = read_spring(r);
    const std::string friction = r.choice("friction", "coulomb", {"none", "coulomb", "critical_load"});
    const double mu = r.number("mu", friction == "none" ? 0.0 : 1.0, Range::non_negative());
    std::optional<RollingResistanceParams> rolling;
    if (r.has("rolling")) {
      SchemaReader rr = r.child("rolling");
      RollingResistanceParams p;
      p.kr = rr.number("kr", spring.kn / 100.0, Range::positive());
      p.mu_r = rr.number("mu_r", p.mu_r, Range::non_negative());
      rr.finish();
      rolling = p;
    }
    if (friction == "critical_load") {
      CriticalLoadFriction f{{mu, r.number("critical_load", 1.0, Range::non_negative())}};
      if (rolling)
        out = compose(LinearSpringCriticalLoadRolling{spring, f, RollingResistance{*rolling}}, surface);
      else
        out = compose(LinearSpringCriticalLoad{spring, f, {}}, surface);
    } else {
      if (friction == "none" && mu != 0.0) r.fail("mu", "must be 0 with friction: none");
      CoulombFriction f{{mu}};
      if (rolling)
        out = compose(LinearSpringCoulombRolling{spring, f, RollingResistance{*rolling}}, surface);
      else
        out = compose(LinearSpringCoulomb{spring, f, {}}, surface);
    }
  } else {
    // Paper 004: Gamma-bar = 6 pi eta a_1^2 gammadot / (k_n (eps_bar h_r)^(3/2)) (eq. 17), G_adh = F_adh / (6 pi).
    const double roughness = r.number("roughness", 5.0e-3, Range::positive());
    const double eps_bar = r.number("eps_bar", 5.0e-2, Range::positive());
    const double gamma_bar = r.number("gamma_bar", 1.0, Range::positive());
    const double g_adh = r.number("g_adh", 0.9, Range::non_negative());
    const double mu_s = r.number("mu_s", 0.5, Range::non_negative());
    HertzAdhesiveParams p = hertz_adhesive_from_groups(gamma_bar, g_adh, eps_bar, roughness, mu_s);
    p.repulsion_onset = r.number("repulsion_onset", p.repulsion_onset, Range::closed(0.0, 1.0));
    p.repulsion_stiffness = r.number("repulsion_stiffness", p.repulsion_stiffness, Range::non_negative());
    out = compose(HertzAdhesive(p), surface);
  }
  r.finish();
  std::visit([](const auto& l) { l.validate(); }, out);
  return out;
}

std::string contact_law_name(const ContactLaw& law) {
  return std::visit(
      [](const auto& l) -> std::string {
        using C = std::decay_t<decltype(l.contact)>;
        if constexpr (std::is_same_v<C, SoftRepulsion>) return "soft_repulsion";
        else if constexpr (std::is_same_v<C, HertzAdhesive>) return "hertz_adhesive";
        else return "linear_spring";
      },
      law);
}

YAML::Node contact_to_yaml(const ContactLaw& law) {
  YAML::Node n;
  n["law"] = contact_law_name(law);
  std::visit(
      [&](const auto& l) {
        using C = std::decay_t<decltype(l.contact)>;
        const auto& c = l.contact;
        if constexpr (std::is_same_v<C, SoftRepulsion>) {
          n["k_hat"] = number_node(k_hat_from_stiffness(c.p.kn));
        } else if constexpr (std::is_same_v<C, HertzAdhesive>) {
          const HertzAdhesiveParams& p = c.params();
          n["roughness"] = number_node(p.roughness);
          n["eps_bar"] = number_node(p.eps_bar);
          n["gamma_bar"] = number_node(6.0 * pi / (p.kn * std::pow(p.eps_bar * p.roughness, 1.5)));
          n["g_adh"] = number_node(p.f_adh / (6.0 * pi));
          n["mu_s"] = number_node(p.mu_s);
          n["repulsion_onset"] = number_node(p.repulsion_onset);
          n["repulsion_stiffness"] = number_node(p.repulsion_stiffness);
        } else {
          n["k_hat"] = number_node(k_hat_from_stiffness(c.p.kn));
          n["kt"] = number_node(c.p.kt);
          n["gamma_n"] = number_node(c.p.gamma_n);
          if constexpr (requires { c.friction.p.critical_load; }) {
            n["friction"] = "critical_load";
            n["critical_load"] = number_node(c.friction.p.critical_load);
          } else {
            n["friction"] = c.friction.p.mu == 0.0 ? "none" : "coulomb";
          }
          n["mu"] = number_node(c.friction.p.mu);
          if constexpr (requires { c.rolling.p.kr; }) {
            n["rolling"]["kr"] = number_node(c.rolling.p.kr);
            n["rolling"]["mu_r"] = number_node(c.rolling.p.mu_r);
          }
        }
        if (l.surface.repulsion) {
          const auto& p = l.surface.repulsion->p;
          n["repulsion"]["force"] = number_node(p.force);
          n["repulsion"]["debye_length"] = number_node(p.debye_length);
          n["repulsion"]["cutoff_in_debye"] = number_node(p.cutoff_in_debye);
        }
        if (l.surface.attraction) {
          const auto& p = l.surface.attraction->p;
          n["attraction"]["hamaker"] = number_node(p.hamaker);
          n["attraction"]["epsilon"] = number_node(p.epsilon_rel);
          n["attraction"]["cutoff"] = number_node(p.cutoff);
        }
      },
      law);
  return n;
}

}  // namespace suspend::io

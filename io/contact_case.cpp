#include "io/contact_case.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace suspend::io {

namespace {
using std::numbers::pi;

// The laws write themselves through this: numbers as exact YAML scalars.
struct YamlWriter {
  YAML::Node& n;
  void number(std::string_view key, double v) { n[std::string(key)] = number_node(v); }
  void text(std::string_view key, std::string_view v) { n[std::string(key)] = std::string(v); }
};

template <class... T>
std::vector<std::string> names(TypeList<T...>) {
  return {std::string(T::name)...};
}
template <class... T, class Fn>
void for_each_type(TypeList<T...>, Fn&& fn) {
  (fn.template operator()<T>(), ...);
}

// The sub-models every normal law composes with: adhesion, damping, the tangential stiffness, twisting.
template <class Model>
void read_common(SchemaReader& r, Model& c) {
  using N = typename Model::normal_type;
  if constexpr (std::is_same_v<N, JkrAdhesion>) {
    if (r.choice(std::string(Adhesion::key), "none", Adhesion::choices()) != "none")
      r.fail(std::string(Adhesion::key), "law: jkr carries its own adhesion (work_of_adhesion); give adhesion: none");
  } else {
    c.adhesion = Adhesion::read(r, N::default_adhesion, N::default_g_adh);
  }
  c.damping = NormalDamping::read(r);
  if (r.has("kt")) c.kt = r.number("kt", Range::positive());
  const std::string block(TwistingResistance::name);
  if (r.has(block)) {
    SchemaReader tr = r.child(block);
    c.twisting = TwistingResistance::read(tr, c.normal.secant_stiffness() / 100.0);
    tr.finish();
  }
}

template <class Normal, class Friction>
ContactLaw with_rolling(SchemaReader& r, const Normal& normal, const Friction& friction, const SurfaceForces& s) {
  ContactModel<Normal, Friction> c{normal, friction};
  read_common(r, c);
  const std::string block(RollingResistance::name);  // the law's own name is its case block
  if (!r.has(block)) return ComposedLaw<ContactModel<Normal, Friction>>{c, s};
  SchemaReader rr = r.child(block);
  const RollingResistance rolling = RollingResistance::read(rr, normal.secant_stiffness() / 100.0);
  rr.finish();
  ContactModel<Normal, Friction, RollingResistance> cr{normal,    friction,   rolling, c.adhesion,
                                                       c.damping, c.twisting, c.kt};
  return ComposedLaw<ContactModel<Normal, Friction, RollingResistance>>{cr, s};
}

// One law from the keys of r: {law, its keys, friction, mu (or mu_s), critical_load, kt, adhesion and its keys,
// damping and its keys, rolling, twisting, surface forces}. Coulomb friction with mu = 0 is no friction.
ContactLaw read_law(SchemaReader& r) {
  const std::string law = r.choice("law", "soft_repulsion", names(NormalLaws{}));
  const SurfaceForces surface = SurfaceForces::read(r);
  std::optional<ContactLaw> out;
  for_each_type(NormalLaws{}, [&]<class N>() {
    if (N::name != law) return;
    const std::string friction = r.choice("friction", std::string(N::default_friction), names(FrictionLaws{}));
    const N normal = N::read(r);
    for_each_type(FrictionLaws{}, [&]<class F>() {
      if (F::name != friction) return;
      const F f = F::read(r, N::default_mu);
      if constexpr (std::is_same_v<F, CoulombFriction>) {
        if (f.coefficient() == 0.0) {
          out = with_rolling(r, normal, NoFriction{}, surface);
          return;
        }
      }
      out = with_rolling(r, normal, f, surface);
    });
  });
  return *out;
}

// species_pairs: [{species: [i, j], keys of the law to change}, ...]: each entry is read as the case's contact
// with its keys replaced, and must give the same law, friction and rolling.
void read_species_pairs(SchemaReader& r, int species, ContactLaw& law) {
  std::vector<std::pair<int, int>> seen;
  for (SchemaReader e : r.children("species_pairs")) {
    const std::vector<double> s = e.number_list("species", Range::closed(0.0, species - 1.0));
    if (s.size() != 2 || s[0] != std::floor(s[0]) || s[1] != std::floor(s[1]))
      e.fail("species", "give two species indices [i, j], each an integer in [0, " + std::to_string(species - 1) +
                            "] (the order of particles.species)");
    const std::pair<int, int> ij = std::minmax(static_cast<int>(s[0]), static_cast<int>(s[1]));
    if (std::find(seen.begin(), seen.end(), ij) != seen.end())
      e.fail("species", "the pair [" + std::to_string(ij.first) + ", " + std::to_string(ij.second) +
                            "] is given twice; give each species pair once");
    seen.push_back(ij);
    for (const std::string_view key : {std::string_view("law"), ElectrostaticRepulsion::name, VanDerWaals::name,
                                       std::string_view("species_pairs")})
      if (e.has(std::string(key)))
        e.fail(std::string(key), "a species pair takes the case's law and surface forces; give only the parameters that differ");
    YAML::Node merged = YAML::Clone(r.node());
    merged.remove("species_pairs");
    for (const auto& kv : e.node()) {
      const std::string key = kv.first.Scalar();
      if (key == "species") continue;
      if (key == "mu" || key == "mu_s") {  // one coefficient under either name (friction_coefficient.hpp)
        merged.remove("mu");
        merged.remove("mu_s");
      }
      merged[key] = YAML::Clone(kv.second);
    }
    SchemaReader m(merged, e.path());
    const ContactLaw pair = read_law(m);
    m.finish();
    if (pair.index() != law.index())
      e.fail("friction", "a species pair may change the parameters of the case's law, friction and rolling, not "
                         "which friction law or whether rolling acts");
    std::visit(
        [&](auto& l) {
          using L = std::decay_t<decltype(l)>;
          l.set_pair(static_cast<int>(s[0]), static_cast<int>(s[1]), std::get<L>(pair).contact, species);
        },
        law);
  }
}

// The keys of one contact model (no law name, no surface forces).
template <class Model>
void write_model(YAML::Node& n, const Model& c) {
  using N = typename Model::normal_type;
  YamlWriter w{n};
  c.normal.write(w);
  // A law whose default is no friction writes none when it has none (soft_repulsion: {law, k_hat}).
  if (Model::has_friction || N::default_friction != NoFriction::name) c.friction.write(w);
  if (Model::has_friction) w.number("kt", c.tangential_stiffness());
  c.adhesion.write(w, N::default_adhesion);
  c.damping.write(w);
  if constexpr (Model::has_rolling) {
    YAML::Node rolling;
    YamlWriter rw{rolling};
    c.rolling.write(rw);
    n[std::string(RollingResistance::name)] = rolling;
  }
  if (c.twisting.active) {
    YAML::Node twisting;
    YamlWriter tw{twisting};
    c.twisting.write(tw);
    n[std::string(TwistingResistance::name)] = twisting;
  }
}

}  // namespace

ContactLaw read_contact(SchemaReader r, int species) {
  ContactLaw law = read_law(r);
  if (r.has("species_pairs")) read_species_pairs(r, species, law);
  r.finish();
  validate(law);
  return law;
}

std::string contact_law_name(const ContactLaw& law) {
  return std::visit([](const auto& l) { return std::string(std::decay_t<decltype(l.contact.normal)>::name); }, law);
}

YAML::Node contact_to_yaml(const ContactLaw& law) {
  YAML::Node n;
  n["law"] = contact_law_name(law);
  std::visit(
      [&](const auto& l) {
        write_model(n, l.contact);
        l.surface.for_each([&](const auto& force) {
          YAML::Node block;
          YamlWriter w{block};
          force.write(w);
          n[std::string(force.name)] = block;
        });
        for (const auto& [s_i, s_j] : l.pairs.given) {
          YAML::Node e;
          e["species"].push_back(s_i);
          e["species"].push_back(s_j);
          e["species"].SetStyle(YAML::EmitterStyle::Flow);
          write_model(e, l.pairs.of(s_i, s_j));
          n["species_pairs"].push_back(e);
        }
      },
      law);
  return n;
}

}  // namespace suspend::io

// No friction, a tangential sub-model: the contact carries no tangential force and keeps no tangential stretch.
// `friction: none` in a case, and Coulomb friction with mu = 0.
#pragma once
#include <string>
#include <string_view>

namespace suspend {

struct NoFriction {
  static constexpr std::string_view name = "none";
  void validate(std::string_view = "mu") const {}
  double coefficient() const { return 0.0; }

  template <class Reader>
  static NoFriction read(Reader& r, std::string_view mu_key, double) {
    const std::string key(mu_key);
    if (r.has(key) && r.number(key, 0.0) != 0.0) r.fail(key, "must be 0 with friction: none");
    return {};
  }
  template <class Writer>
  void write(Writer& w, std::string_view mu_key) const {
    w.text("friction", name);
    w.number(mu_key, 0.0);
  }
};

}  // namespace suspend

// No friction, a tangential sub-model: the contact carries no tangential force and keeps no tangential stretch.
// `friction: none` in a case, and Coulomb friction with mu = 0.
#pragma once
#include <string>
#include <string_view>

namespace suspend {

struct NoFriction {
  static constexpr std::string_view name = "none";
  void validate() const {}
  double coefficient() const { return 0.0; }

  template <class Reader>
  static NoFriction read(Reader& r, double) {
    for (const std::string key : {"mu", "mu_s"})
      if (r.has(key) && r.number(key, 0.0) != 0.0) r.fail(key, "must be 0 with friction: none");
    return {};
  }
  template <class Writer>
  void write(Writer& w) const {
    w.text("friction", name);
    w.number("mu", 0.0);
  }
};

}  // namespace suspend

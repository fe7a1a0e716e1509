// The friction coefficient's case key, shared by the friction rules: `mu`, or `mu_s` (paper 004's name for the same
// sliding coefficient, accepted for every law), not both. A case is written back with `mu`.
#pragma once
#include <string>

#include "core/range.hpp"

namespace suspend {

template <class Reader>
double read_friction_coefficient(Reader& r, double default_mu) {
  if (r.has("mu_s")) {
    if (r.has("mu")) r.fail("mu_s", "the same coefficient as mu; give one of them");
    return r.number("mu_s", default_mu, Range::non_negative());
  }
  return r.number("mu", default_mu, Range::non_negative());
}

}  // namespace suspend

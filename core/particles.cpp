#include "core/particles.hpp"

#include <numbers>

namespace suspend {
double Particles::volume() const {
  double v = 0.0;
  for (double a : radius) v += a * a * a;
  return 4.0 / 3.0 * std::numbers::pi * v;
}
}  // namespace suspend

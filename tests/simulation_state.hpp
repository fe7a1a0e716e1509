// Shared by the dynamics tests: a simulation state of spheres at rest at the given positions.
#pragma once
#include <vector>

#include "dem/simulation.hpp"

namespace suspend::test_support {

inline SimulationState state_of(const std::vector<Vec3>& positions, const std::vector<double>& radii) {
  SimulationState s;
  s.particles.resize(positions.size());
  s.particles.position = positions;
  s.particles.radius = radii;
  return s;
}

}  // namespace suspend::test_support

// The disturbance velocities a set of force multipoles causes on the particles (no ambient flow).
#pragma once
#include <vector>

#include "core/vec.hpp"

namespace suspend::fcm {

struct Disturbance {
  std::vector<Vec3> velocities;
  std::vector<Vec3> angular_velocities;
  std::vector<Mat3> strain_rates;
};

}  // namespace suspend::fcm

// Particle state as a structure of arrays: each field its own contiguous array, so hot loops stream what they use.
#pragma once
#include <cstddef>
#include <vector>

#include "core/vec.hpp"

namespace suspend {

struct Particles {
  std::vector<Vec3> position;          // in the primary cell [0, L)^3
  std::vector<Vec3> velocity;          // lab-frame translational velocity
  std::vector<Vec3> angular_velocity;  // lab-frame angular velocity
  std::vector<double> radius;
  std::vector<int> species;  // index into the case's species list

  std::size_t size() const { return radius.size(); }
  void resize(std::size_t n) {
    position.assign(n, Vec3::Zero());
    velocity.assign(n, Vec3::Zero());
    angular_velocity.assign(n, Vec3::Zero());
    radius.assign(n, 1.0);
    species.assign(n, 0);
  }
  // Total particle volume (4/3) pi sum a^3.
  double volume() const;
};

}  // namespace suspend

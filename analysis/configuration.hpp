// One snapshot of a run as the microstructure analyses see it: particles in the sheared periodic box and the
// contact network (docs/output.md, /snapshots). Built by io/snapshot_reader.hpp from run.h5, or by hand in tests.
#pragma once
#include <cstdint>
#include <vector>

#include "core/box.hpp"
#include "core/vec.hpp"

namespace suspend::analysis {

// A pair on which the contact law exerts a normal force (adhesive contacts included), as run.h5 lists it.
struct Contact {
  std::uint32_t i = 0, j = 0;
  Vec3 force_on_j = Vec3::Zero();        // every pair force on j (surface forces included)
  double gap = 0.0;                      // surface gap r - a_i - a_j (negative: overlap)
  double normal_force = 0.0;             // the contact law's normal force on j along n = (r_j - r_i)/r, > 0 repulsive
  Vec3 tangential_force = Vec3::Zero();  // the contact law's tangential force on j
  bool sliding = false;                  // the tangential force is at its Coulomb limit
};

struct Configuration {
  std::int64_t step = 0;
  double time = 0.0, strain = 0.0;
  Box box;  // lengths and the Lees-Edwards offset of this instant
  std::vector<Vec3> position;
  std::vector<Vec3> velocity;  // lab-frame translational velocity; empty when unknown (built by hand without it)
  std::vector<double> radius;
  std::vector<int> species;
  std::vector<Contact> contacts;
  // false for run.h5 files written before the snapshots carried each contact's gap, law forces and sliding state:
  // then only the pairs and force_on_j are known.
  bool contact_details = true;
  std::size_t size() const { return position.size(); }
};

}  // namespace suspend::analysis

// Tensors of the contact network: the fabric and the contact stress, from one configuration.
//   fabric  R = < n n >   over the contacts, n = (r_j - r_i)/|r_j - r_i| (trace 1; isotropic: I/3)
//   contact stress  Sigma^c = -(1/V) sum_contacts sym(d F_j),  d = r_j - r_i (minimum image), F_j the force on j
// the same virial as the engines' series (dem/pair_forces.hpp), in eta_0 gammadot_ref. `contact_law` takes
// F_j = the contact law's normal and tangential forces (the series' contact_normal + contact_tangential, whose
// implicit-step changes the snapshot includes); `contact_pairs` takes every force of the listed pairs, surface
// forces included (adhesion and repulsion of pairs not in contact, acting at a distance, are not in it).
#pragma once
#include "analysis/configuration.hpp"

namespace suspend::analysis {

struct ContactTensors {
  Mat3 fabric = Mat3::Zero();
  Mat3 contact_law_stress = Mat3::Zero();
  Mat3 contact_pair_stress = Mat3::Zero();
};
ContactTensors contact_tensors(const Configuration& c);

}  // namespace suspend::analysis

// Profiles across the gradient direction y of one configuration: the local volume fraction and the mean flow
// velocity in slabs of the box, the test for shear banding and migration (a homogeneous simple shear has a uniform
// phi(y) and a linear u_x(y) whose slope is the imposed rate; paper 004 section IV on banding at low sigma*).
// Lengths in a_1, velocities in gammadot_ref a_1 as in run.h5.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/configuration.hpp"

namespace suspend::analysis {

struct GradientProfile {
  double width = 0.0;     // of a slab: L_y / bins
  std::vector<double> y;  // slab centres, (k + 1/2) width, k = 0 .. bins - 1
  // Each sphere's exact volume between the slab's planes (periodic in y) over the slab's volume; sums to phi.
  std::vector<double> phi;
  std::vector<std::size_t> count;  // particles whose centre lies in the slab
  // The particles of a slab by centre, weighted by their volume: mean y and mean u_x (NaN for an empty slab).
  std::vector<double> mean_y, velocity;
  // Least-squares slope of u_x against y over every particle (volume-weighted): the rate the cell is sheared at
  // (exactly gammadot for affine motion). NaN without velocities or with all centres at one y.
  double shear_rate = 0.0;
  // Slope of u_x between neighbouring slabs k and k + 1 inside the cell, (velocity[k+1] - velocity[k]) /
  // (mean_y[k+1] - mean_y[k]) (bins - 1 values; NaN next to an empty slab): a band shows as slopes far from
  // shear_rate on one side of the cell.
  std::vector<double> local_rate;
};

// bins >= 1 slabs across [0, L_y); the velocity parts are NaN when the configuration has no velocities.
GradientProfile gradient_profile(const Configuration& c, int bins);

// Volume of a sphere of radius a centred at height yc between the planes y = lo and y = hi (lo < hi), no wrapping.
double sphere_slab_volume(double a, double yc, double lo, double hi);

}  // namespace suspend::analysis

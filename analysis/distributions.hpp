// Distributions of one configuration: contact forces (normalised by their mean), surface gaps of near pairs, the
// pair distribution g(r) and its map in the shear plane g(x, y) (the anisotropy behind N1 and N2).
// Lengths in a_1. Pairs are found with the Lees-Edwards cell list of the engines (dem/neighbour_search.hpp).
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/configuration.hpp"

namespace suspend::analysis {

// Bin k covers [edges[k], edges[k+1]); density[k] = count / (total * width), so that sum density * width is the
// fraction inside the range; below / above count the values outside it.
struct Histogram {
  std::vector<double> edges, density;
  std::size_t below = 0, above = 0, total = 0;
  double mean = 0.0;  // of the raw values (the normalisation of the force histograms)
};

// P(f / <f>) on [0, 5) in 25 bins of the contact law's normal force (values <= 0 count as below) and of the
// tangential force magnitude; mean = <f>.
struct ForceDistributions {
  Histogram normal, tangential;
};
ForceDistributions force_distributions(const Configuration& c);

// Surface gaps h = r - a_i - a_j of every pair with h < 1: logarithmic bins from 1e-4 to 1 (five per decade);
// below counts the pairs with h < 1e-4 (overlapping ones included), `overlapping` those with h <= 0.
struct GapDistribution {
  Histogram gaps;
  std::size_t overlapping = 0;
};
GapDistribution gap_distribution(const Configuration& c);

// g(r) of the centres on [0, r_max) in bins of dr, normalised by the ideal-gas count N (N - 1) / (2 V) per unit
// volume; and g(x, y) of the separations with |dz| < slab (a slab through the shear plane) on the square
// [-r_max, r_max)^2 in bins of dxy, normalised the same way (ordered pairs, both signs of each separation).
// r_max is capped at half the smallest box side, and the map's half-width so that its corners stay within it.
struct PairDistribution {
  double r_max = 0.0, dr = 0.0, dxy = 0.0, slab = 0.0;
  std::vector<double> r, g;        // bin centres and g(r)
  std::vector<double> xy_centres;  // bin centres of both axes of the map
  std::vector<double> g_xy;        // row-major: g_xy[iy * bins + ix]
};
PairDistribution pair_distribution(const Configuration& c, double r_max = 5.0, double dr = 0.05, double dxy = 0.2,
                                   double slab = 1.0);

}  // namespace suspend::analysis

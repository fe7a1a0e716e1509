// The contact network of one configuration: coordination, rattlers, sliding contacts, clusters
// (connected components) and whether a cluster spans the periodic, sheared box.
//
// Percolation: walking a cluster's contacts, each particle gets an unwrapped position (the minimum-image
// separation of every contact added to its neighbour's). A contact that closes a loop whose unwrapped positions
// differ by a lattice vector n_1 a_1 + n_2 a_2 + n_3 a_3 of the sheared cell (a_1 = (L_x, 0, 0),
// a_2 = (offset, L_y, 0), a_3 = (0, 0, L_z)) shows that the cluster wraps around the box: it percolates along x if
// some loop has n_1 != 0, along y if n_2 != 0, along z if n_3 != 0 (a finite cluster has every loop at n = 0).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "analysis/configuration.hpp"

namespace suspend::analysis {

struct ContactNumbers {
  double contacts_per_particle = 0.0;              // Z = 2 M / N
  std::vector<double> contacts_per_particle_of;    // per species: contacts of its particles / its particle count
  double rattler_fraction = 0.0;                   // particles with fewer than two contacts
  double sliding_fraction = 0.0;                   // contacts at the Coulomb limit (0 without contacts)
  std::size_t contacts = 0;
};
ContactNumbers contact_numbers(const Configuration& c);

struct Cluster {
  std::size_t size = 0;
  std::array<bool, 3> percolates{false, false, false};  // along x, y, z (header)
};
struct ClusterStatistics {
  std::vector<Cluster> clusters;    // every connected component of two or more particles, largest first
  std::size_t largest = 0;          // particles in the largest cluster (1 without contacts)
  double mean_size = 0.0;           // number-averaged size of the clusters of two or more (0 without any)
  std::size_t isolated = 0;         // particles without contacts
  std::array<bool, 3> percolates{false, false, false};  // some cluster spans the box along x, y, z
};
ClusterStatistics clusters(const Configuration& c);

}  // namespace suspend::analysis

// Shared by the resistance-solver tests: a bidisperse (a = 1 and 1.4, equal numbers) random packing at phi = 0.5, its
// pairs within a gap cutoff, and random forces and torques (seeded).
#pragma once
#include <random>
#include <vector>

#include "dem/neighbour_search.hpp"
#include "dem/packing.hpp"
#include "dem/pair_forces.hpp"

namespace suspend::test_support {

struct DenseSuspension {
  std::vector<double> radii{1.0, 1.4};
  Particles p;
  Box box;
  std::vector<ActivePair> pairs;
  std::vector<Vec3> force, torque;
};

inline DenseSuspension dense_suspension(std::size_t n, double gap_cutoff) {
  DenseSuspension d;
  std::vector<double> a(n);
  d.p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    d.p.species[i] = i < n / 2 ? 0 : 1;
    a[i] = d.p.radius[i] = d.radii[d.p.species[i]];
  }
  d.box = cube_for_volume_fraction(a, 0.5);
  PackingParams pp;
  pp.seed = 7;
  d.p.position = random_packing(a, d.box, pp).position;
  std::vector<NeighbourPair> list;
  CellListSearch search;
  search.find_pairs(d.p.position, d.p.radius, d.box, gap_cutoff, list);
  compact_active_pairs(list, d.p, d.box, gap_cutoff, d.pairs);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  for (std::size_t i = 0; i < n; ++i) {
    d.force.emplace_back(g(rng), g(rng), g(rng));
    d.torque.emplace_back(g(rng), g(rng), g(rng));
  }
  return d;
}

}  // namespace suspend::test_support

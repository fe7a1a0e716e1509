// Dense packings at the sizes runs use: N = 1000 equal-volume bidisperse (size ratio 1.4) spheres at phi = 0.60 and
// at phi = 0.64, close to random close packing of size-ratio-1.4 bidisperse spheres (0.648 for equal numbers,
// O'Hern et al., PRE 68, 011306 (2003)).
// Checked by brute force over all pairs; the generation time is printed.
#include <gtest/gtest.h>

#include <iostream>
#include <limits>

#include "dem/packing.hpp"

using namespace suspend;

namespace {
void pack_and_check(double phi, std::uint64_t seed) {
  const std::vector<Species> species{{1.0, 0.5}, {1.4, 0.5}};
  const auto a = species_radii(species, species_counts(species, 1000));
  const Box box = cube_for_volume_fraction(a, phi);
  PackingParams params;
  params.seed = seed;
  const Packing p = random_packing(a, box, params);
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      gap = std::min(gap, box.minimum_image(p.position[i], p.position[j]).d.norm() - a[i] - a[j]);
  EXPECT_GE(gap, params.min_gap);
  EXPECT_NEAR(p.report.phi, phi, 1e-3);
  std::cout << "packing N = 1000, phi = " << p.report.phi << ": " << p.report.wall_seconds << " s, "
            << p.report.iterations << " FIRE steps, " << p.report.stages << " stages, " << p.report.retries
            << " retries, minimum gap " << gap << "\n";
}
}  // namespace

TEST(PackingDense, Bidisperse1000AtPhi060) { pack_and_check(0.60, 1); }

TEST(PackingDense, Bidisperse1000AtPhi064) { pack_and_check(0.64, 1); }

// Initial configurations: random, overlap-free polydisperse packings at a target volume fraction
// phi = sum_i (4/3) pi a_i^3 / V, in a plain periodic box (zero shear offset). Lengths in a_1.
//
// Algorithm (docs/packing.md): random centres, radii scaled by s < 1, then s is grown towards 1 and the overlaps are
// removed at each stage by minimising the harmonic soft-sphere energy E = sum_pairs (1/2) delta_ij^2,
// delta_ij = s (a_i + a_j) - |r_ij| > 0 (the harmonic soft spheres of O'Hern et al., PRE 68, 011306 (2003), with
// energy scale delta^2 instead of (delta / sigma)^2), with FIRE (Bitzek et al., PRL 97, 170201 (2006)). The final stage works with radii a_i (1 + margin) + min_gap / 2, so that
// an overlap left below margin * a_min still leaves every true surface gap >= min_gap. Positions are never rescaled:
// the reached phi is the target. A stage that jams short of the target is retried after expanding and shaking.
// Deterministic: the same seed gives bit-identical positions for any thread count (per-particle force gather,
// fixed-block reductions).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/box.hpp"
#include "core/vec.hpp"

namespace suspend {

struct PackingParams {
  std::uint64_t seed = 1;
  double min_gap = 1e-6;       // smallest surface gap |r_ij| - a_i - a_j allowed in the result (units a_1)
  double margin = 1e-6;        // relative radius margin of the final stage (see above)
  double phi_start = 0.40;     // effective volume fraction s^3 phi of the first stage
  double growth = 0.7;         // each stage closes this fraction of the remaining gap to the target phi
  long max_iterations = 2'000'000;  // FIRE steps over all stages
  long stage_iterations = 200'000;  // FIRE steps of one stage before it counts as stalled
  int max_retries = 4;              // expand-shake-compress attempts after a jam or stall
  void validate() const;
};

struct PackingReport {
  double phi_target = 0.0;
  double phi = 0.0;             // sum (4/3) pi a^3 / V of the result
  double min_gap = 0.0;         // smallest surface gap over all pairs (>= PackingParams::min_gap)
  long iterations = 0;          // FIRE steps over all stages
  int stages = 0;
  int retries = 0;              // jams or stalls recovered from
  int neighbour_rebuilds = 0;
  double wall_seconds = 0.0;
};

struct Packing {
  std::vector<Vec3> position;  // in [0, L)^3, same order as the radii given
  PackingReport report;
};

// Volume fraction of spheres with these radii in a box of this volume.
double volume_fraction(const std::vector<double>& radius, double volume);

// The cube in which these spheres fill the volume fraction phi.
Box cube_for_volume_fraction(const std::vector<double>& radius, double phi);

// Places the spheres without overlap in the box (phi is then fixed by radii and box).
// Throws InputError when the volume fraction cannot be reached (the message names the highest reached).
Packing random_packing(const std::vector<double>& radius, const Box& box, const PackingParams& params = {});

// --- species bookkeeping ---------------------------------------------------------------------------------------

struct Species {
  double radius;
  double volume_share;  // fraction of the particle volume carried by this species; shares sum to 1
};

// Counts n_k summing to total whose volume shares n_k a_k^3 / sum_l n_l a_l^3 are closest to the requested ones.
std::vector<std::size_t> species_counts(const std::vector<Species>& species, std::size_t total);

// Counts that fill volume fraction phi of the box with the requested volume shares (each count rounded to nearest).
std::vector<std::size_t> species_counts(const std::vector<Species>& species, double phi, const Box& box);

// The radius list: counts[0] particles of species 0, then counts[1] of species 1, ...
std::vector<double> species_radii(const std::vector<Species>& species, const std::vector<std::size_t>& counts);

}  // namespace suspend

// The two-sphere resistance that FCM itself resolves, measured with the solver (what the sub-grid correction
// subtracts; docs/coupling.md, docs/references.md "Force Coupling Method facts").
//
// Method (measure_fcm_pair): spheres a_i at c - (r/2) e_x and a_j at c + (r/2) e_x in a periodic cube of side
// L = box_factor (a_i + a_j) with the run's grid spacing and truncation. Twelve rigid mobility solves (unit force
// or torque on one sphere, stresslets from the rigidity condition) give the 12x12 mobility M and the stresslet
// response Sigma = dS/dF. Periodic-box correction: the image part of the monopole mobility,
// M_mono,periodic - M_mono,free (Solver::apply without dipoles minus the free-space regularised Stokeslet,
// fcm/direct_sum.hpp), is subtracted from the translational block; it carries the O(a/L) (Hasimoto: -2.837 a/L)
// and O(r^2 a/L^3) image terms. The remaining image terms (rotation O(phi_box) = 4 pi a^3/(3 L^3) < 1e-3, stresslet
// O(r^3/L^3)) are left. Then R = M^-1, dS/dV = Sigma R, and the scalars follow by pair_tensors::scalars_along_x.
//
// Table (FcmPairTable): the scalars on a uniform grid in s' = 2r/(a_i + a_j) from s_min (overlap) to s_max (the
// correction cutoff), interpolated with Catmull-Rom cubics (C1); FCM's functions are smooth on the envelope scale
// sigma_M = a/sqrt(pi), so ds = 0.05 resolves them to ~1e-4. Computed once per (a_i, a_j, h, truncation, grid of
// s') and cached as a text file in cache_dir whose header holds every parameter; a cache with other parameters is
// recomputed and replaced, never used. Units: eta = 1, lengths in a_1.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "dem/hydro/resistance_functions.hpp"
#include "fcm/solver.hpp"

namespace suspend::coupling {

struct FcmPairTableParams {
  double a_i = 1.0, a_j = 1.0;        // radii (a_1 units); the table is stored for a_i <= a_j
  double grid_spacing = 0.5;          // h of the run
  double truncation_widths = 4.0;     // fcm::SolverOptions::truncation_widths of the run
  double s_min = 1.8, s_max = 3.5;    // range of s' = 2 r/(a_i + a_j)
  double ds = 0.05;                   // table spacing in s'
  double box_factor = 12.0;           // L = box_factor (a_i + a_j), rounded up to whole grid cells
  double rigidity_tolerance = 1e-8;   // of the twelve mobility solves
  void validate() const;              // throws InputError naming the key
  bool operator==(const FcmPairTableParams&) const = default;
};

// Scalars from i (lambda = a_j/a_i) and from j, measured at centre distance r with `solver` (box and grid set by
// the caller; the pair is placed at the box centre plus a fixed off-grid shift).
void measure_fcm_pair(fcm::Solver& solver, double a_i, double a_j, double r, hydro::ResistanceScalars& from_i,
                      hydro::ResistanceScalars& from_j);

class FcmPairTable {
 public:
  FcmPairTable() = default;
  // Computes the table (progress is not printed; ~10-30 s for lambda = 1, h = a/2).
  explicit FcmPairTable(const FcmPairTableParams& params);
  // Reads cache_dir/<name> if its parameters equal `params`, otherwise computes and writes it (atomically).
  // Empty cache_dir: compute, no file. `recomputed` (optional) tells which happened.
  static FcmPairTable load_or_compute(const FcmPairTableParams& params, const std::string& cache_dir,
                                      bool* recomputed = nullptr);

  const FcmPairTableParams& params() const { return params_; }
  std::string file_name() const;
  // Scalars at scaled distance s' (clamped to [s_min, s_max]) seen from the first and from the second sphere of
  // params (a_i, a_j).
  void scalars(double s, hydro::ResistanceScalars& from_i, hydro::ResistanceScalars& from_j) const;

  void write(const std::string& path) const;
  // Reads a table file; returns false if it is missing, unreadable or was made with other parameters.
  bool read(const std::string& path, const FcmPairTableParams& expected);

 private:
  void pack();  // fills packed_ from from_i_, from_j_

  FcmPairTableParams params_;
  std::vector<double> s_;
  std::vector<hydro::ResistanceScalars> from_i_, from_j_;
  // The 16 stored functions from i then from j, per node, contiguous: the interpolation is one vector loop.
  std::vector<std::array<double, 32>> packed_;
};

}  // namespace suspend::coupling

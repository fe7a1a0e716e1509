// The O(1) remainder of the pairwise model: exact - (Stokes drag + singular terms), for the sixteen functions of
// the exact two-sphere tables (A, B, C, G, H; Jeffrey & Onishi 1984 / Townsend): equal spheres
// (equal_sphere_table.hpp) and the size ratios lambda = a2/a1 = 1.4 and 1/1.4 (unequal_sphere_table.hpp).
// Bounded at contact (lambda = 1: X11A -0.0046, Y11B +0.239, ...; docs/lubrication.md section 3), so it is
// interpolated linearly in xi between the table's gaps and held at the end values outside them.
// Used by the exact sub-grid target of the FCM coupling (coupling/exact_pair_resistance.hpp) and by the pairwise
// option `hydrodynamics.lubrication.functions: exact_relative` (lubrication.hpp).
#pragma once
#include <array>
#include <span>
#include <string>
#include <vector>

#include "dem/hydro/resistance_functions.hpp"

namespace suspend::hydro {

// The sixteen scalars of the exact tables, in ResistanceScalars.
inline constexpr std::array<double ResistanceScalars::*, 16> tabulated_functions{
    &ResistanceScalars::x11a, &ResistanceScalars::x12a, &ResistanceScalars::y11a, &ResistanceScalars::y12a,
    &ResistanceScalars::y11b, &ResistanceScalars::y12b, &ResistanceScalars::x11c, &ResistanceScalars::x12c,
    &ResistanceScalars::y11c, &ResistanceScalars::y12c, &ResistanceScalars::x11g, &ResistanceScalars::x12g,
    &ResistanceScalars::y11g, &ResistanceScalars::y12g, &ResistanceScalars::y11h, &ResistanceScalars::y12h};

// The six stresslet functions of the tables: the particles' stresslets in a straining flow (M).
inline constexpr std::array<double ResistanceScalars::*, 6> tabulated_stresslet_functions{
    &ResistanceScalars::x11m, &ResistanceScalars::x12m, &ResistanceScalars::y11m,
    &ResistanceScalars::y12m, &ResistanceScalars::z11m, &ResistanceScalars::z12m};

class ExactRemainder {
 public:
  // Table rows: s', XA YA YB XC YC XG YG YH ("11"), the same ("12"), then XM YM ZM ("11") and XM YM ZM ("12"), in
  // the units of sphere 1, s' ascending.
  using Row = std::array<double, 23>;
  ExactRemainder(double lambda, std::span<const Row> rows);

  // The shipped table for lambda = a2/a1 (1, 1.4 or 1/1.4, to a relative 1e-9), or nullptr when there is none.
  static const ExactRemainder* for_ratio(double lambda);
  // The ratios with a shipped table, for messages: "1, 1.4 and 1/1.4".
  static std::string shipped_ratios();

  // Adds the remainder at scaled gap xi to the sixteen functions of tabulated_functions (not M).
  void add_to(double xi, ResistanceScalars& s) const;
  // The interpolated remainder at xi of the sixteen functions (M functions and xi left zero).
  ResistanceScalars at(double xi) const;
  // The exact functions at xi: Stokes drag + the singular terms of this table's lambda + the remainder (the M
  // functions singular only). log_inv_xi = ln(1/xi), shared by the two spheres' calls.
  ResistanceScalars exact(double xi, double log_inv_xi) const;
  // Same, with the M functions exact as well (the pair's stresslet in a straining flow; `suspend pair`).
  ResistanceScalars exact_with_stresslet(double xi, double log_inv_xi) const;
  double lambda() const { return lambda_; }

 private:
  double lambda_;
  LubricationCoefficients coefficients_;
  std::vector<double> xi_;
  std::vector<ResistanceScalars> remainder_;  // all 22 functions; at() and add_to() interpolate the first 16

  double interpolation(double xi, std::size_t& k0, std::size_t& k1) const;
};

}  // namespace suspend::hydro

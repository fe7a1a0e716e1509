// The exact two-sphere resistance near contact: what FCM + sub-grid correction must reproduce.
//
//   lambda = 1, 1.4, 1/1.4: the exact functions of Jeffrey & Onishi (1984) / Townsend
//                (dem/hydro/equal_sphere_table.hpp, unequal_sphere_table.hpp; hydro::ExactRemainder::exact),
//                written as the pairwise model of dem/hydro (Stokes drag + the singular lubrication terms,
//                resistance_functions.hpp) plus a remainder r(xi) = exact - model that is bounded
//                at contact (its contact value is the O(1) term, e.g. X11A: -0.0046, Y11B: +0.239 at lambda = 1)
//                and interpolated linearly in xi between the table's gaps; below the table it is held at its
//                contact value. Seen from j, the table of 1/lambda (the "22" and "21" functions in a_j units).
//   other ratios: the pairwise model alone (no O(1) remainders; docs/lubrication.md section 3 lists their size,
//                10-50% of the tangential functions at xi = 1e-3 - 1e-2). The sub-grid correction then tapers off
//                earlier (docs/coupling.md), and the run says so (io/exact_tables.hpp).
// Scalars in the Kim & Karrila normalisation of resistance_functions.hpp, Stokes drag included (X11A -> 1 far
// apart). The gap is saturated and regularised like the pairwise engine's: xi = 2 max(h, h_in)/(a1 + a2) + eps.
// Units: eta = 1, lengths in a_1.
#pragma once
#include "dem/hydro/exact_remainder.hpp"
#include "dem/hydro/lubrication.hpp"
#include "dem/hydro/resistance_functions.hpp"

namespace suspend::coupling {

class ExactPairResistance {
 public:
  // Spheres a_i, a_j; only the inner cutoff and the regularisation of `lubrication` are used.
  ExactPairResistance(double a_i, double a_j, const hydro::LubricationParams& lubrication);

  // Whether the exact (tabulated) functions are used, rather than the singular model alone.
  bool tabulated() const { return table_i_ != nullptr; }
  // Scalars seen from i (lambda = a_j/a_i) and from j at surface gap h (any sign; saturated below h_in).
  void scalars(double gap, hydro::ResistanceScalars& from_i, hydro::ResistanceScalars& from_j) const;
  double scaled_gap(double gap) const;

 private:
  double a_i_, a_j_;
  hydro::LubricationParams lubrication_;
  hydro::LubricationCoefficients from_i_, from_j_;
  const hydro::ExactRemainder* table_i_ = nullptr;  // exact = model + remainder, seen from i and from j
  const hydro::ExactRemainder* table_j_ = nullptr;
};

}  // namespace suspend::coupling

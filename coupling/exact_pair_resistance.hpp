// The exact two-sphere resistance near contact: what FCM + sub-grid correction must reproduce.
//
//   lambda = 1:  the exact functions of Jeffrey & Onishi (1984) / Townsend (dem/hydro/equal_sphere_table.hpp), written as the
//                pairwise model of dem/hydro (Stokes drag + the singular lubrication terms, resistance_functions.hpp)
//                plus a remainder r(xi) = exact - model that is bounded at contact (its contact value is the
//                O(1) term, e.g. X11A: -0.0046, Y11B: +0.239) and interpolated linearly in xi between the table's
//                gaps (xi = 1e-5 ... 2.5); below xi = 1e-5 the remainder is held at its contact value.
//   lambda != 1: the pairwise model alone (no O(1) remainders available here; docs/lubrication.md section 3 lists
//                their size, 10-50% of the tangential functions at xi = 1e-3 - 1e-2). The sub-grid correction then
//                tapers off earlier (docs/coupling.md).
// Scalars in the Kim & Karrila normalisation of resistance_functions.hpp, Stokes drag included (X11A -> 1 far
// apart). The gap is saturated and regularised like the pairwise engine's: xi = 2 max(h, h_in)/(a1 + a2) + eps.
// Units: eta = 1, lengths in a_1.
#pragma once
#include "dem/hydro/lubrication.hpp"
#include "dem/hydro/resistance_functions.hpp"

namespace suspend::coupling {

class ExactPairResistance {
 public:
  // Spheres a_i, a_j; only the inner cutoff and the regularisation of `lubrication` are used.
  ExactPairResistance(double a_i, double a_j, const hydro::LubricationParams& lubrication);

  // Whether the exact (tabulated) functions are used, rather than the singular model alone.
  bool tabulated() const { return tabulated_; }
  // Scalars seen from i (lambda = a_j/a_i) and from j at surface gap h (any sign; saturated below h_in).
  void scalars(double gap, hydro::ResistanceScalars& from_i, hydro::ResistanceScalars& from_j) const;
  double scaled_gap(double gap) const;

 private:
  double a_i_, a_j_;
  hydro::LubricationParams lubrication_;
  hydro::LubricationCoefficients from_i_, from_j_;
  bool tabulated_ = false;  // lambda = 1: exact = model + hydro::EqualSphereRemainder
};

}  // namespace suspend::coupling

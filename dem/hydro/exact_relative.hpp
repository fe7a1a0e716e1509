// The exact-relative lubrication of the pairwise model (`lubrication.functions: exact_relative`): the part of the
// exact two-sphere resistance that a pairwise-additive model can carry.
//
// With R_ex the exact two-sphere resistance (12x12, ordering U_i, Omega_i, U_j, Omega_j), D the isolated-sphere
// drag diag(6 pi a, 8 pi a^3) and P the projector that removes rigid translation of the pair (U_i = U_j), the
// lubrication is
//     R_lub = P (R_ex - D) P,
// the unique matrix that (1) leaves rigid translation free of force, torque and stresslet, as the singular model
// does (the exact pair's reduced drag when both move together is a many-body far-field effect that pairwise addition
// would overcount), and (2) with the drag gives the exact dissipation for every motion with U_i + U_j = 0: the
// approach, the relative sliding and any rotations. For equal spheres this is "the relative-motion functions
// X11A - X12A, Y11A - Y12A, ... and C, H in full are exact" (docs/lubrication.md section 3b). The strain terms follow
// the same projection (the pair's lubrication forces are equal and opposite). In scalars, with k in units of
// 6 pi eta and the drag removed:
//     k_X = (a_i X11A_i + a_j X11A_j - a_i X12A_i - a_j X12A_j - a_i - a_j)/4,  X11A_i = -X12A_i = k_X/a_i (same for Y^A)
//     Y11B_i = -Y12B_i = (Y11B_i - Y12B_i)/2 of the exact functions (same for X^G, Y^G; each sphere its own)
//     C and H: the exact functions, minus the drag for X11C, Y11C;  M: the singular terms (no M table here).
// Functions "_i" are seen from i in a_i units (lambda = a_j/a_i), "_j" from j in a_j units.
#pragma once
#include "dem/hydro/resistance_functions.hpp"

namespace suspend::hydro {

// exact_i, exact_j: the full exact functions (Stokes drag included) seen from i and from j. lub_i, lub_j: on entry
// the singular lubrication scalars (their M functions are kept), on return the exact-relative lubrication scalars.
void exact_relative_part(double a_i, double a_j, const ResistanceScalars& exact_i, const ResistanceScalars& exact_j,
                         ResistanceScalars& lub_i, ResistanceScalars& lub_j);

}  // namespace suspend::hydro

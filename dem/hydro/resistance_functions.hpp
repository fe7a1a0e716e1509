// Two-sphere resistance scalars of the pairwise model: Stokes drag + the singular lubrication terms.
//
// Spheres 1 (radius a1) and 2 (radius a2), size ratio lambda = a2/a1, centre distance r, surface gap
// h = r - a1 - a2, scaled gap xi = 2 h / (a1 + a2) (Jeffrey & Onishi 1984 write xi = s - 2, s = 2 r / (a1 + a2)).
//
// Normalisation (Kim & Karrila 1991 section 11.3; the reference table tests/data/two_sphere_resistance_table.txt):
// A x 6 pi eta a1, B x 4 pi eta a1^2, C x 8 pi eta a1^3, G x 4 pi eta a1^2, H x 8 pi eta a1^3, M x (20/3) pi eta a1^3.
// The "12" functions use Townsend's scaling (also a1), which equals Jeffrey & Onishi's for lambda = 1. A function
// "alpha beta" is the response of sphere alpha to the motion of sphere beta, with d the unit vector from alpha to
// beta; the other sphere's functions follow by swapping radii (lambda -> 1/lambda) and d -> -d.
//
// Model (paper 000 eq. 3 and Appendix A eqs. A.6-A.7; Jeffrey & Onishi 1984; Jeffrey 1992; Townsend 2018): only the
// terms singular at contact are kept, with Jeffrey & Onishi's exact coefficients g(lambda); isolated-sphere Stokes
// drag is added to the "11" functions of A and C (and M), so X11A -> 1 far apart:
//   X11A = 1 + g1/xi + g2 ln(1/xi)             X12A = -(g1/xi + g2 ln(1/xi))
//   Y11A = 1 + g2ya L      Y12A = -g2ya L      Y11B = g2yb L      Y12B = -g2yb L
//   X11C = 1               X12C = 0            Y11C = 1 + g2yc L  Y12C = g4yc L
//   X11G = g1xg/xi + g2xg L                    X12G = -(g1xg/xi + g2xg L)
//   Y11G = g2yg L          Y12G = -g2yg L      Y11H = g2yh L      Y12H = g5yh L
//   X11M = 1 + g1xm/xi + g2xm L                X12M = g4xm/xi + g5xm L
//   Y11M = 1 + g2ym L      Y12M = g5ym L                                             (L = ln(1/xi))
//   Z11M = 1               Z12M = 0
// The O(1) remainders (exact minus model) are tabulated in docs/lubrication.md. Paper 000 eq. A.7 lists the same g's
// divided by 6 pi eta (e.g. its g^{Y^B_ii} = (2/3) a_i^2 g2yb).
// Validity: xi > 0 and xi << 1. Units: dimensionless.
#pragma once

namespace suspend::hydro {

// The lambda-dependent coefficients g(lambda) of the singular terms: computed once per species pair.
struct LubricationCoefficients {
  double lambda = 1.0;
  double g1xa = 0, g2xa = 0;    // squeeze: 1/xi and ln(1/xi)
  double g2ya = 0;              // translational shear
  double g2yb = 0;              // translation-rotation coupling
  double g2yc = 0, g4yc = 0;    // rotation, self and pair
  double g1xg = 0, g2xg = 0;    // stresslet from squeeze / force from strain along d
  double g2yg = 0;              // stresslet from shear / force from strain across d
  double g2yh = 0, g5yh = 0;    // stresslet from rotation / torque from strain
  double g1xm = 0, g2xm = 0;    // stresslet from strain, along d: self
  double g4xm = 0, g5xm = 0;    // and pair (Jeffrey 1992 eq. 48b; without g2xm, g5xm a free pair's stresslet
                                // would diverge as ln(1/xi) near contact)
  double g2ym = 0, g5ym = 0;    // stresslet from strain, across d
  static LubricationCoefficients for_ratio(double lambda);
};

// Every scalar of the pair, dimensionless, in the normalisation above.
struct ResistanceScalars {
  double xi = 0;
  double x11a = 0, x12a = 0, y11a = 0, y12a = 0;
  double y11b = 0, y12b = 0;
  double x11c = 0, x12c = 0, y11c = 0, y12c = 0;
  double x11g = 0, x12g = 0, y11g = 0, y12g = 0;
  double y11h = 0, y12h = 0;
  double x11m = 0, x12m = 0, y11m = 0, y12m = 0;
  double z11m = 0, z12m = 0;  // not singular at contact: drag only in the model (Z11M = 1, Z12M = 0)
};

// Lubrication part only (no Stokes drag): the singular terms at scaled gap xi > 0. No allocation, no branches.
ResistanceScalars lubrication_scalars(const LubricationCoefficients& c, double xi);
// Same, with ln(1/xi) supplied by the caller (one logarithm per pair for both spheres).
ResistanceScalars lubrication_scalars(const LubricationCoefficients& c, double xi, double log_inv_xi);

// Isolated-sphere drag added to the "11" functions of A, C and M (X11A = Y11A = X11C = Y11C = X11M = Y11M = Z11M = 1).
void add_stokes_drag(ResistanceScalars& s);

// Full model functions (Stokes + lubrication) of spheres a1, a2 at surface gap h (lengths in any common unit).
// The gap used is xi_eff = 2 max(h, inner_cutoff)/(a1 + a2) + regularization; beyond outer_cutoff (a surface gap)
// the lubrication part is zero and only Stokes drag remains. Throws InputError if radii <= 0 or xi_eff <= 0.
struct TwoSphereOptions {
  double regularization = 0.0;  // epsilon added to xi (paper 000 eq. A.6)
  double inner_cutoff = 0.0;    // surface gap below which lubrication saturates (paper 002 Appendix B)
  double outer_cutoff = -1.0;   // surface gap above which lubrication is zero; < 0 means none
};
ResistanceScalars two_sphere_resistance(double a1, double a2, double gap, const TwoSphereOptions& options = {});

}  // namespace suspend::hydro

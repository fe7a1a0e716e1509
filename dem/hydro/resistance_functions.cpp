// Coefficients of the singular terms: Jeffrey & Onishi (1984) for A, B, C; Jeffrey (1992) for G, H, M, in the
// a1-scaling of Townsend (2018, arXiv:1802.08226, eqs. 10-40). Each was checked against the exact table: the
// difference between xi = 1e-4 and 1e-5 agrees to < 0.3% for lambda = 0.1, 1, 10 (tests/unit/test_resistance_functions).
#include "dem/hydro/resistance_functions.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace suspend::hydro {

LubricationCoefficients LubricationCoefficients::for_ratio(double lambda) {
  const double l = lambda;
  const double l2 = l * l, l3 = l2 * l;
  const double p = 1.0 + l;
  const double p2 = p * p, p3 = p2 * p;
  LubricationCoefficients c;
  c.lambda = l;
  c.g1xa = 2.0 * l2 / p3;                                  // J&O (3.17)
  c.g2xa = l * (1.0 + 7.0 * l + l2) / (5.0 * p3);
  c.g2ya = 4.0 / 15.0 * l * (2.0 + l + 2.0 * l2) / p3;     // J&O (4.15)
  c.g2yb = -0.2 * l * (4.0 + l) / p2;                      // J&O (5.6)
  c.g2yc = 0.4 * l / p;                                    // J&O (7.10)
  c.g4yc = 0.1 * l2 / p;                                   // J&O (7.10) x (1+lambda)^3/8 (a1 scaling)
  c.g1xg = 3.0 * l2 / p3;                                  // Jeffrey (19b)
  c.g2xg = 0.3 * (l + 12.0 * l2 - 4.0 * l3) / p3;
  c.g2yg = 0.1 * (4.0 * l - l2 + 7.0 * l3) / p3;           // Jeffrey (27b)
  c.g2yh = 0.1 * (2.0 * l - l2) / p2;                      // Jeffrey (35b)
  c.g5yh = 0.05 * (l2 + 7.0 * l3) / p2;
  c.g1xm = 1.2 * l2 / p3;                                  // Jeffrey (48b), M functions
  c.g2xm = 3.0 / 25.0 * (l + 17.0 * l2 - 9.0 * l3) / p3;
  c.g4xm = 1.2 * l3 / p3;
  c.g5xm = 3.0 / 25.0 * (-4.0 * l2 + 17.0 * l3 - 4.0 * l2 * l2) / p3;
  c.g2ym = 6.0 / 25.0 * l * (1.0 - l + 4.0 * l2) / p3;
  c.g5ym = 3.0 / 50.0 * l2 * (7.0 - 10.0 * l + 7.0 * l2) / p3;
  return c;
}

ResistanceScalars lubrication_scalars(const LubricationCoefficients& c, double xi) {
  return lubrication_scalars(c, xi, std::log(1.0 / xi));
}

ResistanceScalars lubrication_scalars(const LubricationCoefficients& c, double xi, double log_inv_xi) {
  const double inv = 1.0 / xi;
  const double L = log_inv_xi;
  ResistanceScalars s;
  s.xi = xi;
  s.x11a = c.g1xa * inv + c.g2xa * L;
  s.x12a = -s.x11a;
  s.y11a = c.g2ya * L;
  s.y12a = -s.y11a;
  s.y11b = c.g2yb * L;
  s.y12b = -s.y11b;
  s.x11c = 0.0;
  s.x12c = 0.0;
  s.y11c = c.g2yc * L;
  s.y12c = c.g4yc * L;
  s.x11g = c.g1xg * inv + c.g2xg * L;
  s.x12g = -s.x11g;
  s.y11g = c.g2yg * L;
  s.y12g = -s.y11g;
  s.y11h = c.g2yh * L;
  s.y12h = c.g5yh * L;
  s.x11m = c.g1xm * inv + c.g2xm * L;
  s.x12m = c.g4xm * inv + c.g5xm * L;
  s.y11m = c.g2ym * L;
  s.y12m = c.g5ym * L;
  return s;
}

void add_stokes_drag(ResistanceScalars& s) {
  s.x11a += 1.0;
  s.y11a += 1.0;
  s.x11c += 1.0;
  s.y11c += 1.0;
  s.x11m += 1.0;
  s.y11m += 1.0;
  s.z11m += 1.0;
}

ResistanceScalars two_sphere_resistance(double a1, double a2, double gap, const TwoSphereOptions& options) {
  if (!(a1 > 0.0) || !(a2 > 0.0))
    throw InputError("radii must be > 0 (got a1 = " + std::to_string(a1) + ", a2 = " + std::to_string(a2) + ")");
  if (!std::isfinite(gap)) throw InputError("gap must be finite");
  if (!(options.regularization >= 0.0) || !(options.inner_cutoff >= 0.0))
    throw InputError("regularization and inner cutoff must be >= 0");
  const double xi_gap = 2.0 * gap / (a1 + a2);
  ResistanceScalars s;
  if (options.outer_cutoff >= 0.0 && gap > options.outer_cutoff) {
    s.xi = xi_gap;
  } else {
    const double xi_eff = 2.0 * std::fmax(gap, options.inner_cutoff) / (a1 + a2) + options.regularization;
    if (!(xi_eff > 0.0))
      throw InputError("gap = " + std::to_string(gap) +
                       " gives no positive lubrication gap: use gap > 0 or a regularization/inner cutoff > 0");
    s = lubrication_scalars(LubricationCoefficients::for_ratio(a2 / a1), xi_eff);
    s.xi = xi_gap;
  }
  add_stokes_drag(s);
  return s;
}

}  // namespace suspend::hydro

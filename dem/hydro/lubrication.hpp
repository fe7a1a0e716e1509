// Pairwise lubrication between spheres i and j: squeeze (X^A), shear (Y^A, Y^B, Y^C) and the strain-driven terms
// (X^G, Y^G, Y^H), plus the lubrication stresslet (G, H and the singular part of M).
// Paper 000 eq. 3 and Appendix A (eqs. A.2, A.3, A.6, A.7); Kim & Karrila (1991) ch. 11 for the tensor forms;
// gap saturation and truncation from paper 002 Appendix B.
//
// CONTRACT
//  * n = (x_j - x_i)/|x_j - x_i| points from i to j; gap h = |x_j - x_i| - a_i - a_j (negative when overlapping).
//  * Generalised velocity V = (U_i, Omega_i, U_j, Omega_j), force F = (F_i, T_i, F_j, T_j) (12-vectors).
//  * Hydrodynamic force and torque ON the particles from the fluid (lubrication part):
//        F = -R_lub (V - V_inf) + R_FE : E_inf,
//    V_inf = (U_inf(x_i), Omega_inf(x_i), U_inf(x_j), Omega_inf(x_j)) (use the Lees-Edwards image velocity of j),
//    R_FE : E_inf the forces/torques of the strain rates E_i = E_inf(x_i), E_j = E_inf(x_j) (strain_forces()).
//    R_lub is symmetric positive semi-definite; rigid translation of the pair gives no force.
//  * Stresslet (exerted by the particle on the fluid; (1/V) sum S is the particle stress):
//        S_a = sum_b [ -G^{ab} (U_b - U_inf_b) - H^{ab} (Omega_b - Omega_inf_b) + M^{ab} : E_b ]   (lubrication part)
//  * Gap used: xi = 2 max(h, h_in)/(a_i + a_j) + epsilon (saturation below h_in, regularisation epsilon);
//    lubrication is zero for h > h_out. Lengths in a_1, viscosity eta_0 = 1: forces in eta_0 gammadot a_1^2.
//  * exact_relative: the lubrication is the part of the exact two-sphere resistance that leaves rigid translation of
//    the pair free (exact_relative.hpp): with the drag, the approach, relative sliding and rotations are exact and
//    the model keeps its property that rigid translation of the pair costs nothing. Needs an exact table for the
//    pair's size ratio (1, 1.4, 1/1.4; exact_remainder.hpp); other pairs keep the singular terms (exact() false).
//    The M functions stay singular-only.
//  * Dimensional blocks, alpha's response to beta, d the unit vector from alpha to beta:
//        A = 6 pi a_alpha (X^A d d + Y^A (I - d d)),  B v = 4 pi a_alpha^2 Y^B (v x d),
//        C = 8 pi a_alpha^3 (X^C d d + Y^C (I - d d)),
//        G v = 4 pi a_alpha^2 [X^G (d d - I/3)(d.v) + Y^G (d v + v d - 2 d d (d.v))],
//        H w = 8 pi a_alpha^3 Y^H ((w x d) d + d (w x d)),
//        M : E = (20/3) pi a_alpha^3 [X^M (3/2)(d.E.d)(d d - I/3) + Y^M (d (E d) + (E d) d - 2 (d.E.d) d d)],
//    with the scalars of resistance_functions.hpp evaluated at lambda = a_beta / a_alpha. Reciprocity fills the rest:
//    R[F_a, Omega_b] = B^{ba T}, force of strain F_a = sum_b G^{ba}_{jki} E_b,jk, torque T_a = sum_b H^{ba}_{jki} E_b,jk.
#pragma once
#include <Eigen/Dense>

#include "core/vec.hpp"
#include "dem/hydro/exact_remainder.hpp"
#include "dem/hydro/resistance_functions.hpp"

namespace suspend::hydro {

using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Vector12 = Eigen::Matrix<double, 12, 1>;

struct LubricationParams {
  double regularization = 0.0;  // epsilon added to the scaled gap xi (paper 000 eq. A.6)
  double inner_cutoff = 1e-3;   // h_in, surface gap in a_1 below which lubrication saturates (paper 002 App. B)
  double outer_cutoff = 0.25;   // h_out, surface gap in a_1 beyond which lubrication is zero (paper 000 Table 3)
  // Use the exact two-sphere functions for the relative motion (exact_relative.hpp) where a table exists for the
  // pair's size ratio, so that its relative-motion resistance is exact for h_in < h < h_out (see PairLubrication).
  bool exact_relative = false;
  // Throws InputError naming the key. Requires epsilon > 0 or h_in > 0: an overlapping pair must stay finite.
  void validate() const;
};

// Per-particle strain rates and relative velocities the pair law needs.
struct PairMotion {
  Vec3 du_i = Vec3::Zero(), dw_i = Vec3::Zero();  // U_i - U_inf(x_i), Omega_i - Omega_inf(x_i)
  Vec3 du_j = Vec3::Zero(), dw_j = Vec3::Zero();  // U_j - U_inf(x_j), Omega_j - Omega_inf(x_j)
  Mat3 e_i = Mat3::Zero(), e_j = Mat3::Zero();    // E_inf(x_i), E_inf(x_j), symmetric and traceless
  Vector12 stacked() const;
};

struct PairHydroForce {
  Vec3 force_i = Vec3::Zero(), torque_i = Vec3::Zero();
  Vec3 force_j = Vec3::Zero(), torque_j = Vec3::Zero();
  Mat3 stresslet_i = Mat3::Zero(), stresslet_j = Mat3::Zero();
};

// The pair tensors of spheres a_i, a_j along n from their scalars seen from i and from j (any resistance: the
// lubrication law's, or the sub-grid correction's, coupling/subgrid_lubrication.hpp). R, 12x12, ordering
// (U_i, Omega_i, U_j, Omega_j), F = -R (V - V_inf) ON the particles; R_FE : E, ordering (F_i, T_i, F_j, T_j).
Matrix12 pair_resistance(double a_i, double a_j, const Vec3& n, const ResistanceScalars& si,
                         const ResistanceScalars& sj);
Vector12 pair_strain_forces(double a_i, double a_j, const Vec3& n, const ResistanceScalars& si,
                            const ResistanceScalars& sj, const Mat3& e_i, const Mat3& e_j);

// The law for one species pair (a_i, a_j): lambda-dependent coefficients computed once at construction.
class PairLubrication {
 public:
  PairLubrication(double a_i, double a_j, const LubricationParams& params);

  bool active(double gap) const { return gap <= params_.outer_cutoff; }
  double scaled_gap(double gap) const;  // xi actually used (saturated and regularised)
  // Lubrication scalars seen from i (lambda = a_j/a_i) and from j (lambda = a_i/a_j); zero when inactive.
  void scalars(double gap, ResistanceScalars& from_i, ResistanceScalars& from_j) const;

  // R_lub, 12x12, ordering (U_i, Omega_i, U_j, Omega_j); zero when inactive.
  Matrix12 resistance(const Vec3& n, double gap) const;
  // R_FE : E, ordering (F_i, T_i, F_j, T_j); zero when inactive.
  Vector12 strain_forces(const Vec3& n, double gap, const Mat3& e_i, const Mat3& e_j) const;
  // Forces, torques and stresslets on both particles: F = -R_lub (V - V_inf) + R_FE : E, S as in the contract.
  PairHydroForce evaluate(const Vec3& n, double gap, const PairMotion& m) const;

  double a_i() const { return a_i_; }
  double a_j() const { return a_j_; }
  // Whether exact_relative applies to this pair (asked for, and a table exists for its size ratio).
  bool exact() const { return exact_i_ != nullptr; }

 private:
  double a_i_, a_j_;
  LubricationParams params_;
  LubricationCoefficients from_i_, from_j_;
  const ExactRemainder* exact_i_ = nullptr;  // exact_relative: the tables seen from i and from j
  const ExactRemainder* exact_j_ = nullptr;
};

}  // namespace suspend::hydro

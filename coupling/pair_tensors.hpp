// Pair resistance tensors from the two-sphere scalars, for any line of centres (the sub-grid correction's blocks).
//
// CONTRACT (that of dem/hydro/lubrication.hpp, whose pair_resistance and pair_strain_forces assemble the full
// tensors; test_coupling_pair_tensors checks the block coefficients and the matrix-free product against them):
//  * n = (x_j - x_i)/|x_j - x_i|; generalised velocity V = (U_i, Omega_i, U_j, Omega_j), forces (F_i, T_i, F_j, T_j).
//  * Scalars in the Kim & Karrila normalisation of dem/hydro/resistance_functions.hpp, `from_i` seen from i
//    (lambda = a_j/a_i, d = n), `from_j` seen from j (lambda = a_i/a_j, d = -n).
//  * pair_resistance: R with F = -R (V - V_inf) the force ON the particles; blocks A = 6 pi a (X d d + Y (I - d d)),
//    B v = 4 pi a^2 Y (v x d), C = 8 pi a^3 (X d d + Y (I - d d)); symmetric by construction (the pair blocks are
//    taken from i).
//  * pair_strain_forces: R_FE : E, the forces and torques ON the particles held fixed in the strain rates E_i, E_j
//    (G and H functions; docs/lubrication.md section 4).
// Units: eta = 1, lengths in a_1.
#pragma once
#include <array>

#include "core/vec.hpp"
#include "dem/hydro/exact_remainder.hpp"
#include "dem/hydro/lubrication.hpp"
#include "dem/hydro/resistance_functions.hpp"

namespace suspend::coupling {

using hydro::Matrix12;
using hydro::ResistanceScalars;
using hydro::Vector12;

// The sixteen scalars the sub-grid correction carries (the M functions only enter through the strain stresslet,
// which the FCM rigidity resolves; docs/coupling.md).
inline constexpr std::array<double ResistanceScalars::*, 16> correction_functions = hydro::tabulated_functions;
inline constexpr std::array<const char*, 16> correction_function_names{
    "X11A", "X12A", "Y11A", "Y12A", "Y11B", "Y12B", "X11C", "X12C",
    "Y11C", "Y12C", "X11G", "X12G", "Y11G", "Y12G", "Y11H", "Y12H"};

// The full tensors from the scalars: the pairwise engine's (dem/hydro/lubrication.hpp).
using hydro::pair_resistance;
using hydro::pair_strain_forces;
// The resistance of pair_resistance reduced to the 16 coefficients of its blocks: A and C blocks
// y I + x n n (y = f Y, x = f (X - Y), f = 6 pi a or 8 pi a^3 of the sphere the block is seen from), B blocks
// b [n]_x (b = 4 pi a^2 Y, signs as in pair_resistance).
struct PairResistanceCoefficients {
  double ya11, xa11, ya12, xa12, ya22, xa22;
  double yc11, xc11, yc12, xc12, yc22, xc22;
  double b11, b12, b22, b21;
};
PairResistanceCoefficients pair_resistance_coefficients(double a_i, double a_j, const ResistanceScalars& from_i,
                                                        const ResistanceScalars& from_j);
// The same 12 x 12 matrix as pair_resistance, from the coefficients.
Matrix12 pair_resistance(const PairResistanceCoefficients& c, const Vec3& n);
// pair_resistance(...) * v from the block structure, without forming the matrix: ~130 flops instead of 288 and 128
// bytes per pair to stream instead of 1152.
Vector12 pair_resistance_product(const PairResistanceCoefficients& c, const Vec3& n, const Vector12& v);

// Inverse of the two functions above for n = e_x: the scalars from a 12x12 resistance (ordering as above) and the
// stresslet response G~ = [dS_i/dV, dS_j/dV] (S_a = -G^{ab} (V_b - V_inf_b), stresslets the particles exert on the
// fluid). `stresslet_of_velocity[a][c]` is S_a for unit column c of V (c = 0..11).
void scalars_along_x(double a_i, double a_j, const Matrix12& r, const std::array<std::array<Mat3, 12>, 2>& stresslet,
                     ResistanceScalars& from_i, ResistanceScalars& from_j);

}  // namespace suspend::coupling

// A force- and torque-free pair of spheres in a linear flow: the particle stress it carries, from the resistance
// scalars of any model (drag included), in the two forms the pairwise engine offers (lubrication.stress) and the
// exact form they approximate. Used by `suspend pair --shear` and the tests of the stress form (issue 40).
//
// Force balance (lubrication.hpp contract): R dV = R_FE : E, dV = V - V_inf at the centres, R the full 12x12
// resistance (drag + pair terms). The pair's stress:
//  * stresslet: S_i + S_j, S_a = sum_b [-G^{ab} dU_b - H^{ab} dOmega_b + M^{ab} : E] with X, Y and Z of M
//    (Kim & Karrila 1991 section 11.3): the Stokes-flow stresslet of the two rigid spheres, traceless. With exact
//    scalars it is the exact pair stresslet; with the model's it is the engine's `stress: stresslet` plus the two
//    isolated spheres' (20/3) pi a^3 E (the engine's hydrodynamic contribution).
//  * force_dipole: (20/3) pi (a_i^3 + a_j^3) E - sym(d F_j), F_j = the force on j beyond its own drag, which in a
//    free pair is 6 pi a_j dU_j; the engine's default `stress: force_dipole` (paper 000 eq. 9b). It has a trace.
// Reported as the interaction part: the pair's stress minus the two isolated spheres' (20/3) pi a^3 E.
// Units: eta_0 = 1, the radii's length unit, E in 1/time: stresses in eta_0 E a^3.
#pragma once
#include "core/vec.hpp"
#include "dem/hydro/lubrication.hpp"
#include "dem/hydro/resistance_functions.hpp"

namespace suspend::hydro {

struct FreePairStress {
  Vector12 disturbance = Vector12::Zero();  // dV = (dU_i, dOmega_i, dU_j, dOmega_j)
  Mat3 stresslet = Mat3::Zero();            // S_i + S_j - isolated
  Mat3 force_dipole = Mat3::Zero();         // -sym(d F_j)
};

// Spheres a_i, a_j, n the unit vector from i to j, surface gap `gap`, scalars seen from i and from j with the drag
// included (e.g. ExactRemainder::exact_with_stresslet, or lubrication_scalars + add_stokes_drag), rate of strain e
// (symmetric, traceless).
FreePairStress free_pair_stress(double a_i, double a_j, const Vec3& n, double gap, const ResistanceScalars& si,
                                const ResistanceScalars& sj, const Mat3& e);

// Stresslets of the two spheres (lubrication.hpp's contract, with Z^M) at disturbance velocities dv and strain
// rates e_i, e_j at their centres.
void pair_stresslets(double a_i, double a_j, const Vec3& n, const ResistanceScalars& si, const ResistanceScalars& sj,
                     const Vector12& dv, const Mat3& e_i, const Mat3& e_j, Mat3& s_i, Mat3& s_j);

}  // namespace suspend::hydro

// Spreading of force monopoles and dipoles onto the grid, and its adjoint, interpolation (Lomholt & Maxey 2003,
// eqs. 2.3-2.7; Yeo & Maxey 2010 section 2). For particle n with envelopes Delta_M, Delta_D (envelope.hpp):
//   f_i(x) = F_i Delta_M(x - Y) + G_ij d/dx_j Delta_D(x - Y),   G = S + (1/2) eps . T  (G_ij = S_ij + eps_ijk T_k / 2)
// Interpolation returns the adjoint moments, with dV the node volume:
//   U_i = sum_x u_i Delta_M dV,   A_ij = sum_x u_i d/dx_j Delta_D dV  (= -<du_i/dx_j>_D),
// so that <f, u> dV = F.U + G:A exactly (the discrete adjoint, to round-off). Then
//   Omega_k = (1/2) eps_kij A_ij  and  E_ij = -(A_ij + A_ji) / 2,  hence F.U + G:A = F.U + T.Omega - S:E.
// The Gaussians are evaluated in physical distance on the sheared lattice and truncated on a sphere of radius
// `support` (a fixed number of monopole widths); support_plan.hpp tabulates them once per configuration.
// Units: lengths in a_1.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "fcm/sheared_grid.hpp"
#include "fcm/support_plan.hpp"

namespace suspend::fcm {

// The Gaussians put on the grid. Without spectral splitting they are the FCM envelopes (envelope.hpp); with a
// split width c (solver.hpp) they are the narrower tau = sqrt(sigma^2 - c^2) and the Green's function supplies the
// rest (Delta_sigma = Delta_tau * Delta_c).
struct Envelope {
  Vec3 centre = Vec3::Zero();
  double sigma_m = 0.0;  // monopole width on the grid (tau_M)
  double sigma_d = 0.0;  // dipole width on the grid (tau_D)
  double support = 0.0;  // truncation radius
};
// Truncated at truncation_widths x the (narrow) monopole width; split < dipole_width(radius).
Envelope make_envelope(const Vec3& centre, double radius, double truncation_widths, double split = 0.0);

// The dipole tensor G from a torque and a (symmetric) stresslet, and the angular velocity and rate of strain
// from an interpolated gradient moment A.
Mat3 dipole_tensor(const Vec3& torque, const Mat3& stresslet);
Vec3 angular_velocity_of(const Mat3& gradient_moment);
Mat3 strain_rate_of(const Mat3& gradient_moment);

// Adds the force density of all particles to the field (component c at field + c * stride). `forces` or
// `dipoles` may be empty (treated as zero); both are indexed by particle. OpenMP-parallel: each thread owns a slab
// of z planes holding an equal share of the support nodes (plan.plane_nodes), so no two threads write the same
// node. Particles are visited in the plan's (spatially sorted) order, which keeps the touched rows in cache.
void spread(const SupportPlan& plan, std::span<const Vec3> forces, std::span<const Mat3> dipoles, double* field,
            std::size_t stride);

// Interpolates the velocity field onto every particle (velocities and/or gradient moments may be empty).
void interpolate(const SupportPlan& plan, const double* field, std::size_t stride, std::span<Vec3> velocities,
                 std::span<Mat3> gradient_moments);

// Row kernels: 8-lane AVX-512 ones where the CPU has them (x86-64 with GCC), else 4-lane AVX2 or the portable
// baseline (chosen at load time). The results agree to round-off. For tests and benchmarks: whether the 8-lane
// kernels exist on this CPU, and a process-wide switch (default on; off selects the 4-lane kernels).
bool wide_kernels_available();
void use_wide_kernels(bool on);

// The same for a one-off configuration: plans the supports (support_plan.hpp), then spreads / interpolates.
void spread(const ShearedGrid& grid, std::span<const Envelope> envelopes, std::span<const Vec3> forces,
            std::span<const Mat3> dipoles, double* field, std::size_t stride);
void interpolate(const ShearedGrid& grid, std::span<const Envelope> envelopes, const double* field,
                 std::size_t stride, std::span<Vec3> velocities, std::span<Mat3> gradient_moments);

}  // namespace suspend::fcm

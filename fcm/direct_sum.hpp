// Slow free-space reference for the spectral solver (OpenMM habit: a simple reference first): the FCM mobility
// of Gaussian force multipoles in unbounded fluid, by direct O(N^2) summation.
// The flow of a Gaussian force of width s1 averaged over a Gaussian of width s2 is the regularised Stokeslet
// with combined variance s^2 = s1^2 + s2^2 (Maxey & Patel 2001, eq. 2.10):
//   M(r) = A(r) I + B(r) r r^T / r^2,  c = 1 / (sqrt(2) s), x = c r,
//   4 pi A = erf(x)/(2r) - exp(-x^2)/(2 c sqrt(pi) r^2) + erf(x)/(4 c^2 r^3),
//   4 pi B = erf(x)/(2r) + 3 exp(-x^2)/(2 c sqrt(pi) r^2) - 3 erf(x)/(4 c^2 r^3),
// -> Oseen (I + rr/r^2)/(8 pi r) + s^2 (I - 3 rr/r^2)/(8 pi r^3) far away, A(0) = c/(3 pi sqrt(pi)) (= 1/(6 pi a)
// for two monopole envelopes). Dipoles use derivatives of M (4th-order central differences): with
// r = Y_m - Y_n, U_m = M F_n + d_l M_ij G_n,jl and A_m,ik = -d_k (M F_n)_i - d_k d_l M_ij G_n,jl
// (spreading.hpp for G and A). Self terms are the exact isolated-envelope values (envelope.hpp).
// This reproduces the Rotne-Prager-Yamakawa structure with the FCM regularisation. Units: eta = 1.
#pragma once
#include <span>

#include "core/vec.hpp"
#include "fcm/disturbance.hpp"

namespace suspend::fcm {

Mat3 regularised_stokeslet(const Vec3& r, double variance);

// Free-space disturbance of forces, torques and stresslets on spheres (any span may be empty).
Disturbance direct_sum(std::span<const Vec3> positions, std::span<const double> radii, std::span<const Vec3> forces,
                       std::span<const Vec3> torques, std::span<const Mat3> stresslets);

}  // namespace suspend::fcm

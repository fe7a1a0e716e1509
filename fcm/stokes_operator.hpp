// Spectral Stokes solve on the sheared periodic grid (Yeo & Maxey 2010 section 2; DESIGN.md section 6).
//   eta k^2 u(k) = (I - k k / k^2) f(k),  k = (k1, k2 - gamma_t k1, k3) the physical wavevector.
// The k = 0 mode is set to zero: the net force on the fluid is balanced by a uniform pressure gradient and the
// disturbance has zero mean (the imposed shear carries the mean flow). Nyquist planes are zeroed: on the sheared
// lattice they break the Hermitian symmetry a real field needs, and the envelopes put negligible weight there.
// Units: eta = 1.
#pragma once
#include "fcm/fft.hpp"
#include "fcm/sheared_grid.hpp"

namespace suspend::fcm {

// Replaces the forward transform of f held in fft.spectrum() by `scale` times that of u.
void apply_stokes_green(const ShearedGrid& grid, VectorFft& fft, double scale);

}  // namespace suspend::fcm

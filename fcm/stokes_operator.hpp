// Spectral Stokes solve on the sheared periodic grid (Yeo & Maxey 2010 section 2; docs/fcm.md).
//   eta k^2 u(k) = (I - k k / k^2) f(k),  k = (k1, k2 - gamma_t k1, k3) the physical wavevector.
// The k = 0 mode is set to zero: the net force on the fluid is balanced by a uniform pressure gradient and the
// disturbance has zero mean (the imposed shear carries the mean flow). Nyquist planes are zeroed: on the sheared
// lattice they break the Hermitian symmetry a real field needs, and the envelopes put negligible weight there.
// Spectral splitting (solver.hpp): the Green's function is multiplied by the window exp(-c^2 |k|^2), the Fourier
// transform of the Gaussian of variance 2 c^2 (one Delta_c for spreading, one for interpolation).
// Units: eta = 1.
#pragma once
#include <array>
#include <vector>

#include "fcm/fft.hpp"
#include "fcm/sheared_grid.hpp"

namespace suspend::fcm {

// exp(-c^2 |k|^2) on the modes of the grid's r2c spectrum, separated as xy[iy * (nx/2 + 1) + m1] * z[iz]
// (|k|^2 = k1^2 + (k2 - gamma_t k1)^2 + k3^2). update() recomputes it only when c, the grid or gamma_t changed.
struct SplitWindow {
  double split = 0.0;  // c (a_1); 0: no window
  std::vector<double> xy, z;
  void update(const ShearedGrid& grid, double c);

 private:
  double shear_fraction_ = 0.0;
  std::array<int, 3> n_{};
  Vec3 length_ = Vec3::Zero();
};

// Replaces the forward transform of f held in fft.spectrum() by `scale` times that of u (times the window, if
// given and non-empty).
void apply_stokes_green(const ShearedGrid& grid, VectorFft& fft, double scale, const SplitWindow* window = nullptr);

}  // namespace suspend::fcm

// The linear and non-linear response to an oscillatory shear, from a run's series over whole cycles.
//
// For a signal x(t) sampled over cycle k, [k T, (k+1) T) with T = 2 pi / omega and t = 0 the start of the run, the
// complex amplitude of harmonic n is X_n = (2/T) int x(t) e^{-i n omega t} dt (trapezoidal rule on the samples, the
// cycle's ends interpolated linearly). With the shear stress S and the shear rate R of the same cycle the complex
// viscosity is eta* = S_1 / R_1 = eta' - i eta''; for gamma = gamma_0 sin(omega t) and
// Sigma_xy = gamma_0 (G' sin(omega t) + G'' cos(omega t)) this gives
//   eta' = G'' / (eta_0 omega)  (dissipative),   eta'' = G' / (eta_0 omega)  (elastic),
// under rate or stress control alike (both signals are measured). Means and standard errors are over cycles.
// The higher harmonics of the response (the stress under rate control, the rate under stress control) are given
// as intensities I_n / I_1 = |X_n| / |X_1| for n = 3, 5, 7 (Fourier-transform rheology; Hyun et al., Prog. Polym.
// Sci. 36, 1697 (2011)).
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "io/statistics.hpp"

namespace suspend::io {

struct OscillatoryResponse {
  std::size_t cycles = 0;  // whole cycles in the window
  MeanWithError eta_prime, eta_double_prime;
  double strain_amplitude = 0.0;  // |R_1| / omega, mean over cycles
  double stress_amplitude = 0.0;  // |S_1|
  std::array<double, 3> harmonics{};  // I_3/I_1, I_5/I_1, I_7/I_1 of the response, mean over cycles
};

// Cycles that start at or after from_time and end by the last sample. `response_is_rate`: stress control.
OscillatoryResponse oscillatory_response(const std::vector<double>& time, const std::vector<double>& stress,
                                         const std::vector<double>& rate, double omega, double from_time,
                                         bool response_is_rate);

}  // namespace suspend::io

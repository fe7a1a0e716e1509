// The stress-dependent Maron-Pierce law of paper 004 (eq. 23), eta_r = alpha (1 - phi/phi_m)^-2, fitted to one
// group of (phi, eta_r +- sem) points by weighted least squares. For a given phi_m the best alpha is linear, so the
// fit minimises chi^2 over phi_m alone (a scan in log(phi_m - phi_max), then golden-section refinement).
// Uncertainties: parametric bootstrap (each eta_r redrawn from a normal of its standard error, inflated by
// sqrt(chi^2_reduced) when the scatter exceeds the error bars), seeded so that the numbers are reproducible.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace suspend::campaign {

struct ViscosityPoint {
  double phi = 0.0;
  double eta = 0.0;  // relative viscosity
  double sem = 0.0;  // its standard error (> 0)
};

struct MaronPierceFit {
  double phi_m = 0.0, phi_m_err = 0.0;
  double alpha = 0.0, alpha_err = 0.0;
  double chi2_reduced = 0.0;  // chi^2 / (points - 2)
  int points = 0;
  bool bracketed = true;  // false: chi^2 still falls at phi_m = 1 (the data do not pin the divergence)
};

// Best (alpha, phi_m) with bootstrap errors; nullopt with `why` set when the data cannot be fitted (fewer than three
// points, non-positive errors).
std::optional<MaronPierceFit> fit_maron_pierce(const std::vector<ViscosityPoint>& points, std::string* why = nullptr,
                                               int resamples = 1000, std::uint64_t seed = 1);

// eta_r = alpha (1 - phi/phi_m)^-n with a free exponent n (paper 004 mentions it for mu_s = 0): the best (alpha,
// phi_m, n) by weighted least squares (alpha linear, phi_m and n scanned then refined), and chi^2 / (points - 3); no
// bootstrap: it describes the points near phi_m, the Maron-Pierce fit and the bracket carry the errors. nullopt with
// `why` set below four points or on degenerate data.
struct FreeExponentFit {
  double phi_m = 0.0, exponent = 0.0, alpha = 0.0, chi2_reduced = 0.0;
};
std::optional<FreeExponentFit> fit_free_exponent(const std::vector<ViscosityPoint>& points, std::string* why = nullptr);

// Paper 004 eq. 23.
inline double maron_pierce(double phi, double alpha, double phi_m) {
  const double x = 1.0 - phi / phi_m;
  return alpha / (x * x);
}

}  // namespace suspend::campaign

// The one place where the papers' dimensionless groups become the code's units (docs/units.md).
// Code units: eta_0 = 1, length a_1 (smallest radius), time 1/gammadot_ref, force eta_0 gammadot_ref a_1^2.
#pragma once

namespace suspend::io {

// Paper 000, eq. 12: k-hat = k_n / (eta_0 a_0 gammadot) with a_0 = a_1, so k_n [eta_0 gammadot a_1] = k-hat.
inline double stiffness_from_k_hat(double k_hat) { return k_hat; }
inline double k_hat_from_stiffness(double kn) { return kn; }

}  // namespace suspend::io

// The quantities papers plot, derived from one summary.json (means and standard errors, first-order propagation
// with independent errors): contact-stress ratios, the macroscopic friction and the viscous number.
// Sigma^c is every non-hydrodynamic contribution (contact normal and tangential, repulsion, adhesion).
#pragma once
#include <nlohmann/json.hpp>

namespace suspend::io {

// Keys (each {"mean", "sem"}): eta_r, N1, N2, Pi, Sigma_c12/Sigma_12, Sigma_c22/Sigma_12, Sigma_c11/Sigma_c12,
// mu = -Sigma_12 / Sigma^c_22 and J = -eta_0 gammadot / Sigma^c_22 (paper 004 section III E), sigma_star and G_adh
// when the summary has them.
nlohmann::ordered_json derived_rheology(const nlohmann::ordered_json& summary);

}  // namespace suspend::io

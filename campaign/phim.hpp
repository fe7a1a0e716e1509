// `suspend phim`: phi_m(sigma*) from a campaign table (paper 004 section III C). Points are grouped by
// hydrodynamic model, mu_s and sigma*; each group with at least three flowing points gets a Maron-Pierce fit
// (maron_pierce.hpp). Under imposed stress sigma* is the imposed value (Sigma_12 / G_adh in case units); under an
// imposed rate it varies from point to point, so each sequence of points at one phi is interpolated at the target
// sigma* values, linearly in log sigma* for log eta_r (and its relative error), as the paper does. Non-adhesive
// points (g_adh = 0) form the sigma* = infinity group. Jammed points below a group's fitted phi_m are flagged.
#pragma once
#include <nlohmann/json.hpp>
#include <vector>

namespace suspend::campaign {

struct PhimOptions {
  double min_phi = 0.0;                                    // fit only points at phi >= min_phi (paper: 0.45 for mu_s <= 0.1)
  std::vector<double> sigma_stars = {0.7, 1, 2, 5, 10};    // interpolation targets for rate-controlled points
  int resamples = 1000;                                    // bootstrap draws per fit
};

// {"fits": [{"model", "mu_s", "sigma_star" (null: infinite), "phi_m", "phi_m_err", "alpha", "alpha_err", "points",
//   "chi2_reduced", "bracketed", "jammed_below_phi_m", "data": [[phi, eta, sem], ...], "note"}], "min_phi"}
nlohmann::ordered_json fit_phim(const nlohmann::ordered_json& campaign_table, const PhimOptions& o);
std::string phim_csv(const nlohmann::ordered_json& fits);

}  // namespace suspend::campaign

#include "io/summary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <limits>
#include <stdexcept>

#include "analysis/contact_network.hpp"
#include "core/error.hpp"
#include "core/stress.hpp"
#include "io/run_file.hpp"
#include "io/snapshot_reader.hpp"
#include "io/statistics.hpp"

namespace suspend::io {

nlohmann::json summary_entry(const MeanWithError& m) { return {{"mean", m.mean}, {"sem", m.sem}}; }

namespace {
// eta_r, N1, N2, Pi of one stress series (columns xx yy zz xy xz yz) over the window rows. mean_rate null: each row
// divided by its own shear rate (imposed rate); else the window means divided by *mean_rate, and the rate's standard
// error is propagated to first order (independent errors).
nlohmann::json stress_observables(hid_t f, const std::string& series, const std::vector<double>& rate,
                                  const std::vector<std::size_t>& window, const MeanWithError* mean_rate) {
  std::vector<std::vector<double>> c(6);
  for (int k = 0; k < 6; ++k) c[k] = read_series(f, series, k);
  std::vector<double> eta, n1, n2, pi;
  for (std::size_t r : window) {
    const double g = mean_rate ? 1.0 : rate[r];
    eta.push_back(c[3][r] / g);
    n1.push_back((c[0][r] - c[1][r]) / g);
    n2.push_back((c[1][r] - c[2][r]) / g);
    pi.push_back(-(c[0][r] + c[1][r] + c[2][r]) / 3.0 / g);
  }
  auto scaled = [&](const std::vector<double>& v) {
    MeanWithError m = block_average(v);
    if (mean_rate) {
      const double g = mean_rate->mean, sg = mean_rate->sem;
      m = {m.mean / g, std::hypot(m.sem / g, m.mean * sg / (g * g))};
    }
    return summary_entry(m);
  };
  return {{"eta_r", scaled(eta)}, {"N1", scaled(n1)}, {"N2", scaled(n2)}, {"Pi", scaled(pi)}};
}

// Window averages over the snapshots (analysis/; docs/output.md "Microstructure"): the contact network is not in the
// series, so these are means over the snapshots with strain >= from.
nlohmann::json microstructure(hid_t f, double from, const char* strain_attribute) {
  std::vector<double> sliding, rattlers, largest, spanning;
  bool details = true;
  const std::size_t count = snapshot_count(f);
  for (std::size_t k = 0; k < count; ++k) {
    const std::string g = snapshot_group(k);
    const double strain = h5::has_attribute(f, g, strain_attribute) ? h5::double_attribute(f, g, strain_attribute)
                                                                     : h5::double_attribute(f, g, "strain");
    if (strain < from) continue;
    analysis::Configuration c;
    try {
      c = read_configuration(f, k);
    } catch (const InputError&) {
      continue;  // the failing state a failed run keeps as its last snapshot (non-finite by design): no average's
    }
    if (c.size() == 0) continue;
    const analysis::ContactNumbers z = analysis::contact_numbers(c);
    const analysis::ClusterStatistics cl = analysis::clusters(c);
    details = details && c.contact_details;
    sliding.push_back(z.sliding_fraction);
    rattlers.push_back(z.rattler_fraction);
    largest.push_back(static_cast<double>(cl.largest) / static_cast<double>(c.size()));
    spanning.push_back(cl.percolates[0] || cl.percolates[1] || cl.percolates[2] ? 1.0 : 0.0);
  }
  nlohmann::json j;
  j["snapshots"] = sliding.size();
  if (sliding.empty()) return j;
  j["sliding_fraction"] = details ? summary_entry(block_average(sliding)) : nlohmann::json();
  j["rattler_fraction"] = summary_entry(block_average(rattlers));
  j["largest_cluster_fraction"] = summary_entry(block_average(largest));
  j["spanning_fraction"] = block_average(spanning).mean;
  return j;
}

}  // namespace

nlohmann::json summarize(hid_t f, const SummaryContext& ctx) {
  const bool signed_strain = ctx.flow.counts_signed_strain();
  const std::vector<double> strain = read_series(f, signed_strain ? "strain" : "accumulated_strain");
  const std::vector<double> rate = read_series(f, "shear_rate");
  std::vector<std::size_t> window;
  for (std::size_t r = 0; r < strain.size(); ++r)
    if (strain[r] >= ctx.average_from) window.push_back(r);
  nlohmann::json j;
  std::vector<double> window_rate;
  for (std::size_t r : window) window_rate.push_back(rate[r]);
  MeanWithError mean_rate = block_average(window_rate);
  const SummaryInputs in{f, ctx, strain, rate, window};
  const std::optional<MeanWithError> scale = ctx.protocol ? ctx.protocol->rate_scale(in) : std::nullopt;
  const MeanWithError* by_mean = scale ? &*scale : ctx.stress_control ? &mean_rate : nullptr;
  j["note"] = ctx.stress_control
                  ? "imposed shear stress: stresses are divided by eta_0 times the mean shear rate of the window"
                  : "normal stresses and pressure are divided by eta_0 times the shear rate of each sample";
  j["shear_rate"] = summary_entry(mean_rate);
  j["phi"] = ctx.phi;
  j["particles"] = ctx.particles;
  j["window"] = {{"from_strain", ctx.average_from}, {"to_strain", strain.empty() ? 0.0 : strain.back()}};
  j["samples"] = window.size();
  const nlohmann::json total = stress_observables(f, "stress/total", rate, window, by_mean);
  for (const auto& [k, v] : total.items()) j[k] = v;
  for (auto name : contribution_names)
    j["contributions"][std::string(name)] = stress_observables(f, "stress/" + std::string(name), rate, window, by_mean);
  if (ctx.protocol) ctx.protocol->summarise(in, j);
  std::vector<double> contacts = read_series(f, "contacts"), overlap = read_series(f, "max_overlap");
  std::vector<double> wc, wo;
  for (std::size_t r : window) wc.push_back(contacts[r]), wo.push_back(overlap[r]);
  const MeanWithError z = block_average(wc);
  j["contacts"] = summary_entry(z);
  const double n = static_cast<double>(std::max<std::size_t>(ctx.particles, 1));
  // Z, the mean number of contacts of a particle: every contact (pair) touches two particles.
  j["contacts_per_particle"] = summary_entry({2.0 * z.mean / n, 2.0 * z.sem / n});
  j["max_overlap"] = summary_entry(block_average(wo));
  j["microstructure"] = microstructure(f, ctx.average_from, signed_strain ? "strain" : "accumulated_strain");
  if (ctx.adhesion_force > 0.0) {
    // Paper 004: sigma* = 6 pi Sigma_xy a_1^2 / F_adh, G_adh = F_adh / (6 pi eta_0 a_1^2 gammadot).
    const std::vector<double> sxy = read_series(f, "stress/total", 3);
    std::vector<double> sigma_star;
    for (std::size_t r : window) sigma_star.push_back(6.0 * std::numbers::pi * sxy[r] / ctx.adhesion_force);
    j["sigma_star"] = summary_entry(block_average(sigma_star));
    const double g = ctx.adhesion_force / (6.0 * std::numbers::pi);
    j["G_adh"] = summary_entry({g / mean_rate.mean, g * mean_rate.sem / (mean_rate.mean * mean_rate.mean)});
  }
  return j;
}

}  // namespace suspend::io

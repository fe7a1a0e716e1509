#include "io/summary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <limits>
#include <stdexcept>

#include "analysis/contact_network.hpp"
#include "core/error.hpp"
#include "core/stress.hpp"
#include "io/run_file.hpp"
#include "io/oscillatory_response.hpp"
#include "io/snapshot_reader.hpp"
#include "io/statistics.hpp"

namespace suspend::io {

namespace {
nlohmann::json entry(const MeanWithError& m) { return {{"mean", m.mean}, {"sem", m.sem}}; }

// eta_r, N1, N2, Pi of one stress series (columns xx yy zz xy xz yz). Under an imposed rate each row is divided by
// its own shear rate; under an imposed stress the window means are divided by the mean rate, and the rate's
// standard error is propagated (first order, independent errors).
nlohmann::json observables(hid_t f, const std::string& series, const std::vector<double>& rate,
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
    return entry(m);
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
  j["sliding_fraction"] = details ? entry(block_average(sliding)) : nlohmann::json();
  j["rattler_fraction"] = entry(block_average(rattlers));
  j["largest_cluster_fraction"] = entry(block_average(largest));
  j["spanning_fraction"] = block_average(spanning).mean;
  return j;
}

nlohmann::json optional_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

// eta', eta'' of the total stress and of each contribution, the amplitudes and the response's harmonics.
// t, rate: the series' time and shear_rate columns.
nlohmann::json oscillation(hid_t f, const SummaryContext& ctx, const std::vector<double>& t,
                           const std::vector<double>& rate, double from_time, double* rate_amplitude) {
  const double omega = ctx.flow.angular_frequency;
  const bool stress_control = ctx.flow.control == FlowControl::stress;
  auto of = [&](const std::string& series) {
    return oscillatory_response(t, read_series(f, series, 3), rate, omega, from_time, stress_control);
  };
  const OscillatoryResponse total = of("stress/total");
  *rate_amplitude = total.strain_amplitude * omega;
  nlohmann::json j;
  j["angular_frequency"] = omega;
  j["period"] = ctx.flow.period();
  j["cycles"] = total.cycles;
  j["from_time"] = from_time;
  auto both = [](const OscillatoryResponse& r) {
    return nlohmann::json{
        {"eta_prime", {{"mean", optional_number(r.eta_prime.mean)}, {"sem", optional_number(r.eta_prime.sem)}}},
        {"eta_double_prime",
         {{"mean", optional_number(r.eta_double_prime.mean)}, {"sem", optional_number(r.eta_double_prime.sem)}}}};
  };
  j.update(both(total));
  j["G_prime"] = optional_number(omega * total.eta_double_prime.mean);
  j["G_double_prime"] = optional_number(omega * total.eta_prime.mean);
  j["strain_amplitude"] = optional_number(total.strain_amplitude);
  j["stress_amplitude"] = optional_number(total.stress_amplitude);
  j["harmonics"] = {{"response", stress_control ? "shear_rate" : "shear_stress"},
                    {"I3_I1", optional_number(total.harmonics[0])},
                    {"I5_I1", optional_number(total.harmonics[1])},
                    {"I7_I1", optional_number(total.harmonics[2])}};
  for (auto name : contribution_names)
    j["contributions"][std::string(name)] = both(of("stress/" + std::string(name)));
  return j;
}

// Each reversal's transient: the viscosity Sigma_xy / gammadot over the last strain unit before it, its minimum
// after it and where, and its mean over the last strain unit before the next reversal or the end.
// strain, rate: the series' accumulated_strain and shear_rate columns.
nlohmann::json reversals(hid_t f, const SummaryContext& ctx, const std::vector<double>& strain,
                         const std::vector<double>& rate) {
  const std::vector<double> sxy = read_series(f, "stress/total", 3);
  nlohmann::json out = nlohmann::json::array();
  const std::vector<double>& at = ctx.flow.reverse_at;
  const double end = strain.empty() ? 0.0 : strain.back();
  for (std::size_t k = 0; k < at.size() && at[k] < end; ++k) {
    const double next = k + 1 < at.size() ? std::min(at[k + 1], end) : end;
    std::vector<double> before, after;
    double eta_min = std::numeric_limits<double>::infinity(), strain_of_min = 0.0;
    for (std::size_t r = 0; r < strain.size(); ++r) {
      const double eta = sxy[r] / rate[r];
      if (strain[r] >= at[k] - 1.0 && strain[r] < at[k] * (1.0 - 1e-12)) before.push_back(eta);
      if (strain[r] > at[k] * (1.0 + 1e-12) && strain[r] <= next) {
        if (eta < eta_min) eta_min = eta, strain_of_min = strain[r] - at[k];
        if (strain[r] >= next - 1.0) after.push_back(eta);
      }
    }
    out.push_back({{"at_strain", at[k]},
                   {"eta_before", before.empty() ? nlohmann::json() : entry(block_average(before, 4))},
                   {"eta_min", std::isfinite(eta_min) ? nlohmann::json(eta_min) : nlohmann::json()},
                   {"strain_of_min", strain_of_min},
                   {"eta_after", after.empty() ? nlohmann::json() : entry(block_average(after, 4))},
                   {"after_to_strain", next}});
  }
  return out;
}

}  // namespace

nlohmann::json summarize(hid_t f, const SummaryContext& ctx) {
  const bool steady = ctx.flow.steady();
  const std::vector<double> strain = read_series(f, steady ? "strain" : "accumulated_strain");
  const std::vector<double> rate = read_series(f, "shear_rate");
  std::vector<std::size_t> window;
  for (std::size_t r = 0; r < strain.size(); ++r)
    if (strain[r] >= ctx.average_from) window.push_back(r);
  nlohmann::json j;
  std::vector<double> window_rate;
  for (std::size_t r : window) window_rate.push_back(rate[r]);
  MeanWithError mean_rate = block_average(window_rate);
  const MeanWithError* by_mean = ctx.stress_control ? &mean_rate : nullptr;
  nlohmann::json oscillatory;
  MeanWithError rate_amplitude;
  if (ctx.flow.oscillatory()) {
    const std::vector<double> t = read_series(f, "time");
    const double from_time = window.empty() ? (t.empty() ? 0.0 : t.back()) : t[window.front()];
    oscillatory = oscillation(f, ctx, t, rate, from_time, &rate_amplitude.mean);
    by_mean = &rate_amplitude;  // N1, N2, Pi over the rate amplitude; eta_r below is eta'
  }
  j["note"] = ctx.flow.oscillatory()
                  ? "oscillatory shear: eta_r is eta' (io/oscillatory_response.hpp); N1, N2, Pi are window means "
                    "divided by eta_0 times the shear-rate amplitude"
              : ctx.stress_control
                  ? "imposed shear stress: stresses are divided by eta_0 times the mean shear rate of the window"
                  : "normal stresses and pressure are divided by eta_0 times the shear rate of each sample";
  j["shear_rate"] = entry(mean_rate);
  j["phi"] = ctx.phi;
  j["particles"] = ctx.particles;
  j["window"] = {{"from_strain", ctx.average_from}, {"to_strain", strain.empty() ? 0.0 : strain.back()}};
  j["samples"] = window.size();
  const nlohmann::json total = observables(f, "stress/total", rate, window, by_mean);
  for (const auto& [k, v] : total.items()) j[k] = v;
  for (auto name : contribution_names)
    j["contributions"][std::string(name)] = observables(f, "stress/" + std::string(name), rate, window, by_mean);
  if (ctx.flow.oscillatory()) {
    j["eta_r"] = oscillatory["eta_prime"];
    for (auto name : contribution_names)
      j["contributions"][std::string(name)]["eta_r"] = oscillatory["contributions"][std::string(name)]["eta_prime"];
    j["oscillatory"] = oscillatory;
  }
  if (ctx.flow.protocol == FlowProtocol::reversal) j["reversals"] = reversals(f, ctx, strain, rate);
  std::vector<double> contacts = read_series(f, "contacts"), overlap = read_series(f, "max_overlap");
  std::vector<double> wc, wo;
  for (std::size_t r : window) wc.push_back(contacts[r]), wo.push_back(overlap[r]);
  const MeanWithError z = block_average(wc);
  j["contacts"] = entry(z);
  const double n = static_cast<double>(std::max<std::size_t>(ctx.particles, 1));
  // Z, the mean number of contacts of a particle: every contact (pair) touches two particles.
  j["contacts_per_particle"] = entry({2.0 * z.mean / n, 2.0 * z.sem / n});
  j["max_overlap"] = entry(block_average(wo));
  j["microstructure"] = microstructure(f, ctx.average_from, steady ? "strain" : "accumulated_strain");
  if (ctx.adhesion_force > 0.0) {
    // Paper 004: sigma* = 6 pi Sigma_xy a_1^2 / F_adh, G_adh = F_adh / (6 pi eta_0 a_1^2 gammadot).
    const std::vector<double> sxy = read_series(f, "stress/total", 3);
    std::vector<double> sigma_star;
    for (std::size_t r : window) sigma_star.push_back(6.0 * std::numbers::pi * sxy[r] / ctx.adhesion_force);
    j["sigma_star"] = entry(block_average(sigma_star));
    const double g = ctx.adhesion_force / (6.0 * std::numbers::pi);
    j["G_adh"] = entry({g / mean_rate.mean, g * mean_rate.sem / (mean_rate.mean * mean_rate.mean)});
  }
  return j;
}

}  // namespace suspend::io

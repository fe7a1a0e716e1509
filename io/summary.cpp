#include "io/summary.hpp"

#include <stdexcept>

#include "core/stress.hpp"
#include "io/run_file.hpp"
#include "io/statistics.hpp"

namespace suspend::io {

namespace {
nlohmann::json entry(const MeanWithError& m) { return {{"mean", m.mean}, {"sem", m.sem}}; }

// eta_r, N1, N2, Pi of one stress series (columns xx yy zz xy xz yz), normalised by the shear rate of each row.
nlohmann::json observables(hid_t f, const std::string& series, const std::vector<double>& rate,
                           const std::vector<std::size_t>& window) {
  std::vector<std::vector<double>> c(6);
  for (int k = 0; k < 6; ++k) c[k] = read_series(f, series, k);
  std::vector<double> eta, n1, n2, pi;
  for (std::size_t r : window) {
    eta.push_back(c[3][r] / rate[r]);
    n1.push_back((c[0][r] - c[1][r]) / rate[r]);
    n2.push_back((c[1][r] - c[2][r]) / rate[r]);
    pi.push_back(-(c[0][r] + c[1][r] + c[2][r]) / 3.0 / rate[r]);
  }
  return {{"eta_r", entry(block_average(eta))},
          {"N1", entry(block_average(n1))},
          {"N2", entry(block_average(n2))},
          {"Pi", entry(block_average(pi))}};
}
}  // namespace

nlohmann::json summarize(hid_t f, const SummaryContext& ctx) {
  const std::vector<double> strain = read_series(f, "strain");
  const std::vector<double> rate = read_series(f, "shear_rate");
  std::vector<std::size_t> window;
  for (std::size_t r = 0; r < strain.size(); ++r)
    if (strain[r] >= ctx.average_from) window.push_back(r);
  nlohmann::json j;
  j["note"] = "normal stresses and pressure are divided by eta_0 times the shear rate of each sample";
  j["phi"] = ctx.phi;
  j["particles"] = ctx.particles;
  j["window"] = {{"from_strain", ctx.average_from}, {"to_strain", strain.empty() ? 0.0 : strain.back()}};
  j["samples"] = window.size();
  const nlohmann::json total = observables(f, "stress/total", rate, window);
  for (const auto& [k, v] : total.items()) j[k] = v;
  for (auto name : contribution_names)
    j["contributions"][std::string(name)] = observables(f, "stress/" + std::string(name), rate, window);
  std::vector<double> contacts = read_series(f, "contacts"), overlap = read_series(f, "max_overlap");
  std::vector<double> wc, wo;
  for (std::size_t r : window) wc.push_back(contacts[r]), wo.push_back(overlap[r]);
  j["contacts"] = entry(block_average(wc));
  j["max_overlap"] = entry(block_average(wo));
  return j;
}

}  // namespace suspend::io

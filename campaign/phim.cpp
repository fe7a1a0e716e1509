#include "campaign/phim.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>
#include <tuple>

#include "campaign/maron_pierce.hpp"

namespace suspend::campaign {

using json = nlohmann::ordered_json;

namespace {
constexpr double infinite = std::numeric_limits<double>::infinity();

double number(const json& v) { return v.is_number() ? v.get<double>() : std::nan(""); }

// sigma* to 6 significant digits, so that 2 and 2.0000000001 are one group.
double group_value(double s) {
  if (!std::isfinite(s)) return s;
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", s);
  return std::strtod(b, nullptr);
}

struct Group {
  std::vector<ViscosityPoint> points;
  std::vector<std::pair<std::string, double>> jammed;  // name, phi
  std::map<double, std::vector<ViscosityPoint>> seeds;  // flowing points by requested phi (several seeds each)
  std::map<double, std::pair<int, int>> outcomes;      // requested phi -> (seeds that flowed, seeds that jammed)
};

// The seeds of one requested phi as one point: the mean eta_r, with the larger of two standard errors of that mean,
// the seeds' own scatter (sd / sqrt(n), which holds the packing-to-packing spread) and their block errors combined
// (sqrt(sum sem^2) / n); one seed is itself.
ViscosityPoint merge_seeds(const std::vector<ViscosityPoint>& s) {
  if (s.size() == 1) return s.front();
  const double n = static_cast<double>(s.size());
  ViscosityPoint m{0.0, 0.0, 0.0};
  double sem2 = 0.0;
  for (const ViscosityPoint& q : s) m.phi += q.phi / n, m.eta += q.eta / n, sem2 += q.sem * q.sem;
  double var = 0.0;
  for (const ViscosityPoint& q : s) var += (q.eta - m.eta) * (q.eta - m.eta) / (n - 1.0);
  m.sem = std::max(std::sqrt(var / n), std::sqrt(sem2) / n);
  return m;
}
using Key = std::tuple<std::string, double, double>;  // model, mu_s, sigma*

// Rate-controlled adhesive points at one phi, interpolated at each target sigma* inside their range.
void interpolate(std::vector<std::tuple<double, double, double, double>> seq, const PhimOptions& o,
                 const std::string& model, double mu_s, std::map<Key, Group>& groups) {
  // seq: (sigma*, phi, eta, sem), sorted by sigma*
  std::sort(seq.begin(), seq.end());
  for (double target : o.sigma_stars)
    for (std::size_t k = 0; k + 1 < seq.size(); ++k) {
      const auto& [s0, p0, e0, d0] = seq[k];
      const auto& [s1, p1, e1, d1] = seq[k + 1];
      if (!(s0 <= target && target <= s1) || s0 == s1) continue;
      const double w = (std::log(target) - std::log(s0)) / (std::log(s1) - std::log(s0));
      const double eta = std::exp((1 - w) * std::log(e0) + w * std::log(e1));
      const double rel = (1 - w) * d0 / e0 + w * d1 / e1;
      groups[{model, mu_s, group_value(target)}].points.push_back({(1 - w) * p0 + w * p1, eta, rel * eta});
      break;
    }
}
}  // namespace

json fit_phim(const json& table, const PhimOptions& o) {
  std::map<Key, Group> groups;
  std::map<std::tuple<std::string, double, double>, std::vector<std::tuple<double, double, double, double>>> sequences;
  for (const json& e : table["points"]) {
    const json& c = e["case"];
    const std::string model = c["model"].get<std::string>();
    const double mu_s = c["mu_s"].get<double>(), g_adh = c["g_adh"].get<double>();
    const bool stress = c["control"] == "stress";
    const std::string status = e["status"].get<std::string>();
    const double requested_phi = group_value(c["phi"].get<double>());
    if (status == "jammed") {
      const double s = g_adh > 0 && stress ? group_value(c["shear_stress"].get<double>() / g_adh) : infinite;
      if (stress || g_adh == 0) {
        groups[{model, mu_s, s}].jammed.emplace_back(e["name"], c["phi"].get<double>());
        ++groups[{model, mu_s, s}].outcomes[requested_phi].second;
      }
      continue;
    }
    if (status != "done" || e["summary"].is_null()) continue;
    const double phi = number(e["summary"]["phi"]);
    if (phi < o.min_phi) continue;
    const double eta = number(e["summary"]["eta_r"]["mean"]), sem = number(e["summary"]["eta_r"]["sem"]);
    if (g_adh == 0.0 || stress) {
      Group& g = groups[{model, mu_s, g_adh == 0.0 ? infinite : group_value(c["shear_stress"].get<double>() / g_adh)}];
      g.seeds[requested_phi].push_back({phi, eta, sem});
      ++g.outcomes[requested_phi].first;
    } else {
      sequences[{model, mu_s, c["phi"].get<double>()}].emplace_back(number(e["summary"]["sigma_star"]["mean"]), phi,
                                                                    eta, sem);
    }
  }
  for (const auto& [key, seq] : sequences) interpolate(seq, o, std::get<0>(key), std::get<1>(key), groups);

  json fits = json::array();
  for (auto& [key, g] : groups) {
    const auto& [model, mu_s, sigma_star] = key;
    for (const auto& [requested, s] : g.seeds) g.points.push_back(merge_seeds(s));
    std::sort(g.points.begin(), g.points.end(), [](const auto& a, const auto& b) { return a.phi < b.phi; });
    json f;
    f["model"] = model;
    f["mu_s"] = mu_s;
    f["sigma_star"] = std::isfinite(sigma_star) ? json(sigma_star) : json();
    std::string why;
    const auto fit = fit_maron_pierce(g.points, &why, o.resamples);
    f["points"] = g.points.size();
    if (fit) {
      f["phi_m"] = fit->phi_m;
      f["phi_m_err"] = fit->phi_m_err;
      f["alpha"] = fit->alpha;
      f["alpha_err"] = fit->alpha_err;
      f["chi2_reduced"] = fit->chi2_reduced;
      f["bracketed"] = fit->bracketed;
      json below = json::array();
      for (const auto& [name, phi] : g.jammed)
        if (phi < fit->phi_m) below.push_back(name);
      f["jammed_below_phi_m"] = below;
      if (!below.empty()) f["note"] = "jammed point(s) below the fitted phi_m";
      if (!fit->bracketed) f["note"] = "chi^2 still falls at phi_m = 1: the data do not pin the divergence";
      // Leave-one-point-out: how far phi_m moves without each point (a fit that depends on one point, or on a
      // law that does not describe the points, moves more than its bootstrap error says). The total error adds
      // it in quadrature to the bootstrap's (whose per-point errors hold the seed-to-seed scatter, merge_seeds).
      double lopo = 0.0;
      if (g.points.size() >= 4)
        for (std::size_t i = 0; i < g.points.size(); ++i) {
          std::vector<ViscosityPoint> rest = g.points;
          rest.erase(rest.begin() + static_cast<long>(i));
          if (const auto without = fit_maron_pierce(rest, nullptr, 1))
            lopo = std::max(lopo, std::abs(without->phi_m - fit->phi_m));
        }
      f["phi_m_err_lopo"] = g.points.size() >= 4 ? json(lopo) : json();
      if (const auto free = fit_free_exponent(g.points))
        f["free_exponent"] = {{"phi_m", free->phi_m}, {"exponent", free->exponent}, {"alpha", free->alpha},
                              {"chi2_reduced", free->chi2_reduced}};
      f["phi_m_err_total"] = std::hypot(fit->phi_m_err, lopo);
    } else {
      f["phi_m"] = nullptr;
      f["note"] = why;
    }
    // The bracket: the highest requested phi that a majority of its seeds flowed at, the lowest that a majority
    // (or half) jammed at. It is the group's phi_m when there is no fit, or when a jammed point or the bracket
    // itself contradicts the fit.
    double flows_hi = -1.0, jams_lo = 2.0;
    for (const auto& [phi, seeds] : g.outcomes)
      if (2 * seeds.first > seeds.first + seeds.second) flows_hi = std::max(flows_hi, phi);
      else jams_lo = std::min(jams_lo, phi);
    f["bracket"] = nullptr;
    std::string result = fit ? "fit" : "";
    if (flows_hi > 0.0 && jams_lo < 2.0) {
      const auto [lf, lj] = g.outcomes[flows_hi];
      const auto [uf, uj] = g.outcomes[jams_lo];
      f["bracket"] = {flows_hi, jams_lo};
      f["bracket_seeds"] = {lf + lj, uf + uj};
      f["bracket_flowing_fraction"] = {static_cast<double>(lf) / (lf + lj), static_cast<double>(uf) / (uf + uj)};
      if (flows_hi > jams_lo) {
        const std::string monotone = "not monotone: a majority flowed above a value where a majority jammed";
        f["note"] = f.contains("note") ? f["note"].get<std::string>() + "; " + monotone : monotone;
      }
      const bool contradicted =
          fit && (!f["jammed_below_phi_m"].empty() || fit->phi_m < flows_hi - f["phi_m_err_total"].get<double>() ||
                  fit->phi_m > jams_lo + f["phi_m_err_total"].get<double>());
      if (!fit || contradicted) result = "bracket";
    }
    f["result"] = result.empty() ? json() : json(result);
    json jammed = json::array();
    for (const auto& [name, phi] : g.jammed) jammed.push_back(phi);
    f["jammed_phi"] = jammed;
    json data = json::array();
    for (const ViscosityPoint& p : g.points) data.push_back({p.phi, p.eta, p.sem});
    f["data"] = data;
    fits.push_back(f);
  }
  return {{"min_phi", o.min_phi}, {"fits", fits}};
}

std::string phim_csv(const json& result) {
  std::ostringstream out;
  out << "model,mu_s,sigma_star,phi_m,phi_m_err,alpha,alpha_err,points,chi2_reduced,note,phi_m_err_total,result,"
         "bracket_lo,bracket_hi,seeds_lo,seeds_hi,flowing_lo,flowing_hi\n";
  auto cell = [&](const json& v) {
    if (v.is_number()) {
      char b[32];
      std::snprintf(b, sizeof b, "%.6g", v.get<double>());
      out << b;
    } else if (v.is_string()) {
      out << '"' << v.get<std::string>() << '"';
    }
  };
  for (const json& f : result["fits"]) {
    out << f["model"].get<std::string>() << ',';
    cell(f["mu_s"]);
    out << ',';
    if (f["sigma_star"].is_null()) out << "inf";
    else cell(f["sigma_star"]);
    for (const char* k : {"phi_m", "phi_m_err", "alpha", "alpha_err", "points", "chi2_reduced", "note",
                          "phi_m_err_total", "result"}) {
      out << ',';
      if (f.contains(k)) cell(f[k]);
    }
    for (const char* k : {"bracket", "bracket_seeds", "bracket_flowing_fraction"})
      for (int end = 0; end < 2; ++end) {
        out << ',';
        if (f.contains(k) && f[k].is_array()) cell(f[k][end]);
      }
    out << '\n';
  }
  return out.str();
}

}  // namespace suspend::campaign

// phi_m(sigma*) fits: the Maron-Pierce law (paper 004 eq. 23) recovered from synthetic data with a known phi_m and
// alpha, bootstrap errors that cover the truth as often as one standard deviation should, and the grouping of a
// campaign table (imposed stress, non-adhesive limit, rate-controlled points interpolated at constant sigma*).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "campaign/maron_pierce.hpp"
#include "campaign/phim.hpp"
#include "campaign/search.hpp"

using namespace suspend::campaign;
using json = nlohmann::ordered_json;

namespace {
std::vector<ViscosityPoint> synthetic(double alpha, double phi_m, double relative_error, std::mt19937_64* rng) {
  std::vector<ViscosityPoint> p;
  std::normal_distribution<double> noise(0.0, 1.0);
  for (double phi : {0.40, 0.44, 0.48, 0.52, 0.55}) {
    const double eta = maron_pierce(phi, alpha, phi_m);
    const double sem = relative_error * eta;
    p.push_back({phi, rng ? eta + sem * noise(*rng) : eta, sem});
  }
  return p;
}
}  // namespace

TEST(MaronPierce, ExactDataGiveTheLawBack) {
  const auto fit = fit_maron_pierce(synthetic(0.8, 0.59, 0.02, nullptr), nullptr, 200);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->phi_m, 0.59, 1e-7);
  EXPECT_NEAR(fit->alpha, 0.8, 1e-5);
  EXPECT_LT(fit->chi2_reduced, 1e-8);
  EXPECT_TRUE(fit->bracketed);
  EXPECT_EQ(fit->points, 5);
  // 2% errors on eta_r give phi_m to a few 1e-3 (the bootstrap's spread)
  EXPECT_GT(fit->phi_m_err, 1e-4);
  EXPECT_LT(fit->phi_m_err, 1e-2);
}

TEST(MaronPierce, BootstrapErrorsCoverTheTruthAsOneSigmaShould) {
  std::mt19937_64 rng(7);
  int within = 0, within_alpha = 0;
  const int sets = 120;
  for (int s = 0; s < sets; ++s) {
    const auto fit = fit_maron_pierce(synthetic(0.8, 0.59, 0.04, &rng), nullptr, 150, 100 + s);
    ASSERT_TRUE(fit);
    within += std::abs(fit->phi_m - 0.59) < fit->phi_m_err;
    within_alpha += std::abs(fit->alpha - 0.8) < fit->alpha_err;
  }
  // 68% expected; 120 sets give a binomial spread of about 4%.
  EXPECT_GT(within, 0.55 * sets);
  EXPECT_LT(within, 0.85 * sets);
  EXPECT_GT(within_alpha, 0.55 * sets);
  EXPECT_LT(within_alpha, 0.85 * sets);
}

TEST(MaronPierce, TooFewPointsAreSaidNotFitted) {
  std::string why;
  EXPECT_FALSE(fit_maron_pierce({{0.4, 5, 0.1}, {0.5, 20, 1}}, &why));
  EXPECT_NE(why.find("at least 3"), std::string::npos) << why;
  EXPECT_FALSE(fit_maron_pierce({{0.4, 5, 0.1}, {0.45, 8, 0.0}, {0.5, 20, 1}}, &why));
  EXPECT_NE(why.find("standard error"), std::string::npos) << why;
}

// Degenerate data (issue 37, item 3) are reported with the point, never fitted: 2fbb67f fitted infinite errors (all
// weights zero), negative viscosities and phi > 1 into numbers.
TEST(MaronPierce, DegenerateDataAreReportedNotFitted) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::pair<std::vector<ViscosityPoint>, std::string>> cases = {
      {{{0.4, 5, inf}, {0.45, 8, inf}, {0.5, 20, inf}}, "finite positive standard error (phi = 0.4"},
      {{{0.4, 5, 0.0}, {0.45, 8, 0.0}, {0.5, 20, 0.0}}, "finite positive standard error (phi = 0.4"},
      {{{0.4, 5, 0.1}, {0.45, -8, 0.2}, {0.5, 20, 1}}, "no finite positive eta_r (phi = 0.45, eta_r = -8"},
      {{{0.4, 5, 0.1}, {0.45, 8, 0.2}, {1.2, 20, 1}}, "phi outside (0, 1) (phi = 1.2"},
  };
  for (const auto& [points, fragment] : cases) {
    std::string why;
    EXPECT_FALSE(fit_maron_pierce(points, &why, 20)) << fragment;
    EXPECT_NE(why.find(fragment), std::string::npos) << why;
    EXPECT_EQ(why.rfind("not fitted", 0), 0u) << why;
  }
}

TEST(Phim, GroupsByMuAndSigmaStarFlagsJammedPointsAndInterpolatesRateControl) {
  auto point = [](const std::string& name, const std::string& status, const std::string& control, double mu_s,
                  double g_adh, double stress, double phi, double eta, double sigma_star) {
    json e;
    e["name"] = name;
    e["status"] = status;
    e["case"] = {{"model", "pairwise"}, {"control", control}, {"phi", phi}, {"mu_s", mu_s}, {"g_adh", g_adh}};
    if (control == "stress") e["case"]["shear_stress"] = stress;
    e["summary"] = nullptr;
    if (status == "done") {
      e["summary"] = {{"phi", phi}, {"eta_r", {{"mean", eta}, {"sem", 0.02 * eta}}}};
      if (g_adh > 0) e["summary"]["sigma_star"] = {{"mean", sigma_star}, {"sem", 0.0}};
    }
    return e;
  };
  json table;
  table["points"] = json::array();
  int n = 0;
  auto name = [](char prefix, int k) {  // (not "s" + std::to_string(k): a GCC 12 -Wrestrict false positive)
    std::string s(1, prefix);
    s += std::to_string(k);
    return s;
  };
  // Imposed stress: sigma* = Sigma / G_adh = 2 (one group even with two G_adh), and the non-adhesive limit.
  for (double phi : {0.40, 0.44, 0.48, 0.52}) {
    const double g = n++ % 2 ? 1.0 : 2.0;
    table["points"].push_back(point(name('s', n), "done", "stress", 0.5, g, 2.0 * g, phi,
                                    maron_pierce(phi, 0.9, 0.55), 2.0));
    table["points"].push_back(point(name('n', n), "done", "stress", 0.5, 0.0, 10.0, phi + 0.04,
                                    maron_pierce(phi + 0.04, 0.8, 0.60), 0.0));
  }
  table["points"].push_back(point("j1", "jammed", "stress", 0.5, 1.0, 2.0, 0.50, 0.0, 0.0));  // below 0.55: flagged
  table["points"].push_back(point("j2", "jammed", "stress", 0.5, 1.0, 2.0, 0.58, 0.0, 0.0));
  table["points"].push_back(point("f1", "failed", "stress", 0.5, 1.0, 2.0, 0.45, 0.0, 0.0));
  // Imposed rate at mu_s = 0.1: at each phi two G_adh whose measured sigma* bracket 1; eta_r is a power law of
  // sigma*, so log-log interpolation is exact: eta(phi, 1) = maron_pierce(phi, 0.7, 0.58).
  for (double phi : {0.40, 0.45, 0.50})
    for (double s : {0.5, 3.0}) {
      const double eta = maron_pierce(phi, 0.7, 0.58) * std::pow(s, -0.3);
      table["points"].push_back(point("r", "done", "rate", 0.1, 5.0, 0.0, phi, eta, s));
    }
  PhimOptions o;
  o.sigma_stars = {1.0};
  o.resamples = 100;
  const json r = fit_phim(table, o);
  ASSERT_EQ(r["fits"].size(), 3u) << r.dump(1);
  const json& rate = r["fits"][0];  // ordered by (model, mu_s, sigma*)
  EXPECT_EQ(rate["mu_s"], 0.1);
  EXPECT_EQ(rate["sigma_star"], 1.0);
  EXPECT_EQ(rate["points"], 3);
  EXPECT_NEAR(rate["phi_m"].get<double>(), 0.58, 1e-6);
  EXPECT_NEAR(rate["alpha"].get<double>(), 0.7, 1e-5);
  const json& s2 = r["fits"][1];
  EXPECT_EQ(s2["sigma_star"], 2.0);
  EXPECT_EQ(s2["points"], 4);
  EXPECT_NEAR(s2["phi_m"].get<double>(), 0.55, 1e-6);
  EXPECT_NEAR(s2["alpha"].get<double>(), 0.9, 1e-5);
  ASSERT_EQ(s2["jammed_below_phi_m"].size(), 1u);
  EXPECT_EQ(s2["jammed_below_phi_m"][0], "j1");
  const json& inf = r["fits"][2];
  EXPECT_TRUE(inf["sigma_star"].is_null());
  EXPECT_NEAR(inf["phi_m"].get<double>(), 0.60, 1e-6);
  EXPECT_NE(phim_csv(r).find("pairwise,0.5,inf,0.6,"), std::string::npos) << phim_csv(r);
  // min_phi drops the dilute points: the sigma* = 2 group keeps two and is said, not fitted.
  o.min_phi = 0.47;
  const json cut = fit_phim(table, o);
  EXPECT_TRUE(cut["fits"][1]["phi_m"].is_null());
  EXPECT_NE(cut["fits"][1]["note"].get<std::string>().find("at least 3"), std::string::npos);
}

// Seeds and brackets (issue 34): three seeds per phi under imposed stress. The bracket is the highest phi that a
// majority of its seeds flowed at and the lowest that a majority jammed at, with the seeds and flowing fractions at
// both ends; the seeds of one phi enter the fit as one point whose error holds their scatter; the total error holds
// the leave-one-point-out spread; a jammed point below the fitted phi_m makes the bracket the result.
TEST(Phim, SeedsGiveABracketWithItsFractionsAndATotalError) {
  json table;
  table["points"] = json::array();
  auto add = [&](double phi, int seed, bool flows, double eta) {
    json e;
    e["name"] = "p";
    e["status"] = flows ? "done" : "jammed";
    e["case"] = {{"model", "pairwise"}, {"control", "stress"}, {"phi", phi}, {"mu_s", 0.5}, {"g_adh", 1.0},
                 {"shear_stress", 1.0}};
    e["summary"] = nullptr;
    if (flows) e["summary"] = {{"phi", phi + 0.001 * seed}, {"eta_r", {{"mean", eta}, {"sem", 0.01 * eta}}}};
    table["points"].push_back(e);
  };
  // eta_r of Maron-Pierce (alpha 1, phi_m 0.55) with a seed-to-seed scatter of +-5%, far above the 1% block errors.
  for (double phi : {0.40, 0.44, 0.47, 0.49})
    for (int seed = 1; seed <= 3; ++seed) add(phi, seed, true, maron_pierce(phi, 1.0, 0.55) * (1.0 + 0.05 * (seed - 2)));
  add(0.50, 1, true, maron_pierce(0.50, 1.0, 0.55));
  add(0.50, 2, true, maron_pierce(0.50, 1.0, 0.55));
  add(0.50, 3, false, 0.0);
  add(0.52, 1, true, maron_pierce(0.52, 1.0, 0.55));
  add(0.52, 2, false, 0.0);
  add(0.52, 3, false, 0.0);
  for (int seed = 1; seed <= 3; ++seed) add(0.56, seed, false, 0.0);
  PhimOptions o;
  o.resamples = 200;
  const json r = fit_phim(table, o);
  ASSERT_EQ(r["fits"].size(), 1u);
  const json& f = r["fits"][0];
  EXPECT_EQ(f["bracket"], json::parse("[0.5, 0.52]"));
  EXPECT_EQ(f["bracket_seeds"], json::parse("[3, 3]"));
  EXPECT_NEAR(f["bracket_flowing_fraction"][0].get<double>(), 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(f["bracket_flowing_fraction"][1].get<double>(), 1.0 / 3.0, 1e-12);
  // One point per phi (0.40, 0.44, 0.47, 0.49, 0.50 and the lone flowing seed of 0.52), the 5% scatter in the errors.
  ASSERT_EQ(f["points"], 6);
  const json& at040 = f["data"][0];
  EXPECT_NEAR(at040[1].get<double>(), maron_pierce(0.40, 1.0, 0.55), 1e-9);
  EXPECT_NEAR(at040[2].get<double>(), 0.05 * maron_pierce(0.40, 1.0, 0.55) / std::sqrt(3.0), 1e-9);
  ASSERT_TRUE(f["phi_m"].is_number());
  EXPECT_GE(f["phi_m_err_total"].get<double>(), f["phi_m_err_lopo"].get<double>());
  EXPECT_GE(f["phi_m_err_total"].get<double>(), f["phi_m_err"].get<double>());
  // The jammed seed at 0.50 lies below phi_m ~ 0.55: the fit is contradicted, the bracket is the result.
  EXPECT_FALSE(f["jammed_below_phi_m"].empty());
  EXPECT_EQ(f["result"], "bracket");
}

// The free-exponent law eta_r = alpha (1 - phi/phi_m)^-n recovers n, phi_m and alpha of exact data, and needs four
// points (issue 34: a description of the points near phi_m beside Maron-Pierce's n = 2).
TEST(MaronPierce, AFreeExponentIsRecoveredFromExactData) {
  std::vector<ViscosityPoint> p;
  for (double phi : {0.40, 0.44, 0.48, 0.51, 0.53}) {
    const double eta = 0.7 * std::pow(1.0 - phi / 0.57, -2.6);
    p.push_back({phi, eta, 0.01 * eta});
  }
  const auto f = fit_free_exponent(p);
  ASSERT_TRUE(f);
  EXPECT_NEAR(f->exponent, 2.6, 1e-4);
  EXPECT_NEAR(f->phi_m, 0.57, 1e-5);
  EXPECT_NEAR(f->alpha, 0.7, 1e-3);
  EXPECT_LT(f->chi2_reduced, 1e-6);
  std::string why;
  EXPECT_FALSE(fit_free_exponent({p.begin(), p.begin() + 3}, &why));
  EXPECT_NE(why.find("at least 4"), std::string::npos) << why;
}

TEST(SearchEstimate, PointsToComeAreTheSeedsOfTheHalvingsLeft) {
  Campaign c;
  c.search = Search{"particles.phi", 0.40, 0.64, 0.01, 3};
  GroupSearch ends;  // only the two ends planned: 0.24 wide takes 5 halvings (0.24 / 2^5 = 0.0075)
  ends.state = "searching";
  GroupSearch bracket;  // bracket [0.52, 0.55] with its midpoint planned: one halving after it
  bracket.state = "searching";
  bracket.bracketed = true;
  bracket.flow_end = 0.52;
  bracket.jam_end = 0.55;
  GroupSearch last = bracket;  // [0.52, 0.54]: the planned midpoint is the last
  last.jam_end = 0.54;
  GroupSearch done = bracket;
  done.state = "converged";
  EXPECT_EQ(points_to_come(c, {ends}), 15);
  EXPECT_EQ(points_to_come(c, {bracket}), 3);
  EXPECT_EQ(points_to_come(c, {last, done}), 0);
  EXPECT_EQ(points_to_come(c, {ends, bracket, last, done}), 18);
  c.search.reset();
  EXPECT_EQ(points_to_come(c, {ends}), 0);
}

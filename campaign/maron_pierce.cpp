#include "campaign/maron_pierce.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace suspend::campaign {

namespace {
struct Best {
  double phi_m = 0.0, alpha = 0.0, chi2 = 0.0;
  bool bracketed = true;
};

// chi^2 at phi_m with the optimal alpha = sum(eta f / s^2) / sum(f^2 / s^2), f = (1 - phi/phi_m)^-2.
double profile(const std::vector<ViscosityPoint>& p, double phi_m, double* alpha) {
  double ef = 0.0, ff = 0.0;
  for (const ViscosityPoint& q : p) {
    const double f = maron_pierce(q.phi, 1.0, phi_m), w = 1.0 / (q.sem * q.sem);
    ef += q.eta * f * w;
    ff += f * f * w;
  }
  const double a = ef / ff;
  double chi2 = 0.0;
  for (const ViscosityPoint& q : p) {
    const double r = (q.eta - a * maron_pierce(q.phi, 1.0, phi_m)) / q.sem;
    chi2 += r * r;
  }
  if (alpha) *alpha = a;
  return chi2;
}

Best best_fit(const std::vector<ViscosityPoint>& p) {
  double phi_max = 0.0;
  for (const ViscosityPoint& q : p) phi_max = std::max(phi_max, q.phi);
  // phi_m = phi_max + exp(t), from 1e-5 above the densest point up to phi_m = 1.
  const double t_lo = std::log(1e-5), t_hi = std::log(1.0 - phi_max);
  const int n = 400;
  auto at = [&](double t) { return profile(p, phi_max + std::exp(t), nullptr); };
  int k_best = 0;
  double c_best = at(t_lo);
  for (int k = 1; k <= n; ++k) {
    const double c = at(t_lo + (t_hi - t_lo) * k / n);
    if (c < c_best) c_best = c, k_best = k;
  }
  double a = t_lo + (t_hi - t_lo) * std::max(0, k_best - 1) / n, b = t_lo + (t_hi - t_lo) * std::min(n, k_best + 1) / n;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int it = 0; it < 100; ++it) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (at(x1) < at(x2)) b = x2;
    else a = x1;
  }
  Best r;
  r.phi_m = phi_max + std::exp(0.5 * (a + b));
  r.chi2 = profile(p, r.phi_m, &r.alpha);
  r.bracketed = k_best < n;
  return r;
}

// A standard normal variate from the project's generator (Box-Muller on 53-bit uniforms: the same on every platform).
double normal(std::mt19937_64& rng) {
  auto uniform = [&] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };
  const double u = uniform(), v = uniform();
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}
}  // namespace

std::optional<MaronPierceFit> fit_maron_pierce(const std::vector<ViscosityPoint>& points, std::string* why,
                                               int resamples, std::uint64_t seed) {
  auto fail = [&](const std::string& reason) -> std::optional<MaronPierceFit> {
    if (why) *why = reason;
    return std::nullopt;
  };
  if (points.size() < 3) return fail(std::to_string(points.size()) + " flowing point(s); a fit needs at least 3");
  // Degenerate data are reported, never fitted: a zero or infinite error would weigh a point infinitely or not at
  // all, and a viscosity <= 0 or phi outside (0, 1) is no suspension.
  for (const ViscosityPoint& q : points) {
    auto number = [](double v) {
      char b[32];
      std::snprintf(b, sizeof b, "%.6g", v);
      return std::string(b);
    };
    const std::string at = " (phi = " + number(q.phi) + ", eta_r = " + number(q.eta) + " +- " + number(q.sem) + ")";
    if (!(q.phi > 0.0) || !(q.phi < 1.0)) return fail("not fitted: a point has phi outside (0, 1)" + at);
    if (!std::isfinite(q.eta) || !(q.eta > 0.0)) return fail("not fitted: a point has no finite positive eta_r" + at);
    if (!std::isfinite(q.sem) || !(q.sem > 0.0))
      return fail("not fitted: a point has no finite positive standard error" + at);
  }
  const Best b = best_fit(points);
  MaronPierceFit f;
  f.points = static_cast<int>(points.size());
  f.phi_m = b.phi_m;
  f.alpha = b.alpha;
  f.bracketed = b.bracketed;
  f.chi2_reduced = points.size() > 2 ? b.chi2 / static_cast<double>(points.size() - 2) : 0.0;
  const double inflate = std::sqrt(std::max(1.0, f.chi2_reduced));
  std::mt19937_64 rng(seed);
  double sp = 0, spp = 0, sa = 0, saa = 0;
  std::vector<ViscosityPoint> draw = points;
  for (int r = 0; r < resamples; ++r) {
    for (std::size_t i = 0; i < points.size(); ++i)
      draw[i].eta = points[i].eta + inflate * points[i].sem * normal(rng);
    const Best d = best_fit(draw);
    sp += d.phi_m, spp += d.phi_m * d.phi_m, sa += d.alpha, saa += d.alpha * d.alpha;
  }
  const double n = std::max(1, resamples);
  f.phi_m_err = resamples > 0 ? std::sqrt(std::max(0.0, spp / n - (sp / n) * (sp / n))) : 0.0;
  f.alpha_err = resamples > 0 ? std::sqrt(std::max(0.0, saa / n - (sa / n) * (sa / n))) : 0.0;
  return f;
}

std::optional<FreeExponentFit> fit_free_exponent(const std::vector<ViscosityPoint>& points, std::string* why) {
  if (points.size() < 4) {
    if (why) *why = std::to_string(points.size()) + " flowing point(s); a free exponent needs at least 4";
    return std::nullopt;
  }
  if (!fit_maron_pierce(points, why, 0)) return std::nullopt;  // the same checks of the data
  double phi_max = 0.0;
  for (const ViscosityPoint& q : points) phi_max = std::max(phi_max, q.phi);
  // chi^2 at (t, n), phi_m = phi_max + exp(t), with the optimal alpha.
  auto chi2 = [&](double t, double n, double* alpha) {
    const double phi_m = phi_max + std::exp(t);
    double ef = 0.0, ff = 0.0;
    for (const ViscosityPoint& q : points) {
      const double f = std::pow(1.0 - q.phi / phi_m, -n), w = 1.0 / (q.sem * q.sem);
      ef += q.eta * f * w, ff += f * f * w;
    }
    const double a = ef / ff;
    double c = 0.0;
    for (const ViscosityPoint& q : points) {
      const double r = (q.eta - a * std::pow(1.0 - q.phi / phi_m, -n)) / q.sem;
      c += r * r;
    }
    if (alpha) *alpha = a;
    return c;
  };
  const double t_lo = std::log(1e-5), t_hi = std::log(1.0 - phi_max);
  double best_t = t_lo, best_n = 2.0, best = chi2(best_t, best_n, nullptr);
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 70; ++j) {
      const double t = t_lo + (t_hi - t_lo) * i / 200.0, n = 0.5 + 0.05 * j;
      if (const double c = chi2(t, n, nullptr); c < best) best = c, best_t = t, best_n = n;
    }
  // Refinement: coordinate steps that halve until they are below 1e-10.
  for (double dt = (t_hi - t_lo) / 200.0, dn = 0.05; dt > 1e-10 || dn > 1e-10; dt *= 0.5, dn *= 0.5)
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [ddt, ddn] : {std::pair{dt, 0.0}, {-dt, 0.0}, {0.0, dn}, {0.0, -dn}}) {
        const double t = std::clamp(best_t + ddt, t_lo, t_hi), n = std::clamp(best_n + ddn, 0.1, 10.0);
        if (const double c = chi2(t, n, nullptr); c < best) best = c, best_t = t, best_n = n, moved = true;
      }
    }
  FreeExponentFit f;
  f.phi_m = phi_max + std::exp(best_t);
  f.exponent = best_n;
  f.chi2_reduced = chi2(best_t, best_n, &f.alpha) / static_cast<double>(points.size() - 3);
  return f;
}

}  // namespace suspend::campaign

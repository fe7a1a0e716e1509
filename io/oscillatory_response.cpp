#include "io/oscillatory_response.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace suspend::io {

namespace {
using cplx = std::complex<double>;

// (2/T) int_{t0}^{t0+T} x(t) e^{-i n omega t} dt for n = 1, 3, 5, 7: trapezoids between samples, the ends
// interpolated linearly.
std::array<cplx, 4> harmonics_of(const std::vector<double>& t, const std::vector<double>& x, double omega, double t0,
                                 double t1) {
  std::array<cplx, 4> out{};
  constexpr int order[4] = {1, 3, 5, 7};
  auto value = [&](double at) {
    const auto it = std::upper_bound(t.begin(), t.end(), at);
    const std::size_t b = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(it - t.begin(), 1, t.size() - 1));
    const double w = (at - t[b - 1]) / (t[b] - t[b - 1]);
    return x[b - 1] + w * (x[b] - x[b - 1]);
  };
  std::vector<double> ts{t0}, xs{value(t0)};
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] > t0 && t[k] < t1) ts.push_back(t[k]), xs.push_back(x[k]);
  ts.push_back(t1);
  xs.push_back(value(t1));
  for (std::size_t k = 1; k < ts.size(); ++k) {
    const double h = ts[k] - ts[k - 1];
    for (int m = 0; m < 4; ++m) {
      const double w = order[m] * omega;
      out[m] += 0.5 * h * (xs[k - 1] * std::polar(1.0, -w * ts[k - 1]) + xs[k] * std::polar(1.0, -w * ts[k]));
    }
  }
  for (cplx& c : out) c *= 2.0 / (t1 - t0);
  return out;
}

MeanWithError mean_over(const std::vector<double>& v) {
  MeanWithError m;
  m.samples = v.size();
  if (v.empty()) return m;
  for (double x : v) m.mean += x;
  m.mean /= static_cast<double>(v.size());
  if (v.size() < 2) {
    m.sem = std::nan("");
    return m;
  }
  double var = 0.0;
  for (double x : v) var += (x - m.mean) * (x - m.mean);
  m.sem = std::sqrt(var / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()));
  return m;
}
}  // namespace

OscillatoryResponse oscillatory_response(const std::vector<double>& time, const std::vector<double>& stress,
                                         const std::vector<double>& rate, double omega, double from_time,
                                         bool response_is_rate) {
  OscillatoryResponse r;
  if (time.size() < 2 || !(omega > 0.0)) return r;
  const double period = 2.0 * std::numbers::pi / omega;
  std::vector<double> eta1, eta2, gamma0, sigma0;
  std::array<std::vector<double>, 3> ratio;
  const double first = std::ceil(std::max(from_time, time.front()) / period - 1e-9);
  // A run that ends on its accumulated strain stops within a small fraction of a period of a whole cycle.
  for (double k = first; (k + 1.0) * period <= time.back() + 1e-3 * period; k += 1.0) {
    const double t0 = k * period, t1 = t0 + period;
    const std::array<cplx, 4> s = harmonics_of(time, stress, omega, t0, t1);
    const std::array<cplx, 4> g = harmonics_of(time, rate, omega, t0, t1);
    const cplx eta = s[0] / g[0];
    eta1.push_back(eta.real());
    eta2.push_back(-eta.imag());
    gamma0.push_back(std::abs(g[0]) / omega);
    sigma0.push_back(std::abs(s[0]));
    const std::array<cplx, 4>& x = response_is_rate ? g : s;
    for (int m = 0; m < 3; ++m) ratio[m].push_back(std::abs(x[m + 1]) / std::abs(x[0]));
  }
  r.cycles = eta1.size();
  if (r.cycles == 0) {  // nothing to say: undefined, not zero
    r.eta_prime.mean = r.eta_double_prime.mean = r.strain_amplitude = r.stress_amplitude = std::nan("");
    r.harmonics.fill(std::nan(""));
    return r;
  }
  r.eta_prime = mean_over(eta1);
  r.eta_double_prime = mean_over(eta2);
  r.strain_amplitude = mean_over(gamma0).mean;
  r.stress_amplitude = mean_over(sigma0).mean;
  for (int m = 0; m < 3; ++m) r.harmonics[m] = mean_over(ratio[m]).mean;
  return r;
}

}  // namespace suspend::io

#include "analysis/gradient_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace suspend::analysis {

double sphere_slab_volume(double a, double yc, double lo, double hi) {
  // integral of the cross-section pi (a^2 - t^2), t = y - yc, over the part of [lo, hi] inside the sphere
  const double t0 = std::max(lo - yc, -a), t1 = std::min(hi - yc, a);
  if (t1 <= t0) return 0.0;
  const auto primitive = [a](double t) { return a * a * t - t * t * t / 3.0; };
  return std::numbers::pi * (primitive(t1) - primitive(t0));
}

GradientProfile gradient_profile(const Configuration& c, int bins) {
  if (bins < 1) throw std::invalid_argument("gradient_profile: bins must be at least 1");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double ly = c.box.length()[1];
  const std::size_t nb = static_cast<std::size_t>(bins);
  GradientProfile p;
  p.width = ly / bins;
  p.y.resize(nb);
  for (std::size_t k = 0; k < nb; ++k) p.y[k] = (static_cast<double>(k) + 0.5) * p.width;
  p.phi.assign(nb, 0.0);
  p.count.assign(nb, 0);
  std::vector<double> weight(nb, 0.0), weighted_y(nb, 0.0), weighted_u(nb, 0.0);
  const bool moving = c.velocity.size() == c.size();
  double w_sum = 0.0, y_sum = 0.0, u_sum = 0.0, yy_sum = 0.0, yu_sum = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double a = c.radius[i];
    double yc = std::fmod(c.position[i][1], ly);
    if (yc < 0.0) yc += ly;
    // the sphere and its images one period above and below: a sphere is smaller than the box
    for (double shift : {-ly, 0.0, ly}) {
      const double centre = yc + shift;
      if (centre + a <= 0.0 || centre - a >= ly) continue;
      const auto first = static_cast<std::size_t>(std::clamp(std::floor((centre - a) / p.width), 0.0, bins - 1.0));
      const auto last = static_cast<std::size_t>(std::clamp(std::floor((centre + a) / p.width), 0.0, bins - 1.0));
      for (std::size_t k = first; k <= last; ++k)
        p.phi[k] += sphere_slab_volume(a, centre, k * p.width, (k + 1) * p.width);
    }
    const std::size_t k = std::min(nb - 1, static_cast<std::size_t>(yc / p.width));
    ++p.count[k];
    const double w = 4.0 / 3.0 * std::numbers::pi * a * a * a;
    weight[k] += w;
    weighted_y[k] += w * yc;
    if (moving) {
      const double u = c.velocity[i][0];
      weighted_u[k] += w * u;
      w_sum += w;
      y_sum += w * yc;
      u_sum += w * u;
      yy_sum += w * yc * yc;
      yu_sum += w * yc * u;
    }
  }
  const double slab_volume = p.width * c.box.length()[0] * c.box.length()[2];
  p.mean_y.assign(nb, nan);
  p.velocity.assign(nb, nan);
  for (std::size_t k = 0; k < nb; ++k) {
    p.phi[k] /= slab_volume;
    if (weight[k] > 0.0) {
      p.mean_y[k] = weighted_y[k] / weight[k];
      if (moving) p.velocity[k] = weighted_u[k] / weight[k];
    }
  }
  p.shear_rate = nan;
  if (moving && w_sum > 0.0) {
    const double y_mean = y_sum / w_sum, u_mean = u_sum / w_sum;
    const double syy = yy_sum / w_sum - y_mean * y_mean, syu = yu_sum / w_sum - y_mean * u_mean;
    if (syy > 1e-12 * ly * ly) p.shear_rate = syu / syy;
  }
  p.local_rate.assign(nb - 1, nan);
  for (std::size_t k = 0; k + 1 < nb; ++k)
    if (std::isfinite(p.velocity[k]) && std::isfinite(p.velocity[k + 1]) && p.mean_y[k + 1] > p.mean_y[k])
      p.local_rate[k] = (p.velocity[k + 1] - p.velocity[k]) / (p.mean_y[k + 1] - p.mean_y[k]);
  return p;
}

}  // namespace suspend::analysis

// The tabulated footprints (support_plan.hpp: separable Gaussian tables, rows split at the periodic x' boundary,
// threads on balanced z slabs) reproduce the FCM force density evaluated node by node from its definition
// (Lomholt & Maxey 2003, eqs. 2.3-2.7): f_i(x) = F_i Delta_M(r) + G_ij d/dx_j Delta_D(r), r = x - Y the physical
// offset on the sheared lattice, truncated at |r| <= support, Delta(r) = (2 pi s^2)^(-3/2) exp(-r^2 / 2 s^2).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "fcm/spreading.hpp"
#include "fcm/support_plan.hpp"

using namespace suspend;
using namespace suspend::fcm;

namespace {
double gaussian(double r2, double s) {
  return std::pow(2.0 * std::numbers::pi * s * s, -1.5) * std::exp(-r2 / (2.0 * s * s));
}
}  // namespace

class SupportPlanVsDefinition : public ::testing::TestWithParam<double> {};

TEST_P(SupportPlanVsDefinition, SpreadEqualsNodeByNodeGaussians) {
  ShearedGrid g;
  g.n = {18, 16, 14};
  g.length = Vec3(9.0, 8.0, 7.0);
  g.spacing = g.length.cwiseQuotient(Vec3(18, 16, 14));
  g.shear_fraction = GetParam();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-4.0, 12.0), radius(0.7, 1.3), unit(-1.0, 1.0);
  std::vector<Envelope> env;
  std::vector<Vec3> f;
  std::vector<Mat3> dip;
  for (int p = 0; p < 7; ++p) {  // polydisperse, centres outside the primary cell included
    env.push_back(make_envelope(Vec3(pos(rng), pos(rng), pos(rng)), radius(rng), 4.5));
    f.emplace_back(unit(rng), unit(rng), unit(rng));
    Mat3 m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = unit(rng);
    dip.push_back(m);
  }
  const std::size_t stride = static_cast<std::size_t>(18 * 16 * 14);
  std::vector<double> fast(3 * stride, 0.0), slow(3 * stride, 0.0);
  spread(plan_support(g, env, grid_order(g, env)), f, dip, fast.data(), stride);

  // Definition: every unwrapped node (kx, ky, kz) sits at (kx h_x + gamma_t ky h_y, ky h_y, kz h_z).
  for (std::size_t p = 0; p < env.size(); ++p) {
    const Envelope& e = env[p];
    const int reach = 2 + static_cast<int>(e.support / g.spacing.minCoeff());
    const Vec3 c = e.centre;
    const int cy = static_cast<int>(std::floor(c.y() / g.spacing.y()));
    const int cz = static_cast<int>(std::floor(c.z() / g.spacing.z()));
    for (int kz = cz - reach; kz <= cz + reach; ++kz)
      for (int ky = cy - reach; ky <= cy + reach; ++ky) {
        const int cx = static_cast<int>(std::floor((c.x() - g.shear_fraction * ky * g.spacing.y()) / g.spacing.x()));
        for (int kx = cx - reach - 2; kx <= cx + reach + 2; ++kx) {
          const Vec3 r(kx * g.spacing.x() + g.shear_fraction * ky * g.spacing.y() - c.x(), ky * g.spacing.y() - c.y(),
                       kz * g.spacing.z() - c.z());
          const double r2 = r.squaredNorm();
          if (r2 > e.support * e.support) continue;
          // d/dx_j Delta_D = -r_j / s_D^2 Delta_D
          const Vec3 v = f[p] * gaussian(r2, e.sigma_m) -
                         dip[p] * r * (gaussian(r2, e.sigma_d) / (e.sigma_d * e.sigma_d));
          const std::size_t i = g.index(periodic_index(kx, g.n[0]), periodic_index(ky, g.n[1]),
                                        periodic_index(kz, g.n[2]));
          for (int k = 0; k < 3; ++k) slow[i + k * stride] += v[k];
        }
      }
  }
  double scale = 0.0, err = 0.0;
  for (std::size_t i = 0; i < slow.size(); ++i) {
    scale = std::max(scale, std::abs(slow[i]));
    err = std::max(err, std::abs(fast[i] - slow[i]));
  }
  EXPECT_GT(scale, 0.1);
  EXPECT_LT(err, 1e-12 * scale);
}

INSTANTIATE_TEST_SUITE_P(ShearFractions, SupportPlanVsDefinition, ::testing::Values(0.0, 0.37, -0.5));

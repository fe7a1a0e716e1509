// Dilute random suspension of rigid FCM spheres in simple shear: the bulk stress 2 eta E_inf + (1/V) sum S gives
// the effective viscosity eta_eff = Sigma_xy / gammadot = 1 + 2.5 phi + c phi^2 (Einstein 1906; Batchelor & Green
// 1972 give c = 5.0 for pure straining of hard spheres with full hydrodynamics). We fit (eta_eff - 1)/phi =
// A + c phi over phi = 0.01-0.05, several seeded configurations each, and require A within 2% of 2.5.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "core/box.hpp"
#include "fcm/solver.hpp"

using namespace suspend;
using namespace suspend::fcm;

namespace {
std::vector<Vec3> random_spheres(int n, double l, double min_distance, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, l);
  const Box box(l, l, l);
  std::vector<Vec3> p;
  while (static_cast<int>(p.size()) < n) {
    const Vec3 c(u(rng), u(rng), u(rng));
    bool ok = true;
    for (const Vec3& q : p) ok = ok && box.minimum_image(c, q).d.norm() >= min_distance;
    if (ok) p.push_back(c);
  }
  return p;
}
}  // namespace

TEST(FcmSuspensionViscosity, EinsteinCoefficientOfADiluteRandomSuspension) {
  const double l = 16.0, vol = l * l * l, vp = 4.0 / 3.0 * std::numbers::pi;
  SolverOptions o;
  o.planning = FftPlanning::estimate;
  o.rigidity_tolerance = 1e-8;
  Solver s(Vec3::Constant(l), {32, 32, 32}, o);
  std::mt19937_64 rng(2024);
  std::vector<double> phis, ratios;
  for (int n : {10, 20, 29, 39, 49}) {
    const double phi = n * vp / vol;
    double eta = 0.0;
    const int configs = 6;
    int iterations = 0;
    for (int c = 0; c < configs; ++c) {
      const std::vector<Vec3> pos = random_spheres(n, l, 2.0, rng);
      const std::vector<double> rad(n, 1.0);
      MobilityProblem pb{.positions = pos, .radii = rad, .flow = AmbientFlow::simple_shear(1.0)};
      const std::vector<Mat3> zero(n, Mat3::Zero());
      pb.stresslet_guess = zero;
      const MobilityResult r = s.solve(pb);
      iterations += r.iterations;
      eta += s.bulk_stress(r, AmbientFlow::simple_shear(1.0))(0, 1) / configs;
    }
    std::cout << "phi = " << phi << ": eta_eff = " << eta << ", (eta_eff - 1)/(2.5 phi) = " << (eta - 1.0) / (2.5 * phi)
              << ", mean CG iterations " << iterations / double(configs) << "\n";
    phis.push_back(phi);
    ratios.push_back((eta - 1.0) / phi);
  }
  // Least-squares line (eta - 1)/phi = A + c phi.
  const double m = static_cast<double>(phis.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < phis.size(); ++i) {
    sx += phis[i];
    sy += ratios[i];
    sxx += phis[i] * phis[i];
    sxy += phis[i] * ratios[i];
  }
  const double c = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  const double a = (sy - c * sx) / m;
  std::cout << "fit: (eta_eff - 1)/phi = " << a << " + " << c << " phi\n";
  EXPECT_NEAR(a / 2.5, 1.0, 0.02);
  EXPECT_GT(c, 0.0);  // hydrodynamic interactions raise the viscosity at O(phi^2)
}

// Accuracy of the FCM solver against exact values, for the truncation and spectral-splitting table of docs/fcm.md.
//  1. One sphere (a = 1) in a periodic cube L = 16 a at h = a/2 (32^3) and h = a/4 (64^3), six positions (on a
//     node, half-way between nodes, four off-grid), maximum relative error over the positions of
//       drag 6 pi a U / F   against the exact periodic-Gaussian value 1 - 2.837297 a/L + 4 (a/L)^3,
//       Omega 8 pi a^3 / T  against 1 (Stokes, no periodic correction: the floor is phi = 1.0e-3),
//       S_xy / ((20/3) pi a^3 E_xy) against 1 (rigid sphere in shear; floor ~0.83 phi),
//     rigid mobility solves to 1e-10.
//  2. A random suspension (phi = 0.4, L = 16 a, 391 spheres, F, T, S all nonzero, sheared lattice D = 1.3):
//     one Stokes solve at h = a/2 against the same solve at h = a/4 with 5 widths and no splitting (the grid-
//     converged FCM operator): relative RMS error of U, Omega and E over the particles.
// Usage: fcm_accuracy [split_dipole_width = 0 (no splitting)] [truncation widths ... = 3.5 4 4.5 5]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <vector>

#include "fcm/solver.hpp"

using namespace suspend;
using namespace suspend::fcm;

namespace {
constexpr double pi = std::numbers::pi;

SolverOptions options(double split, double widths) {
  SolverOptions o;
  o.planning = FftPlanning::estimate;
  o.rigidity_tolerance = 1e-10;
  o.split_dipole_width = split;
  o.truncation_widths = widths;
  return o;
}

struct Errors {
  double u = 0.0, omega = 0.0, s = 0.0;
};

Errors isolated_sphere(int n, double split, double widths, double& c) {
  const double l = 16.0;
  Solver solver(Vec3::Constant(l), {n, n, n}, options(split, widths));
  const std::vector<double> r{1.0};
  const double drag_exact = 1.0 - 2.837297 / l + 4.0 / (l * l * l);
  Errors e;
  for (const Vec3& pos : {Vec3(8.0, 8.0, 8.0), Vec3(8.25, 8.25, 8.25), Vec3(8.125, 8.375, 8.0625),
                          Vec3(3.1, 7.37, 11.62), Vec3(4.96, 8.32, 12.32), Vec3(5.2, 9.1, 3.3)}) {
    const std::vector<Vec3> p{pos}, f{Vec3(1.0, 0.0, 0.0)}, t{Vec3(0.2, -0.5, 1.0)};
    const MobilityResult rf = solver.solve({.positions = p, .radii = r, .forces = f});
    e.u = std::max(e.u, std::abs(6.0 * pi * rf.velocities[0].x() / drag_exact - 1.0));
    const MobilityResult rt = solver.solve({.positions = p, .radii = r, .torques = t});
    const Vec3 expect = t[0] / (8.0 * pi);
    e.omega = std::max(e.omega, (rt.angular_velocities[0] - expect).norm() / expect.norm());
    const MobilityResult rs = solver.solve({.positions = p, .radii = r, .flow = AmbientFlow::simple_shear(1.0)});
    e.s = std::max(e.s, std::abs(rs.stresslets[0](0, 1) / (20.0 / 3.0 * pi * 0.5) - 1.0));
    c = solver.split_width();
  }
  return e;
}

struct Suspension {
  std::vector<Vec3> pos, force, torque;
  std::vector<double> rad;
  std::vector<Mat3> stresslet;
};

Suspension random_suspension(double l, double phi) {
  const int n = static_cast<int>(phi * l * l * l / (4.0 / 3.0 * pi));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, l), g(-1.0, 1.0);
  Suspension s;
  for (int i = 0; i < n; ++i) {
    s.pos.emplace_back(u(rng), u(rng), u(rng));
    s.rad.push_back(1.0);
    s.force.emplace_back(g(rng), g(rng), g(rng));
    s.torque.emplace_back(g(rng), g(rng), g(rng));
    Mat3 m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = g(rng);
    Mat3 sym = m + m.transpose();
    sym.diagonal().array() -= sym.trace() / 3.0;
    s.stresslet.push_back(sym);
  }
  return s;
}

Disturbance suspension_solve(const Suspension& s, int n, double split, double widths) {
  Solver solver(Vec3::Constant(16.0), {n, n, n}, options(split, widths));
  return solver.apply(s.pos, s.rad, s.force, s.torque, s.stresslet, 1.3);
}

template <class T>
double rms_error(const std::vector<T>& x, const std::vector<T>& ref) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    num += (x[i] - ref[i]).squaredNorm();
    den += ref[i].squaredNorm();
  }
  return std::sqrt(num / den);
}
}  // namespace

int main(int argc, char** argv) {
  const double split = argc > 1 ? std::atof(argv[1]) : 0.0;
  std::vector<double> widths;
  for (int i = 2; i < argc; ++i) widths.push_back(std::atof(argv[i]));
  if (widths.empty()) widths = {3.5, 4.0, 4.5, 5.0};
  std::printf("split_dipole_width %g\n", split);
  std::printf("isolated sphere, L = 16 a, max relative error over 6 positions\n");
  std::printf("| widths | h = a/2: U | Omega | S | h = a/4: U | Omega | S |\n");
  for (double w : widths) {
    double c2 = 0.0, c4 = 0.0;
    const Errors e2 = isolated_sphere(32, split, w, c2), e4 = isolated_sphere(64, split, w, c4);
    std::printf("| %g | %.1e | %.1e | %.1e | %.1e | %.1e | %.1e |   (c = %.4f a at h = a/2, %.4f a at a/4)\n", w,
                e2.u, e2.omega, e2.s, e4.u, e4.omega, e4.s, c2, c4);
  }
  const Suspension s = random_suspension(16.0, 0.4);
  const Disturbance ref = suspension_solve(s, 64, 0.0, 5.0);
  std::printf("suspension phi = 0.4, %zu spheres, L = 16 a, sheared: h = a/2 vs h = a/4 (5 widths, unsplit)\n",
              s.pos.size());
  std::printf("| widths | U | Omega | E |\n");
  for (double w : widths) {
    const Disturbance d = suspension_solve(s, 32, split, w);
    std::printf("| %g | %.1e | %.1e | %.1e |\n", w, rms_error(d.velocities, ref.velocities),
                rms_error(d.angular_velocities, ref.angular_velocities), rms_error(d.strain_rates, ref.strain_rates));
  }
  return 0;
}

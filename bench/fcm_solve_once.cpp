// One FCM Stokes solve at phi = 0.4 on a 64^3 grid (3129 spheres, h = a/2, same suspension as bench_fcm), for
// deterministic instruction counts of its stages:
//   OMP_NUM_THREADS=1 valgrind --tool=callgrind --collect-atstart=no
//     --toggle-collect='suspend::fcm::Solver::apply*' build/bin/fcm_solve_once   (one command line)
//   callgrind_annotate --inclusive=yes callgrind.out.<pid> | grep -E 'spread|interpolate|fftw_execute|green'
// Args: [grid nodes per direction = 64] [volume fraction = 0.4] [solves = 1] [mode]. FFTW plans with FFTW_ESTIMATE
// (an FFTW_MEASURE plan takes minutes under valgrind).
// mode "mobility": rigidity CG iteration counts instead, per preconditioner, sheared at gammadot = 1: from a zero
// stresslet guess, then `solves` time steps that displace every particle by 1e-3 a in a random direction and
// re-solve from the previous stresslets (what a time-stepper sees; the near-field factor is reused while the
// particles stay within SolverOptions::near_field_reuse_displacement); a 6th argument sets the near-field cutoff,
// a 7th the reuse displacement.
// mode "mobility_near_field": the same for the near-field preconditioner only.
// mode "stokes" with a 6th argument: the Stokes solves with that truncation (in monopole widths); a 7th sets
// SolverOptions::split_dipole_width (spectral splitting), an 8th the grid spacing in radii (default 0.5: the box is
// then 64 h at 64^3 and holds proportionally fewer spheres at the same phi).
// Example, h = a/4 with and without splitting: fcm_solve_once 64 0.4 3 stokes 4.5 0 0.25 / ... stokes 5 1.0 0.25
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

#include "fcm/solver.hpp"

using namespace suspend;
using namespace suspend::fcm;

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 64;
  const double phi = argc > 2 ? std::atof(argv[2]) : 0.4;
  const int solves = argc > 3 ? std::atoi(argv[3]) : 1;
  const bool stokes_mode = argc > 5 && std::strcmp(argv[4], "stokes") == 0;
  const double h = stokes_mode && argc > 7 ? std::atof(argv[7]) : 0.5;
  const double l = h * n;
  const int np = static_cast<int>(phi * l * l * l / (4.0 / 3.0 * std::numbers::pi));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, l), g(-1.0, 1.0);
  std::vector<Vec3> pos, force, torque;
  std::vector<double> rad;
  std::vector<Mat3> stresslet;
  for (int i = 0; i < np; ++i) {
    pos.emplace_back(u(rng), u(rng), u(rng));
    rad.push_back(1.0);
    force.emplace_back(g(rng), g(rng), g(rng));
    torque.emplace_back(g(rng), g(rng), g(rng));
    Mat3 m;
    for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = g(rng);
    stresslet.push_back(m + m.transpose());
  }
  SolverOptions opt;
  opt.planning = FftPlanning::estimate;
  if (stokes_mode) opt.truncation_widths = std::atof(argv[5]);
  if (stokes_mode && argc > 6) opt.split_dipole_width = std::atof(argv[6]);
  const bool near_only = argc > 4 && std::strcmp(argv[4], "mobility_near_field") == 0;
  if (argc > 4 && (std::strcmp(argv[4], "mobility") == 0 || near_only)) {
    if (argc > 5) opt.near_field_cutoff = std::atof(argv[5]);
    if (argc > 6) opt.near_field_reuse_displacement = std::atof(argv[6]);
    for (const auto pc : {RigidityPreconditioner::jacobi, RigidityPreconditioner::near_field}) {
      if (near_only && pc == RigidityPreconditioner::jacobi) continue;
      opt.preconditioner = pc;
      Solver solver(Vec3::Constant(l), {n, n, n}, opt);
      std::vector<Vec3> p = pos;
      const std::vector<Mat3> zero(p.size(), Mat3::Zero());
      std::mt19937_64 step_rng(11);
      std::normal_distribution<double> normal;
      MobilityProblem pb{p, rad, force, torque, AmbientFlow::simple_shear(1.0), 1.3, zero};
      const double t0 = omp_get_wtime();
      MobilityResult r = solver.solve(pb);
      const double t1 = omp_get_wtime();
      std::printf("%s: zero guess %d iterations, %.3f s (preconditioner %.3f s)\n",
                  pc == RigidityPreconditioner::jacobi ? "jacobi" : "near_field", r.iterations, t1 - t0,
                  solver.timings().precondition);
      pb.stresslet_guess = {};  // warm start from the previous solution
      int total = 0;
      solver.reset_timings();
      const double t2 = omp_get_wtime();
      for (int step = 0; step < solves; ++step) {
        for (Vec3& x : p) {
          const Vec3 dir(normal(step_rng), normal(step_rng), normal(step_rng));
          x += 1e-3 * dir.normalized();
        }
        r = solver.solve(pb);
        total += r.iterations;
        std::printf("  warm step %d: %d iterations\n", step + 1, r.iterations);
      }
      if (solves > 0)
        std::printf("  warm start mean %.2f iterations, %.3f s per solve (preconditioner %.3f s)\n",
                    static_cast<double>(total) / solves, (omp_get_wtime() - t2) / solves,
                    solver.timings().precondition / solves);
    }
    return 0;
  }
  Solver solver(Vec3::Constant(l), {n, n, n}, opt);
  double check = 0.0;
  for (int s = 0; s < solves; ++s) {
    const Disturbance d = solver.apply(pos, rad, force, torque, stresslet, 1.3);
    check += d.velocities[0].x();
  }
  std::printf("particles %d, u_0x %.12g\n", np, check / solves);
  return 0;
}

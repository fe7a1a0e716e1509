// One coupled FCM step (fcm_simulation: contacts + sub-grid lubrication + FCM/GMRES velocity solve) at phi = 0.45,
// 440 monodisperse spheres (a = 1) in a (16 a)^3 box, h = a/2 (32^3 grid), truncation 4 widths, soft-repulsion
// contacts, simple shear, adaptive time step, warm-started GMRES. After `warmup` steps, `steps` steps are timed
// and split into contacts, sub-grid work (assembly + applications), the near-field preconditioner (sparse
// Cholesky), the FCM Stokes solves and the rest; every time is reported as a ratio to one bare FFT Stokes solve
// (3 forward + 3 inverse r2c transforms of the same grid, FFTW measure plans), measured in the same run.
// Usage: bench_coupling [steps=10] [warmup=5] [cache_dir=coupling_cache] [krylov_tolerance=1e-4]
//                       [near_field=cg|cholesky] [preconditioner_cutoff=2.2] [inner_max_iterations=5]
//                       [inner_tolerance=1e-2] [min_gap=0.01 (of the initial packing, a)]
//                       [truncation_widths=4 (fcm.truncation_widths)]
// Deterministic instruction counts of the timed steps only (the bare FFTs and the warm-up are not collected):
//   OMP_NUM_THREADS=1 valgrind --tool=callgrind --collect-atstart=no build/bin/bench_coupling 4 5 coupling_cache
//   callgrind_annotate --inclusive=yes callgrind.out.<pid>
#include <omp.h>
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define SUSPEND_CALLGRIND_TOGGLE() CALLGRIND_TOGGLE_COLLECT
#else
#define SUSPEND_CALLGRIND_TOGGLE() ((void)0)
#endif

#include <cstdio>
#include <cstdlib>
#include <string>

#include "coupling/fcm_model.hpp"
#include "dem/packing.hpp"
#include "fcm/fft.hpp"

using namespace suspend;

int main(int argc, char** argv) {
  const int steps = argc > 1 ? std::atoi(argv[1]) : 10;
  const int warmup = argc > 2 ? std::atoi(argv[2]) : 5;
  const std::string cache = argc > 3 ? argv[3] : "coupling_cache";
  const double tolerance = argc > 4 ? std::atof(argv[4]) : 1e-4;

  const std::vector<double> radius(440, 1.0);
  const Box box(16, 16, 16);
  PackingParams pp;
  pp.seed = 3;
  pp.min_gap = argc > 9 ? std::atof(argv[9]) : 0.01;
  const Packing packing = random_packing(radius, box, pp);
  SimulationState state;
  state.particles.resize(radius.size());
  state.particles.position = packing.position;
  state.particles.radius = radius;
  SimulationParams params;
  FcmParams fcm;
  fcm.cache_dir = cache;
  fcm.krylov_tolerance = tolerance;
  if (argc > 10) fcm.truncation_widths = std::atof(argv[10]);
  const bool cholesky = argc > 5 && std::string(argv[5]) == "cholesky";
  if (argc > 6) fcm.preconditioner_cutoff = std::atof(argv[6]);
  double t0 = omp_get_wtime();
  Simulation sim = fcm_simulation(state, box, params, fcm);
  {
    coupling::KrylovParams k = fcm_model(sim).mobility().params();
    if (cholesky) k.near_field = coupling::KrylovParams::NearField::cholesky;
    if (argc > 7) k.inner_max_iterations = std::atoi(argv[7]);
    if (argc > 8) k.inner_tolerance = std::atof(argv[8]);
    fcm_model(sim).mobility().set_params(k);
  }
  std::printf("setup (pair table from cache or computed): %.2f s; phi = %.4f, N = %zu, threads = %d\n",
              omp_get_wtime() - t0, packing.report.phi, radius.size(), omp_get_max_threads());
  for (int s = 0; s < warmup; ++s) {
    sim.evaluate();
    sim.advance();
  }
  const double contacts0 = sim.contact_seconds(), assembly0 = fcm_model(sim).subgrid_assembly_seconds();
  const long inner0 = fcm_model(sim).mobility().inner_iterations();
  fcm_model(sim).mobility().reset_timings();
  fcm_model(sim).mobility().solver().reset_timings();
  long iterations = 0, solves = 0;
  std::size_t pairs = 0, contacts = 0;
  // Bare FFT Stokes solve: 3 forward + 3 inverse r2c transforms of the same grid, timed between the steps so that
  // both see the same machine load (the 2-core machine is shared).
  fcm::VectorFft fft({32, 32, 32}, 0, fcm::FftPlanning::measure);
  const int reps = 10;
  double bare_total = 0.0, total_time = 0.0;
  for (int s = 0; s < steps; ++s) {
    t0 = omp_get_wtime();
    for (int r = 0; r < reps; ++r) {
      fft.forward(fcm::FftScaling::none);
      fft.inverse(fcm::FftScaling::none);
    }
    bare_total += omp_get_wtime() - t0;
    t0 = omp_get_wtime();
    SUSPEND_CALLGRIND_TOGGLE();
    sim.evaluate();
    sim.advance();
    SUSPEND_CALLGRIND_TOGGLE();
    total_time += omp_get_wtime() - t0;
    iterations += sim.solver_iterations();
    solves += fcm_model(sim).stokes_solves();
    pairs += fcm_model(sim).corrected_pairs();
    contacts += sim.contact_count();
  }
  const double total = total_time / steps;
  const double bare = bare_total / (reps * steps);
  const auto& tm = fcm_model(sim).mobility().timings();
  const auto& ft = fcm_model(sim).mobility().solver().timings();
  const double contact = (sim.contact_seconds() - contacts0) / steps;
  const double subgrid = (tm.subgrid + fcm_model(sim).subgrid_assembly_seconds() - assembly0) / steps;
  const double precond = tm.preconditioner / steps;
  const double stokes = tm.stokes / steps;

  std::printf("per step (average of %d steps after %d warm-up steps, strain %.4f):\n", steps, warmup,
              sim.state().strain);
  std::printf("  GMRES iterations %.1f, Stokes solves %.1f, corrected pairs %.0f, contacts %.1f\n",
              double(iterations) / steps, double(solves) / steps, double(pairs) / steps, double(contacts) / steps);
  std::printf("  footprint plans %.1f\n", double(ft.plans) / steps);
  std::printf("  near field: %s, inner CG iterations %.1f per step, Cholesky analyses %d, failures %d\n",
              cholesky ? "cholesky" : "block-SGS CG", double(fcm_model(sim).mobility().inner_iterations() - inner0) / steps,
              fcm_model(sim).mobility().preconditioner_analyses(), fcm_model(sim).mobility().preconditioner_failures());
  std::printf("  bare FFT Stokes solve (32^3): %.3f ms\n", 1e3 * bare);
  std::printf("  %-28s %9s %9s\n", "stage", "ms", "/ bare FFT");
  auto row = [&](const char* name, double t) { std::printf("  %-28s %9.2f %9.1f\n", name, 1e3 * t, t / bare); };
  row("total step", total);
  row("contacts", contact);
  row("sub-grid (assembly+apply)", subgrid);
  row("  of which assembly", (fcm_model(sim).subgrid_assembly_seconds() - assembly0) / steps);
  row("near-field preconditioner", precond);
  row("FCM Stokes solves", stokes);
  row("  of which plan (footprints)", ft.plan / steps);
  row("  of which spread", ft.spread / steps);
  row("  of which FFTs", ft.fft / steps);
  row("  of which interpolate", ft.interpolate / steps);
  row("one Stokes solve", stokes / std::max(1.0, double(solves) / steps));
  row("other (GMRES, lists, ...)", total - contact - subgrid - precond - stokes);
  return 0;
}

// One FCM Stokes solve (spread F, T, S -> FFT -> Green's function -> inverse FFT -> interpolate U, Omega, E),
// split into its stages, against the bare FFTs it needs (3 forward + 3 inverse real transforms); and a full
// rigid mobility solve (rigidity CG), whose Stokes solves share one footprint plan.
// Args: grid nodes per direction, volume fraction in percent, OpenMP threads. h = a/2, monodisperse a = 1.
// Deterministic instruction counts of the same split: bench/fcm_solve_once.cpp under callgrind.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "fcm/solver.hpp"

using namespace suspend;
using namespace suspend::fcm;

namespace {
struct Suspension {
  std::vector<Vec3> pos, force, torque;
  std::vector<double> rad;
  std::vector<Mat3> stresslet;
};
Suspension random_suspension(double l, double phi) {
  const int n = static_cast<int>(phi * l * l * l / (4.0 / 3.0 * std::numbers::pi));
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
    s.stresslet.push_back(m + m.transpose());
  }
  return s;
}
}  // namespace

// Per-stage counters (ms per Stokes solve) and the acceptance ratio: spread + FFT + Green + interpolate over the
// bare FFTs timed inside the same solves (same process, same machine load), target <= 2. The footprint tables
// (plan_ms, per plan) are built once per configuration (the solver keeps them while the configuration is the
// same, so BM_FcmStokesSolve pays them once); apply_over_fft charges one plan to one solve, as for a new
// configuration.
void report_stages(benchmark::State& state, const Solver& solver, std::size_t particles) {
  const SolveTimings& t = solver.timings();
  const double k = 1e3 / t.solves;
  const double stokes = t.spread + t.fft + t.green + t.interpolate;
  state.counters["particles"] = static_cast<double>(particles);
  state.counters["plan_ms"] = 1e3 * t.plan / std::max(1, t.plans);
  state.counters["spread_ms"] = t.spread * k;
  state.counters["fft_ms"] = t.fft * k;
  state.counters["green_ms"] = t.green * k;
  state.counters["interp_ms"] = t.interpolate * k;
  state.counters["solve_over_fft"] = stokes / t.fft;
  state.counters["apply_over_fft"] = (stokes + t.plan / std::max(1, t.plans) * t.solves) / t.fft;
}

// Args: grid, phi in percent, threads, row kernels (1: 8-lane AVX-512 where the CPU has them, 0: 4-lane).
static void BM_FcmStokesSolve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double phi = 0.01 * static_cast<double>(state.range(1));
  omp_set_num_threads(static_cast<int>(state.range(2)));
  use_wide_kernels(state.range(3) != 0);
  const double l = 0.5 * n;
  const Suspension s = random_suspension(l, phi);
  Solver solver(Vec3::Constant(l), {n, n, n});
  for (auto _ : state) {
    Disturbance d = solver.apply(s.pos, s.rad, s.force, s.torque, s.stresslet, 1.3);
    benchmark::DoNotOptimize(d.velocities.data());
  }
  report_stages(state, solver, s.pos.size());
  state.counters["wide_kernels"] = state.range(3) != 0 && wide_kernels_available();
  use_wide_kernels(true);
}
BENCHMARK(BM_FcmStokesSolve)
    ->ArgsProduct({{64}, {10, 40}, {1, 2}, {1}})
    ->ArgsProduct({{64}, {40}, {1, 2}, {0}})
    ->ArgsProduct({{128}, {40}, {1, 2}, {1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A full rigid mobility solve (the rigidity CG from a zero stresslet guess, sheared at gammadot = 1): one plan,
// then one Stokes solve per CG iteration plus the initial one; the counters are per Stokes solve, except
// precond_ms (building and applying the near-field preconditioner, per mobility solve).
// Args: grid, phi in percent, threads, preconditioner (0 Jacobi, 1 near field).
static void BM_FcmMobilitySolve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double phi = 0.01 * static_cast<double>(state.range(1));
  omp_set_num_threads(static_cast<int>(state.range(2)));
  const double l = 0.5 * n;
  const Suspension s = random_suspension(l, phi);
  const std::vector<Mat3> zero(s.pos.size(), Mat3::Zero());
  SolverOptions options;
  options.preconditioner = state.range(3) == 0 ? RigidityPreconditioner::jacobi : RigidityPreconditioner::near_field;
  options.near_field_reuse_displacement = 0.0;  // every repetition pays the factorisation, as a new configuration
  Solver solver(Vec3::Constant(l), {n, n, n}, options);
  MobilityProblem pb{s.pos, s.rad, s.force, s.torque, AmbientFlow::simple_shear(1.0), 1.3, zero};
  int iterations = 0, solves = 0;
  for (auto _ : state) {
    MobilityResult r = solver.solve(pb);
    iterations = r.iterations;
    ++solves;
    benchmark::DoNotOptimize(r.velocities.data());
  }
  report_stages(state, solver, s.pos.size());
  state.counters["cg_iterations"] = iterations;
  const SolveTimings& t = solver.timings();
  state.counters["precond_ms"] = 1e3 * t.precondition / solves;
  // One plan per mobility solve, as for a new configuration (the solver itself plans the repeated one only once).
  const double plan = t.plan / std::max(1, t.plans) * solves;
  state.counters["mobility_over_fft"] = (plan + t.spread + t.fft + t.green + t.interpolate + t.precondition) / t.fft;
}
BENCHMARK(BM_FcmMobilitySolve)
    ->ArgsProduct({{64}, {40}, {1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The acceptance ratios in one interleaved loop, so that a machine whose speed drifts between benchmarks (shared
// hosts: the bare FFTs alone varied 3.4-5.9 ms between runs) cannot bias them: every iteration times one Stokes solve
// (spread, FFTs, Green's function, interpolation; the plan is kept, as in the rigidity CG and a coupled step) and one
// pass of the bare FFTs (3 forward + 3 inverse, FFTW measure plans of their own), each with 1 and with 2 threads
// (separate solvers and plans per thread count). Counters: solve_over_bare_t1 / _t2 = summed solve time / summed
// bare FFT time at 1 / 2 threads (target <= 2), solve_speedup_2t = 1-thread / 2-thread solve time (target >= 1.6),
// bare_speedup_2t the same for the bare FFTs. Args: grid, phi in percent, truncation in tenths of a width (0: the
// default of SolverOptions).
static void BM_FcmAcceptanceRatios(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double phi = 0.01 * static_cast<double>(state.range(1));
  const double l = 0.5 * n;
  const Suspension s = random_suspension(l, phi);
  SolverOptions options;
  if (state.range(2) > 0) options.truncation_widths = 0.1 * static_cast<double>(state.range(2));
  std::unique_ptr<Solver> solver[2];
  std::unique_ptr<VectorFft> bare[2];
  for (int t = 0; t < 2; ++t) {
    omp_set_num_threads(t + 1);
    solver[t] = std::make_unique<Solver>(Vec3::Constant(l), std::array<int, 3>{n, n, n}, options);
    bare[t] = std::make_unique<VectorFft>(std::array<int, 3>{n, n, n}, t + 1, FftPlanning::measure);
    omp_set_num_threads(t + 1);
    solver[t]->apply(s.pos, s.rad, s.force, s.torque, s.stresslet, 1.3);  // plan the footprints once
  }
  double solve_time[2] = {0.0, 0.0}, bare_time[2] = {0.0, 0.0};
  for (auto _ : state) {
    for (int t = 0; t < 2; ++t) {
      omp_set_num_threads(t + 1);
      double t0 = omp_get_wtime();
      Disturbance d = solver[t]->apply(s.pos, s.rad, s.force, s.torque, s.stresslet, 1.3);
      solve_time[t] += omp_get_wtime() - t0;
      benchmark::DoNotOptimize(d.velocities.data());
      t0 = omp_get_wtime();
      bare[t]->forward(FftScaling::none);
      bare[t]->inverse(FftScaling::none);
      bare_time[t] += omp_get_wtime() - t0;
    }
  }
  omp_set_num_threads(omp_get_num_procs());
  const double k = 1e3 / static_cast<double>(state.iterations());
  state.counters["particles"] = static_cast<double>(s.pos.size());
  state.counters["solve_ms_t1"] = solve_time[0] * k;
  state.counters["solve_ms_t2"] = solve_time[1] * k;
  state.counters["bare_ms_t1"] = bare_time[0] * k;
  state.counters["bare_ms_t2"] = bare_time[1] * k;
  state.counters["solve_over_bare_t1"] = solve_time[0] / bare_time[0];
  state.counters["solve_over_bare_t2"] = solve_time[1] / bare_time[1];
  state.counters["solve_speedup_2t"] = solve_time[0] / solve_time[1];
  state.counters["bare_speedup_2t"] = bare_time[0] / bare_time[1];
  const SolveTimings& a = solver[0]->timings();
  const SolveTimings& b = solver[1]->timings();
  state.counters["spread_speedup_2t"] = (a.spread / a.solves) / (b.spread / b.solves);
  state.counters["fft_speedup_2t"] = (a.fft / a.solves) / (b.fft / b.solves);
  state.counters["interp_speedup_2t"] = (a.interpolate / a.solves) / (b.interpolate / b.solves);
}
BENCHMARK(BM_FcmAcceptanceRatios)
    ->Args({64, 40, 0})
    ->Args({64, 10, 0})
    ->Args({64, 40, 45})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

static void BM_BareFfts(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  omp_set_num_threads(static_cast<int>(state.range(1)));
  VectorFft fft({n, n, n}, 0, FftPlanning::measure);
  for (auto _ : state) {
    fft.forward(FftScaling::none);
    fft.inverse(FftScaling::none);
  }
}
BENCHMARK(BM_BareFfts)->ArgsProduct({{64, 128}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();

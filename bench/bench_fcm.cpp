// One FCM Stokes solve (spread F, T, S -> FFT -> Green's function -> inverse FFT -> interpolate U, Omega, E),
// split into its stages, against the bare FFTs it needs (3 forward + 3 inverse real transforms).
// Args: grid nodes per direction, volume fraction in percent, OpenMP threads. h = a/2, monodisperse a = 1.
#include <benchmark/benchmark.h>
#include <omp.h>

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

static void BM_FcmStokesSolve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double phi = 0.01 * static_cast<double>(state.range(1));
  omp_set_num_threads(static_cast<int>(state.range(2)));
  const double l = 0.5 * n;
  const Suspension s = random_suspension(l, phi);
  Solver solver(Vec3::Constant(l), {n, n, n});
  for (auto _ : state) {
    Disturbance d = solver.apply(s.pos, s.rad, s.force, s.torque, s.stresslet, 1.3);
    benchmark::DoNotOptimize(d.velocities.data());
  }
  const SolveTimings& t = solver.timings();
  const double k = 1e3 / t.solves;
  state.counters["particles"] = static_cast<double>(s.pos.size());
  state.counters["spread_ms"] = t.spread * k;
  state.counters["fft_ms"] = t.fft * k;
  state.counters["green_ms"] = t.green * k;
  state.counters["interp_ms"] = t.interpolate * k;
  // The acceptance target: whole solve / the bare FFTs inside it (same run, same machine load), at most 2.
  state.counters["solve_over_fft"] = (t.spread + t.fft + t.green + t.interpolate) / t.fft;
}
BENCHMARK(BM_FcmStokesSolve)
    ->ArgsProduct({{64}, {10, 40}, {1, 2}})
    ->Args({128, 40, 2})
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
BENCHMARK(BM_BareFfts)->ArgsProduct({{64}, {1, 2}})->Args({128, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();

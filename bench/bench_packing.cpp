// Random packings: N = 1000 equal-volume bidisperse spheres (size ratio 1.4) at increasing volume fraction, and the
// large-scale case N = 65536, size ratio 3, large-sphere volume share 0.2, phi = 0.5 (one iteration; minutes).
// Usage: build/bin/bench_packing --benchmark_filter='BM_RandomPacking/'   (the N = 1000 cases at 0.55, 0.60, 0.62)
//        build/bin/bench_packing --benchmark_filter=Dense|Large
#include <benchmark/benchmark.h>

#include "dem/packing.hpp"

namespace {
void pack(benchmark::State& state, std::size_t n, double ratio, double large_share, double phi) {
  const std::vector<suspend::Species> species{{1.0, 1.0 - large_share}, {ratio, large_share}};
  const auto radius = suspend::species_radii(species, suspend::species_counts(species, n));
  const suspend::Box box = suspend::cube_for_volume_fraction(radius, phi);
  suspend::PackingParams params;
  suspend::PackingReport report;
  for (auto _ : state) {
    const suspend::Packing p = suspend::random_packing(radius, box, params);
    benchmark::DoNotOptimize(p.position.data());
    report = p.report;
  }
  state.counters["phi"] = report.phi;
  state.counters["fire_steps"] = static_cast<double>(report.iterations);
  state.counters["retries"] = report.retries;
  state.counters["rebuilds"] = report.neighbour_rebuilds;
}

void BM_RandomPacking(benchmark::State& state) { pack(state, 1000, 1.4, 0.5, state.range(0) / 100.0); }
void BM_RandomPackingDense(benchmark::State& state) { pack(state, 1000, 1.4, 0.5, 0.64); }
void BM_RandomPackingLarge(benchmark::State& state) { pack(state, 65536, 3.0, 0.2, 0.5); }
}  // namespace

BENCHMARK(BM_RandomPacking)->Arg(55)->Arg(60)->Arg(62)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RandomPackingDense)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RandomPackingLarge)->Iterations(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

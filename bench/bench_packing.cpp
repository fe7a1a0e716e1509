// Random packing of N = 1000 equal-volume bidisperse spheres (size ratio 1.4) at increasing volume fraction.
// Usage: build/bin/bench_packing [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include "dem/packing.hpp"

namespace {
void BM_RandomPacking(benchmark::State& state) {
  const double phi = static_cast<double>(state.range(0)) / 100.0;
  const std::vector<suspend::Species> species{{1.0, 0.5}, {1.4, 0.5}};
  const auto radius = suspend::species_radii(species, suspend::species_counts(species, 1000));
  const suspend::Box box = suspend::cube_for_volume_fraction(radius, phi);
  suspend::PackingParams params;
  long steps = 0;
  for (auto _ : state) {
    const suspend::Packing p = suspend::random_packing(radius, box, params);
    benchmark::DoNotOptimize(p.position.data());
    steps = p.report.iterations;
  }
  state.counters["phi"] = phi;
  state.counters["fire_steps"] = static_cast<double>(steps);
}
}  // namespace

BENCHMARK(BM_RandomPacking)->Arg(55)->Arg(60)->Arg(62)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

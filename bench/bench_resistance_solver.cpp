// One overdamped resistance solve (assembly + linear solve + stress) for N = 500 and 4000 bidisperse spheres
// (a = 1 and 1.4, equal volume shares) at phi = 0.5 in simple shear, pairs from the cell list within the outer
// cutoff plus a skin (0.25 + 0.1 a_1), random O(1) forces and torques.
//   cold:     CG from zero;
//   warm:     CG from the solution of the previous step (particles advanced by dt = 1/1400 with the solved
//             velocities, the pair list kept, as between two neighbour-list rebuilds);
//   storage: cold CG with the coupling blocks dense and in pair form, N = 500, 2000, 8000;
//   warm block Jacobi: the same with the block-Jacobi preconditioner instead of symmetric Gauss-Seidel;
//   assembly and stress: a solve whose warm start is already the solution (0 iterations);
//   cholesky: sparse Cholesky with the symbolic analysis reused (same pattern), and with a fresh analysis.
// Usage: build/bin/bench_resistance_solver [--benchmark_filter=...]
#include <benchmark/benchmark.h>

#include <map>
#include <random>

#include "dem/integrate/resistance_solver.hpp"
#include "dem/neighbour_search.hpp"
#include "dem/packing.hpp"

namespace {

using namespace suspend;

struct Step {
  Particles p;
  std::vector<ActivePair> pairs;
};

struct Configuration {
  std::vector<double> species_radius{1.0, 1.4};
  Box box;
  Step previous, current;  // two consecutive time steps
  std::vector<Vec3> force, torque;
};

const Configuration& configuration(std::size_t n) {
  static std::map<std::size_t, Configuration> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Configuration& c = cache[n];
  const std::vector<Species> species{{1.0, 0.5}, {1.4, 0.5}};
  const auto counts = species_counts(species, n);
  const std::vector<double> radius = species_radii(species, counts);
  c.box = cube_for_volume_fraction(radius, 0.5);
  PackingParams pp;
  pp.seed = 3;
  const Packing packing = random_packing(radius, c.box, pp);
  Particles& p = c.previous.p;
  p.resize(radius.size());
  for (std::size_t i = 0; i < radius.size(); ++i) {
    p.position[i] = packing.position[i];
    p.radius[i] = radius[i];
    p.species[i] = i < counts[0] ? 0 : 1;
  }
  std::vector<NeighbourPair> list;
  CellListSearch search;
  search.find_pairs(p.position, p.radius, c.box, 0.35, list);
  compact_active_pairs(list, p, c.box, 0.35, c.previous.pairs);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  for (std::size_t i = 0; i < p.size(); ++i) {
    c.force.emplace_back(g(rng), g(rng), g(rng));
    c.torque.emplace_back(g(rng), g(rng), g(rng));
  }
  // Advance one step with the solved velocities; same pair list, new geometry.
  ResistanceSolver solver(c.species_radius, {});
  SolveResult out;
  solver.solve(p, c.previous.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  c.current = c.previous;
  const double dt = 1.0 / 1400.0;
  for (std::size_t i = 0; i < p.size(); ++i) c.current.p.position[i] += dt * out.velocity[i];
  for (ActivePair& pr : c.current.pairs) {
    const Vec3 d = c.box.minimum_image(c.current.p.position[pr.i], c.current.p.position[pr.j]).d;
    pr.set_geometry(PairGeometry::from(d, pr.a_i, pr.a_j));
  }
  return c;
}

void report(benchmark::State& state, const Configuration& c, const SolveResult& out) {
  state.counters["N"] = static_cast<double>(c.current.p.size());
  state.counters["lub_pairs"] = static_cast<double>(out.lubricated_pairs);
  state.counters["iterations"] = out.iterations;
  state.counters["residual"] = out.residual;
}

void BM_ConjugateGradientCold(benchmark::State& state) {
  const Configuration& c = configuration(static_cast<std::size_t>(state.range(0)));
  ResistanceSolverParams params;
  params.warm_start = false;
  ResistanceSolver solver(c.species_radius, params);
  SolveResult out;
  const AmbientFlow unit_shear = AmbientFlow::simple_shear(1.0);
  for (auto _ : state) solver.solve(c.current.p, c.current.pairs, unit_shear, c.force, c.torque, out);
  report(state, c, out);
}

void BM_ConjugateGradientWarm(benchmark::State& state) {
  const Configuration& c = configuration(static_cast<std::size_t>(state.range(0)));
  ResistanceSolver solver(c.species_radius, {});
  SolveResult out;
  for (auto _ : state) {
    state.PauseTiming();
    solver.solve(c.previous.p, c.previous.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
    state.ResumeTiming();
    solver.solve(c.current.p, c.current.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  }
  report(state, c, out);
}

// Cold CG (many iterations, so the time is that of the iterations) with the coupling blocks stored dense (arg 0)
// or in pair form (1): the cost per iteration of the two storages as the system outgrows the caches.
void BM_ConjugateGradientStorage(benchmark::State& state) {
  const Configuration& c = configuration(static_cast<std::size_t>(state.range(0)));
  ResistanceSolverParams params;
  params.warm_start = false;
  params.storage = state.range(1) == 0 ? CouplingStorage::dense : CouplingStorage::pair_form;
  ResistanceSolver solver(c.species_radius, params);
  SolveResult out;
  const AmbientFlow unit_shear = AmbientFlow::simple_shear(1.0);
  for (auto _ : state) solver.solve(c.current.p, c.current.pairs, unit_shear, c.force, c.torque, out);
  report(state, c, out);
  state.counters["us_per_iteration_and_particle"] = benchmark::Counter(
      out.iterations * static_cast<double>(c.current.p.size()) * 1e-6,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_ConjugateGradientWarmBlockJacobi(benchmark::State& state) {
  const Configuration& c = configuration(static_cast<std::size_t>(state.range(0)));
  ResistanceSolverParams params;
  params.preconditioner = Preconditioner::block_jacobi;
  ResistanceSolver solver(c.species_radius, params);
  SolveResult out;
  for (auto _ : state) {
    state.PauseTiming();
    solver.solve(c.previous.p, c.previous.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
    state.ResumeTiming();
    solver.solve(c.current.p, c.current.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  }
  report(state, c, out);
}

// Everything but the iterations: assembly, preconditioner set-up, one residual, velocities and stress (the warm
// start is already the solution).
void BM_AssemblyAndStress(benchmark::State& state) {
  const Configuration& c = configuration(static_cast<std::size_t>(state.range(0)));
  ResistanceSolver solver(c.species_radius, {});
  SolveResult out;
  solver.solve(c.current.p, c.current.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  const AmbientFlow unit_shear = AmbientFlow::simple_shear(1.0);
  for (auto _ : state) solver.solve(c.current.p, c.current.pairs, unit_shear, c.force, c.torque, out);
  report(state, c, out);
}

void BM_CholeskyPatternReused(benchmark::State& state) {
  const Configuration& c = configuration(static_cast<std::size_t>(state.range(0)));
  ResistanceSolverParams params;
  params.solver = LinearSolver::cholesky;
  ResistanceSolver solver(c.species_radius, params);
  SolveResult out;
  solver.solve(c.previous.p, c.previous.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  const AmbientFlow unit_shear = AmbientFlow::simple_shear(1.0);
  for (auto _ : state) solver.solve(c.current.p, c.current.pairs, unit_shear, c.force, c.torque, out);
  report(state, c, out);
  state.counters["analyses"] = solver.pattern_analyses();
}

void BM_CholeskyFreshAnalysis(benchmark::State& state) {
  const Configuration& c = configuration(static_cast<std::size_t>(state.range(0)));
  ResistanceSolverParams params;
  params.solver = LinearSolver::cholesky;
  SolveResult out;
  for (auto _ : state) {
    ResistanceSolver solver(c.species_radius, params);
    solver.solve(c.current.p, c.current.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  }
  report(state, c, out);
}

// The kernel of one CG iteration: y = R x with the assembled block matrix.
void BM_MatrixVectorProduct(benchmark::State& state) {
  const Configuration& c = configuration(static_cast<std::size_t>(state.range(0)));
  ResistanceSolver solver(c.species_radius, {});
  SolveResult out;
  solver.solve(c.current.p, c.current.pairs, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  const Eigen::VectorXd x = solver.disturbance();
  Eigen::VectorXd y(x.size());
  for (auto _ : state) {
    solver.matrix().multiply(x, y);
    benchmark::DoNotOptimize(y.data());
  }
  state.counters["blocks"] = static_cast<double>(solver.matrix().block_rows() + 2 * solver.matrix().links());
}

}  // namespace

BENCHMARK(BM_MatrixVectorProduct)->Arg(500)->Arg(4000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ConjugateGradientCold)->Arg(500)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConjugateGradientWarm)->Arg(500)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConjugateGradientStorage)
    ->ArgsProduct({{500, 2000, 8000}, {0, 1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConjugateGradientWarmBlockJacobi)->Arg(500)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AssemblyAndStress)->Arg(500)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CholeskyPatternReused)->Arg(500)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CholeskyFreshAnalysis)->Arg(500)->Arg(4000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

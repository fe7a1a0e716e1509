// Benchmarks of the pairwise engine's pair machinery (docs/performance.md has the numbers and commands).
//
//  BM_Search/<stencil>/<N>: neighbour search for N = 500, 8000, 65536 bidisperse spheres (radii 1 and 1.4, equal
//    volume shares) at phi = 0.5, positions uniform in the box (the search cost does not care about overlaps), a
//    Lees-Edwards offset of 0.37 L_x, gap cutoff 0.65 a_1 (lubrication outer cutoff 0.25 + skin 0.4).
//    stencil 0: half-stencil cell list (the engine's), 1: full stencil, 2: brute force O(N^2). items/s = pairs/s.
//  BM_ContactForces/<threads>: accumulate_pair_forces with the linear spring + Coulomb friction law and its pair
//    histories (paper 000 Table 1 parameters) on N = 8000 packed spheres whose radii are inflated by 1%, so that
//    near neighbours overlap; all pairs within the lubrication range 0.25 a_1 are evaluated. items/s = pairs/s.
//  BM_ContactForcesThreadRatio: the same loop timed alternately on 1 and 2 threads inside one run (the minimum of
//    each over the iterations), so load changes hit both equally; counter speedup = t(1) / t(2). On a loaded
//    machine the wall clock mostly measures the other processes, so the process CPU time of each batch is also
//    given: cpu_ratio = cpu(2 threads) / cpu(1 thread) is the work the second thread adds (1 = no overhead), and
//    speedup_bound = 2 / cpu_ratio the speedup two idle cores would give if the work is split evenly. As a control,
//    control_speedup is the same 1-vs-2-thread ratio for a loop with no shared data at all (a sum of square roots):
//    when it is near 1, the second core is taken by other processes and no loop can show a speedup.
//  BM_LubricationAssembly/<threads>: the resistance solver's assembly, preconditioner set-up, residual check and
//    stress for the same configuration, with a warm start that is already the solution (0 CG iterations); items/s =
//    lubricated pairs/s.
//  BM_ExplicitHydrodynamics/<0|1>: the inertial integrator's hydrodynamic forces, stress and rate bound at random
//    disturbance velocities on the same configuration: 0 = assembled (ResistanceSolver::explicit_forces +
//    relaxation_rate), 1 = matrix-free (ExplicitHydrodynamics, every pair evaluated from both ends); items/s =
//    lubricated pairs/s.
// All times are wall-clock (UseRealTime): the CPU time of the main thread says nothing about OpenMP loops.
// Usage: OMP_WAIT_POLICY=passive build/bin/bench_pairwise [--benchmark_filter=...]
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <map>
#include <random>

#include "dem/contact/contact_law.hpp"
#include "dem/integrate/explicit_hydrodynamics.hpp"
#include "dem/integrate/resistance_solver.hpp"
#include "dem/neighbour_search.hpp"
#include "dem/packing.hpp"
#include "dem/pair_forces.hpp"

namespace {

using namespace suspend;

const std::vector<Species> bidisperse{{1.0, 0.5}, {1.4, 0.5}};

struct Uniform {
  std::vector<Vec3> position;
  std::vector<double> radius;
  Box box;
};

const Uniform& uniform(std::size_t n) {
  static std::map<std::size_t, Uniform> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Uniform& u = cache[n];
  u.radius = species_radii(bidisperse, species_counts(bidisperse, n));
  u.box = cube_for_volume_fraction(u.radius, 0.5);
  u.box.set_shear_offset(0.37 * u.box.length().x());
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> f(0.0, 1.0);
  const Vec3& L = u.box.length();
  for (std::size_t i = 0; i < n; ++i) u.position.emplace_back(L.x() * f(rng), L.y() * f(rng), L.z() * f(rng));
  return u;
}

void BM_Search(benchmark::State& state) {
  const auto kind = state.range(0);
  const Uniform& u = uniform(static_cast<std::size_t>(state.range(1)));
  const double gap = 0.65;
  CellListSearch search(kind == 1 ? Stencil::full : Stencil::half);
  std::vector<NeighbourPair> pairs;
  for (auto _ : state) {
    if (kind == 2)
      find_pairs_brute_force(u.position, u.radius, u.box, gap, pairs);
    else
      search.find_pairs(u.position, u.radius, u.box, gap, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pairs.size()));  // pairs per second
}

struct Packed {
  Particles p;
  Box box;
  std::vector<ActivePair> active;
  std::vector<double> species_radius{1.01, 1.01 * 1.4};
  std::vector<Vec3> force, torque;
};

const Packed& packed() {
  static Packed c = [] {
    Packed k;
    const auto counts = species_counts(bidisperse, 8000);
    const std::vector<double> radius = species_radii(bidisperse, counts);
    k.box = cube_for_volume_fraction(radius, 0.5);
    PackingParams pp;
    pp.seed = 3;
    const Packing packing = random_packing(radius, k.box, pp);
    k.box.set_shear_offset(0.37 * k.box.length().x());
    Particles& p = k.p;
    p.resize(radius.size());
    std::mt19937_64 rng(5);
    std::normal_distribution<double> g;
    for (std::size_t i = 0; i < radius.size(); ++i) {
      p.position[i] = packing.position[i];
      p.radius[i] = k.species_radius[i < counts[0] ? 0 : 1];  // radii +1%: near neighbours overlap
      p.species[i] = i < counts[0] ? 0 : 1;
      p.velocity[i] = Vec3(g(rng), g(rng), g(rng));
      p.angular_velocity[i] = Vec3(g(rng), g(rng), g(rng));
      k.force.emplace_back(g(rng), g(rng), g(rng));
      k.torque.emplace_back(g(rng), g(rng), g(rng));
    }
    std::vector<NeighbourPair> list;
    CellListSearch search;
    search.find_pairs(p.position, p.radius, k.box, 0.25, list);
    compact_active_pairs(list, p, k.box, 0.25, k.active);
    return k;
  }();
  return c;
}

struct ForceLoop {
  // paper 000 Table 1: k-hat 4e5, k_t/k_n 2/7, gamma_n gammadot / k_n 1e-7 (the viscous damping sub-model), mu_C = 1
  ComposedLaw<LinearSpringCoulomb> law;
  std::vector<PairHistory> history;
  PairSums sums;
  std::vector<Vec3> pair_force;
  std::vector<PairSums> local;
  explicit ForceLoop(std::size_t pairs) : history(pairs) {
    law.contact.damping = NormalDamping::viscous(1.0e-7 * 4.0e5);
  }
  void run(const Packed& c) {
    accumulate_pair_forces(c.active, c.p, c.box.length().y(), law, 1e-5, history, sums, pair_force, local);
  }
};

void BM_ContactForces(benchmark::State& state) {
  const Packed& c = packed();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  ForceLoop loop(c.active.size());
  loop.run(c);
  for (auto _ : state) {
    loop.run(c);
    benchmark::DoNotOptimize(loop.sums.force.data());
  }
  omp_set_num_threads(omp_get_num_procs());
  state.counters["pairs"] = static_cast<double>(c.active.size());
  state.counters["contacts"] = static_cast<double>(loop.sums.contacts);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.active.size()));  // pairs per second
}

void BM_ContactForcesThreadRatio(benchmark::State& state) {
  const Packed& c = packed();
  ForceLoop one(c.active.size()), two(c.active.size());
  double best1 = 1e30, best2 = 1e30, cpu1 = 1e30, cpu2 = 1e30;
  auto cpu_now = [] {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  };
  auto timed = [&](ForceLoop& loop, int threads, double& best, double& cpu) {
    omp_set_num_threads(threads);
    const double c0 = cpu_now();
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < 20; ++r) loop.run(c);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / 20);
    cpu = std::min(cpu, (cpu_now() - c0) / 20);
  };
  double control1 = 1e30, control2 = 1e30;
  auto control = [&](int threads, double& best) {
    omp_set_num_threads(threads);
    const auto t0 = std::chrono::steady_clock::now();
    double sum = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum)
    for (long i = 0; i < 10'000'000; ++i) sum += std::sqrt(static_cast<double>(i));
    benchmark::DoNotOptimize(sum);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  };
  double unused_wall = 0.0, unused_cpu = 0.0;
  timed(one, 1, unused_wall, unused_cpu);
  timed(two, 2, unused_wall, unused_cpu);
  for (auto _ : state) {
    timed(one, 1, best1, cpu1);
    timed(two, 2, best2, cpu2);
    control(1, control1);
    control(2, control2);
  }
  omp_set_num_threads(omp_get_num_procs());
  state.counters["t1_us"] = 1e6 * best1;
  state.counters["t2_us"] = 1e6 * best2;
  state.counters["speedup"] = best1 / best2;
  state.counters["cpu_ratio"] = cpu2 / cpu1;
  state.counters["speedup_bound"] = 2.0 * cpu1 / cpu2;
  state.counters["control_speedup"] = control1 / control2;
}

void BM_LubricationAssembly(benchmark::State& state) {
  const Packed& c = packed();
  omp_set_num_threads(static_cast<int>(state.range(0)));
  ResistanceSolver solver(c.species_radius, {});
  SolveResult out;
  solver.solve(c.p, c.active, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  for (auto _ : state) solver.solve(c.p, c.active, AmbientFlow::simple_shear(1.0), c.force, c.torque, out);
  omp_set_num_threads(omp_get_num_procs());
  state.counters["lub_pairs"] = static_cast<double>(out.lubricated_pairs);
  state.counters["iterations"] = out.iterations;
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(out.lubricated_pairs));
}

void BM_ExplicitHydrodynamics(benchmark::State& state) {
  const Packed& c = packed();
  const std::size_t n = c.p.size();
  Eigen::VectorXd dv(6 * static_cast<Eigen::Index>(n));
  std::mt19937_64 rng(9);
  std::normal_distribution<double> g;
  for (Eigen::Index k = 0; k < dv.size(); ++k) dv[k] = g(rng);
  std::vector<double> mass(n), moment(n);
  for (std::size_t i = 0; i < n; ++i) {
    mass[i] = 1e-3 * (4.0 / 3.0) * 3.141592653589793 * std::pow(c.p.radius[i], 3);
    moment[i] = 0.4 * mass[i] * c.p.radius[i] * c.p.radius[i];
  }
  const AmbientFlow flow = AmbientFlow::simple_shear(1.0);
  ResistanceSolver assembled(c.species_radius, {});
  ExplicitHydrodynamics matrix_free(c.species_radius, hydro::LubricationParams{});
  Eigen::VectorXd force;
  SolveResult out;
  ExplicitHydroResult result;
  double rate = 0.0;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      assembled.explicit_forces(c.p, c.p.species, c.active, flow, dv, force, out);
      rate = assembled.relaxation_rate(mass, moment);
    } else {
      matrix_free.evaluate(c.p, c.p.species, c.active, flow, dv, mass, moment, result);
      rate = result.relaxation_rate;
    }
    benchmark::DoNotOptimize(rate);
  }
  matrix_free.evaluate(c.p, c.p.species, c.active, flow, dv, mass, moment, result);
  state.counters["lub_pairs"] = static_cast<double>(result.lubricated_pairs);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(result.lubricated_pairs));
}

}  // namespace

BENCHMARK(BM_Search)
    ->ArgsProduct({{0, 1, 2}, {500, 8000}})
    ->Args({0, 65536})
    ->Args({1, 65536})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Search)->Args({2, 65536})->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ContactForces)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ContactForcesThreadRatio)->Iterations(10)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LubricationAssembly)->Arg(1)->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExplicitHydrodynamics)->Arg(0)->Arg(1)->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

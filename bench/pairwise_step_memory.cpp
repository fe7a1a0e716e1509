// Peak resident memory per particle of the pairwise engine's full overdamped step (docs/performance.md, item d):
// paper 000 Table 3 suspension (N = 65536, a_2/a_1 = 3, V_2/V_1 = 0.25, phi = 0.5) with pairwise lubrication
// (outer cutoff 0.25 a_1) and linear-spring Coulomb contacts (k-hat = 4e5, k_t/k_n = 2/7, gamma_n gammadot/k_n =
// 1e-7, mu_C = 1). Surface forces are left out: the brief measures lubrication + frictional contacts.
//
//   pairwise_step_memory pack FILE [N]          random packing, written as "x y z radius" lines
//   pairwise_step_memory step FILE [STEPS]      reads FILE, runs STEPS full steps (default 5) and prints
//       the resident-set baseline before the particles are read, the peak (VmHWM) at the end, and
//       (peak - baseline) / N, plus the bytes held by the main per-pair and per-particle buffers.
// Threads: OMP_NUM_THREADS (per-thread scratch is part of the peak).
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "dem/packing.hpp"
#include "dem/simulation.hpp"

namespace {

using namespace suspend;

long status_kb(const char* key) {  // a field of /proc/self/status, in kB
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string k = std::string(key) + ":";
  while (std::getline(in, line))
    if (line.rfind(k, 0) == 0) return std::stol(line.substr(k.size()));
  return -1;
}

std::vector<double> table3_radii(std::size_t n) {
  const std::vector<Species> species{{1.0, 0.8}, {3.0, 0.2}};  // V_2/V_1 = 0.2/0.8 = 0.25
  return species_radii(species, species_counts(species, n));
}

int pack(const std::string& file, std::size_t n) {
  const std::vector<double> radius = table3_radii(n);
  const Box box = cube_for_volume_fraction(radius, 0.5);
  PackingParams pp;
  pp.min_gap = 1e-3;
  const Packing packing = random_packing(radius, box, pp);
  std::ofstream out(file);
  out.precision(17);
  out << "# box " << box.length().x() << "\n";
  for (std::size_t i = 0; i < radius.size(); ++i)
    out << packing.position[i].x() << ' ' << packing.position[i].y() << ' ' << packing.position[i].z() << ' '
        << radius[i] << '\n';
  std::printf("packed %zu spheres, phi %.4f, %.1f s\n", radius.size(), packing.report.phi,
              packing.report.wall_seconds);
  return 0;
}

int step(const std::string& file, int steps) {
  const long baseline = status_kb("VmRSS");
  std::ifstream in(file);
  std::string hash, word;
  double edge = 0.0;
  in >> hash >> word >> edge;
  SimulationState state;
  Particles& p = state.particles;
  double x, y, z, a;
  while (in >> x >> y >> z >> a) {
    p.position.emplace_back(x, y, z);
    p.radius.push_back(a);
    p.species.push_back(a > 1.5 ? 1 : 0);
  }
  const std::size_t n = p.radius.size();
  p.velocity.assign(n, Vec3::Zero());
  p.angular_velocity.assign(n, Vec3::Zero());
  const Box box(edge, edge, edge);

  SimulationParams params;
  ComposedLaw<LinearSpringCoulomb> law;
  law.contact.p = {4.0e5, 2.0 / 7.0 * 4.0e5, 1.0e-7 * 4.0e5};
  law.contact.friction.p.mu = 1.0;
  params.contact = law;
  params.lubrication = true;
  params.resistance.lubrication.outer_cutoff = 0.25;

  const auto t0 = std::chrono::steady_clock::now();
  PairwiseSimulation sim(std::move(state), box, params);
  for (int s = 0; s < steps; ++s) {
    sim.evaluate();
    sim.advance();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const long peak = status_kb("VmHWM");
  std::printf("N %zu, threads %d, %d steps in %.2f s; active pairs %zu, list pairs %zu, contacts %zu, CG its %d\n",
              n, omp_get_max_threads(), steps, seconds, sim.active_pairs().size(), sim.neighbours().pairs().size(),
              sim.contact_count(), sim.solver_iterations());
  std::printf("baseline RSS %ld kB, peak RSS %ld kB, (peak - baseline) / N = %.0f B per particle\n", baseline, peak,
              1024.0 * static_cast<double>(peak - baseline) / static_cast<double>(n));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: pairwise_step_memory pack FILE [N] | step FILE [STEPS]\n";
    return 2;
  }
  const std::string mode = argv[1], file = argv[2];
  if (mode == "pack") return pack(file, argc > 3 ? std::stoul(argv[3]) : 65536);
  if (mode == "step") return step(file, argc > 3 ? std::stoi(argv[3]) : 5);
  std::cerr << "unknown mode " << mode << "\n";
  return 2;
}

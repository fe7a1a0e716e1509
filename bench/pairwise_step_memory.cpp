// Peak resident memory per particle of the pairwise engine's full step (docs/performance.md, item d): paper 000
// Table 3 suspension (N = 65536, a_2/a_1 = 3, V_2/V_1 = 0.25, phi = 0.5) with pairwise lubrication (outer cutoff
// 0.25 a_1), linear-spring Coulomb contacts (k-hat = 4e5, k_t/k_n = 2/7, gamma_n gammadot/k_n = 1e-7, mu_C = 1)
// and, as cases/validation/large_bidisperse_uniform.yaml, the surface forces of Table 3: electrostatic repulsion
// (F_ER = 1, lambda_D = 0.02 a_1, cut at 20 lambda_D) and van der Waals attraction (F^R/F^A = 19, cut at 0.5 a_1).
//
//   pairwise_step_memory pack FILE [N]                      random packing, written as "x y z radius" lines
//   pairwise_step_memory step FILE [STEPS [INTEGRATOR [SURFACE [STORAGE]]]]
//       reads FILE, runs STEPS full steps (default 5) with INTEGRATOR = overdamped (default: the resistance solve)
//       or inertial (paper 000 eq. 15 at St = 1e-3, explicit matrix-free hydrodynamics); SURFACE = surface
//       (default) or none (lubrication + contacts only, the set-up of the first measurements); STORAGE = dense
//       (default here), pair_form or auto, the resistance matrix's coupling blocks (hydrodynamics.solver.storage,
//       whose default is auto). Prints the
//       resident-set baseline before the particles are read, the peak (VmHWM) at the end, (peak - baseline) / N,
//       and the bytes held by the main per-pair buffers.
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

int step(const std::string& file, int steps, const std::string& integrator, const std::string& surface,
         const std::string& storage) {
  if ((integrator != "overdamped" && integrator != "inertial") || (surface != "surface" && surface != "none") ||
      (storage != "dense" && storage != "pair_form" && storage != "auto")) {
    std::cerr << "INTEGRATOR is overdamped or inertial, SURFACE is surface or none, STORAGE is dense, pair_form or "
                 "auto\n";
    return 2;
  }
  const long baseline = status_kb("VmRSS");
  SimulationState state;
  Particles& p = state.particles;
  double edge = 0.0;
  {
    // Two passes: count the particles, then read them into vectors of exactly that size (growing vectors by
    // push_back would leave freed blocks of every size on the heap before the run starts).
    std::ifstream in(file);
    std::string line;
    std::size_t n = 0;
    while (std::getline(in, line))
      if (!line.empty() && line[0] != '#') ++n;
    in.clear();
    in.seekg(0);
    std::string hash, word;
    in >> hash >> word >> edge;
    p.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      double x, y, z, a;
      if (!(in >> x >> y >> z >> a)) {
        std::cerr << file << ": unreadable particle line " << i + 1 << "\n";
        return 2;
      }
      p.position[i] = Vec3(x, y, z);
      p.radius[i] = a;
      p.species[i] = a > 1.5 ? 1 : 0;
    }
  }
  const std::size_t n = p.radius.size();
  const Box box(edge, edge, edge);

  SimulationParams params;
  ComposedLaw<LinearSpringCoulomb> law;
  law.contact.normal.p = {4.0e5};
  law.contact.damping = NormalDamping::viscous(1.0e-7 * 4.0e5);
  law.contact.friction.p.mu = 1.0;
  if (surface == "surface") {
    ElectrostaticRepulsionParams repulsion;  // F_ER = 1 (gamma-hat = 1), lambda_D = 0.02, cut at 20 lambda_D
    repulsion.force = 1.0;
    repulsion.debye_length = 0.02;
    VanDerWaalsParams attraction;  // F^R/F^A = 19 at contact (the case file's Hamaker constant), cut at 0.5 a_1
    attraction.hamaker = 6.3158e-5;
    attraction.cutoff = 0.5;
    law.surface.repulsion = ElectrostaticRepulsion{repulsion};
    law.surface.attraction = VanDerWaals{attraction};
  }
  params.contact = law;
  params.lubrication = true;
  params.resistance.lubrication.outer_cutoff = 0.25;
  if (storage != "auto")
    params.resistance.storage = storage == "pair_form" ? CouplingStorage::pair_form : CouplingStorage::dense;
  if (integrator == "inertial") {
    params.integrator = Integrator::inertial;
    params.stokes_number = 1.0e-3;
  }

  const auto t0 = std::chrono::steady_clock::now();
  Simulation sim(std::move(state), box, params);
  for (int s = 0; s < steps; ++s) {
    sim.evaluate();
    sim.advance();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const long peak = status_kb("VmHWM");
  std::printf("N %zu, %s%s%s, threads %d, %d steps in %.2f s (dt %.3g); active pairs %zu, list pairs %zu, "
              "contacts %zu, CG its %d\n",
              n, integrator.c_str(), surface == "surface" ? " + surface forces" : "",
              storage == "dense" ? "" : (", " + storage + " blocks").c_str(), omp_get_max_threads(), steps,
              seconds, sim.time_step(), sim.active_pairs().size(), sim.neighbours().pairs().size(),
              sim.contact_count(), sim.solver_iterations());
  std::printf("baseline RSS %ld kB, peak RSS %ld kB, (peak - baseline) / N = %.0f B per particle\n", baseline, peak,
              1024.0 * static_cast<double>(peak - baseline) / static_cast<double>(n));
  const double per = 1.0 / static_cast<double>(n);
  std::printf("held per particle: active pairs %.0f B (%zu x %zu B), pair forces %.0f B, neighbour list %.0f B\n",
              per * static_cast<double>(sim.active_pairs().capacity() * sizeof(ActivePair)),
              sim.active_pairs().capacity(), sizeof(ActivePair),
              per * static_cast<double>(sim.pair_forces().capacity() * sizeof(Vec3)),
              per * static_cast<double>(sim.neighbours().pairs().capacity() * sizeof(NeighbourPair)));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: pairwise_step_memory pack FILE [N] | step FILE [STEPS [overdamped|inertial [surface|none [dense|pair_form|auto]]]]\n";
    return 2;
  }
  const std::string mode = argv[1], file = argv[2];
  if (mode == "pack") return pack(file, argc > 3 ? std::stoul(argv[3]) : 65536);
  if (mode == "step")
    return step(file, argc > 3 ? std::stoi(argv[3]) : 5, argc > 4 ? argv[4] : "overdamped",
                argc > 5 ? argv[5] : "surface", argc > 6 ? argv[6] : "dense");
  std::cerr << "unknown mode " << mode << "\n";
  return 2;
}

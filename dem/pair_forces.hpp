// The generic pair driver (STYLE.md: pure law + generic driver). It owns the loop over interacting pairs, the
// Lees-Edwards images, Newton's third law and the accumulation of forces, torques and stress by contribution.
//
// Determinism: the pairs that interact are first compacted, in list order, to those within the exact interaction
// range; work is then split over threads by position in that compact list and per-thread sums are reduced in
// thread order. The result depends only on the configuration and the thread count, never on when the
// neighbour list was rebuilt, so a restarted run reproduces an uninterrupted one bit for bit.
#pragma once
#include <omp.h>

#include <cmath>
#include <vector>

#include "core/box.hpp"
#include "core/particles.hpp"
#include "core/stress.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"
#include "dem/neighbour_search.hpp"

namespace suspend {

struct ActivePair {
  std::uint32_t i, j;
  int y_images;  // Lees-Edwards image index of j (for velocity corrections)
  PairGeometry geometry;
};

struct PairSums {
  std::vector<Vec3> force, torque;  // per particle
  StressTensors virial;             // sum over pairs of -sym(d F_j^T), not yet divided by the volume
  double max_overlap = 0.0;         // largest -gap over all pairs
  std::uint32_t max_overlap_i = 0, max_overlap_j = 0;
  std::size_t contacts = 0;  // pairs with gap < 0
  // Sum over pairs with an elastic contact (PairForce::normal_stiffness > 0) of their compliance length
  // F_n / (dF_n/d delta) (the overlap for linear springs, 2/3 of the compression for Hertz), and their count.
  double compliance_sum = 0.0;
  std::size_t elastic_contacts = 0;
  double mean_compliance() const { return elastic_contacts ? compliance_sum / static_cast<double>(elastic_contacts) : 0.0; }
};

// Tangent stiffnesses of a pair's contact law at this step (PairForce::normal_stiffness, tangential_stiffness),
// for the linearly implicit contact step.
struct ContactStiffness {
  double normal = 0.0, tangential = 0.0;
  bool any() const { return normal > 0.0 || tangential > 0.0; }
};

// Pairs of the list whose gap is below interaction_gap, with their geometry.
void compact_active_pairs(const std::vector<NeighbourPair>& list, const Particles& p, const Box& box,
                          double interaction_gap, std::vector<ActivePair>& active);

// Evaluates law(geometry, motion, dt, history[k]) -> PairForce on every active pair and accumulates into sums;
// the force on j of each pair goes to pair_force[k] (snapshots). velocity/omega are the particle velocities the
// contact laws see (the last step's); the image of j moves at u_j - y_images gammadot L_y x (Lees-Edwards).
// `local` is per-thread scratch kept by the caller so that steps do not allocate. If `stiffness` is given, it gets
// each pair's contact stiffnesses (same order as active).
template <class Law>
void accumulate_pair_forces(const std::vector<ActivePair>& active, const Particles& p, double image_velocity,
                            const Law& law, double dt, std::vector<PairHistory>& history, PairSums& sums,
                            std::vector<Vec3>& pair_force, std::vector<PairSums>& local,
                            std::vector<ContactStiffness>* stiffness = nullptr) {
  const std::size_t n_particles = p.size();
  // Small systems stay on one thread: a parallel region costs more than their whole loop (and far more when the
  // cores are shared). The split depends only on the pair count, so results stay reproducible.
  const int nthreads = active.size() >= 2048 ? omp_get_max_threads() : 1;
  local.resize(nthreads);
  pair_force.resize(active.size());
  if (stiffness) stiffness->resize(active.size());
  ContactStiffness* const pair_stiffness = stiffness ? stiffness->data() : nullptr;
  sums.force.resize(n_particles);
  sums.torque.resize(n_particles);
#pragma omp parallel num_threads(nthreads)
  {
    const int t = omp_get_thread_num();
    PairSums& mine = local[t];
    mine.force.assign(n_particles, Vec3::Zero());
    mine.torque.assign(n_particles, Vec3::Zero());
    Vec3* const force = mine.force.data();
    Vec3* const torque = mine.torque.data();
    // Scalars and the virial are summed on the thread's stack and stored once: the PairSums of neighbouring
    // threads are adjacent in `local`, and writing them per pair would bounce cache lines between cores.
    StressTensors virial;
    std::size_t contacts = 0, elastic = 0;
    double max_overlap = 0.0, compliance = 0.0;
    std::uint32_t max_i = 0, max_j = 0;
    const std::size_t np = active.size();
    const std::size_t begin = np * t / nthreads, end = np * (t + 1) / nthreads;
    for (std::size_t k = begin; k < end; ++k) {
      const ActivePair& pr = active[k];
      const RelativeMotion m{p.velocity[pr.i], p.velocity[pr.j] - Vec3(pr.y_images * image_velocity, 0.0, 0.0),
                             p.angular_velocity[pr.i], p.angular_velocity[pr.j]};
      const PairForce f = law(pr.geometry, m, dt, history[k]);
      const Vec3 fj = f.total_on_j();
      pair_force[k] = fj;
      if (pair_stiffness) pair_stiffness[k] = {f.normal_stiffness, f.tangential_stiffness};
      if (f.normal_stiffness > 0.0) {
        compliance += std::abs(f[Contribution::contact_normal].dot(pr.geometry.n)) / f.normal_stiffness;
        ++elastic;
      }
      force[pr.j] += fj;
      force[pr.i] -= fj;
      torque[pr.i] += f.torque_i;
      torque[pr.j] += f.torque_j;
      for (std::size_t c = 0; c < contribution_count; ++c)
        if (f.on_j[c].squaredNorm() > 0.0) virial.part[c] -= sym_outer(pr.geometry.d, f.on_j[c]);
      const double overlap = -pr.geometry.gap();
      if (overlap > 0.0) ++contacts;
      if (overlap > max_overlap) {
        max_overlap = overlap;
        max_i = pr.i;
        max_j = pr.j;
      }
    }
    mine.virial = virial;
    mine.contacts = contacts;
    mine.compliance_sum = compliance;
    mine.elastic_contacts = elastic;
    mine.max_overlap = max_overlap;
    mine.max_overlap_i = max_i;
    mine.max_overlap_j = max_j;
    // Per-particle sums over the threads, in thread order (the same order for every particle split).
#pragma omp barrier
#pragma omp for schedule(static)
    for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(n_particles); ++i) {
      Vec3 f = Vec3::Zero(), tq = Vec3::Zero();
      for (const PairSums& l : local) {
        f += l.force[i];
        tq += l.torque[i];
      }
      sums.force[i] = f;
      sums.torque[i] = tq;
    }
  }
  sums.virial.clear();
  sums.max_overlap = 0.0;
  sums.contacts = 0;
  sums.compliance_sum = 0.0;
  sums.elastic_contacts = 0;
  for (const PairSums& l : local) {
    for (std::size_t c = 0; c < contribution_count; ++c) sums.virial.part[c] += l.virial.part[c];
    sums.contacts += l.contacts;
    sums.compliance_sum += l.compliance_sum;
    sums.elastic_contacts += l.elastic_contacts;
    if (l.max_overlap > sums.max_overlap) {
      sums.max_overlap = l.max_overlap;
      sums.max_overlap_i = l.max_overlap_i;
      sums.max_overlap_j = l.max_overlap_j;
    }
  }
}

}  // namespace suspend

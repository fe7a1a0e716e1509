// The generic pair driver: the laws are pure functions of one pair, and this one driver owns the loop over
// interacting pairs, the Lees-Edwards images, Newton's third law and the accumulation of forces, torques and
// stress by contribution.
//
// Determinism: the pairs that interact are first compacted, in list order, to those within the exact interaction
// range; work is then split over threads by position in that compact list and per-thread sums are reduced in
// thread order. The result depends only on the configuration and the thread count, never on when the
// neighbour list was rebuilt, so a restarted run reproduces an uninterrupted one bit for bit.
#pragma once
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/box.hpp"
#include "core/capacity.hpp"
#include "core/error.hpp"
#include "core/particles.hpp"
#include "core/stress.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "dem/contact/pair_history.hpp"
#include "dem/neighbour_search.hpp"

namespace suspend {

// A pair within the interaction range. It keeps d, r and the radii; geometry() forms n = d / r again, bit for bit
// what PairGeometry::from gave, so that a pair costs 64 B instead of 88 B (docs/performance.md section d).
struct ActivePair {
  std::uint32_t i = 0, j = 0;
  int y_images = 0;  // Lees-Edwards image index of j (for velocity corrections)
  Vec3 d = Vec3::Zero();
  double r = 0.0, a_i = 0.0, a_j = 0.0;
  ActivePair() = default;
  ActivePair(std::uint32_t i, std::uint32_t j, int y_images, const PairGeometry& g)
      : i(i), j(j), y_images(y_images) {
    set_geometry(g);
  }
  // A value, const so that assigning to it (a no-op) does not compile: set_geometry() changes the pair.
  const PairGeometry geometry() const { return {d, d / r, r, a_i, a_j}; }
  void set_geometry(const PairGeometry& g) {
    d = g.d;
    r = g.r;
    a_i = g.a_i;
    a_j = g.a_j;
  }
  double gap() const { return r - a_i - a_j; }
};

struct PairSums {
  std::vector<Vec3> force, torque;  // per particle
  StressTensors virial;             // sum over pairs of -sym(d F_j^T), not yet divided by the volume
  double max_overlap = 0.0;         // largest -gap over all pairs
  std::uint32_t max_overlap_i = 0, max_overlap_j = 0;
  std::size_t contacts = 0;  // pairs with a normal contact force (docs/output.md)
  std::size_t offset = 0;    // per-thread scratch of accumulate_pair_forces: force[k] is particle offset + k's
  // Sum over pairs with an elastic contact (PairForce::normal_stiffness > 0) of their compliance length
  // F_n / (dF_n/d delta) (the overlap for linear springs, 2/3 of the compression for Hertz), and their count.
  double compliance_sum = 0.0;
  std::size_t elastic_contacts = 0;
  double mean_compliance() const { return elastic_contacts ? compliance_sum / static_cast<double>(elastic_contacts) : 0.0; }
};

// What a snapshot records of a pair: whether the contact law exerts a normal force on it (a contact, the
// definition of PairSums::contacts), the contact law's normal and tangential force on j, and whether it slides.
struct ContactRecord {
  Vec3 normal = Vec3::Zero(), tangential = Vec3::Zero();
  bool contact = false, sliding = false;
};

// The records of a pair list, by pair: records[slot[k]] for pairs with a history slot (ContactStage keeps records
// only for the pairs its contact law can touch; -1: none, no contact), or records[k] without slots.
class ContactRecords {
 public:
  ContactRecords(const std::vector<ContactRecord>& records, const std::vector<std::int32_t>* slot = nullptr)
      : records_(&records), slot_(slot) {}
  ContactRecord operator[](std::size_t k) const {
    const ContactRecord* r = find(k);
    return r ? *r : ContactRecord{};
  }
  bool contact(std::size_t k) const {
    const ContactRecord* r = find(k);
    return r && r->contact;
  }

 private:
  const ContactRecord* find(std::size_t k) const {
    if (!slot_) return &(*records_)[k];
    const std::int32_t s = (*slot_)[k];
    return s < 0 ? nullptr : &(*records_)[static_cast<std::size_t>(s)];
  }
  const std::vector<ContactRecord>* records_;
  const std::vector<std::int32_t>* slot_;
};

// Tangent stiffnesses of a pair's contact law at this step (PairForce::normal_stiffness, tangential_stiffness,
// slip_direction), for the linearly implicit contact step: S = normal n n + tangential (I - n n - t t), t the slip
// direction of a sliding contact (zero while it sticks).
struct ContactStiffness {
  double normal = 0.0, tangential = 0.0;
  Vec3 slip_direction = Vec3::Zero();
  bool any() const { return normal > 0.0 || tangential > 0.0; }
};

// Pairs of the list whose gap is below interaction_gap, with their geometry.
void compact_active_pairs(const std::vector<NeighbourPair>& list, const Particles& p, const Box& box,
                          double interaction_gap, std::vector<ActivePair>& active);

// Evaluates law(species_i, species_j, geometry, motion, dt, history[k]) -> PairForce on every active pair and accumulates into sums;
// the force on j of each pair goes to pair_force[k] (snapshots). velocity/omega are the particle velocities the
// contact laws see (the last step's); the image of j moves at u_j - y_images gammadot L_y x (Lees-Edwards).
// `local` is per-thread scratch kept by the caller so that steps do not allocate. If `stiffness` is given, it gets
// each pair's contact stiffnesses (same order as active). With `history_slot`, pair k's history is
// history[history_slot[k]] and its record records[history_slot[k]]; a pair without a slot (-1: beyond the contact
// law's range and not in contact before) starts from a fresh history that is not kept and has no record; a law that
// brings such a pair into contact or exerts a contact force on it is a NumericalError.
template <class Law>
void accumulate_pair_forces(const std::vector<ActivePair>& active, const Particles& p, double image_velocity,
                            const Law& law, double dt, std::vector<PairHistory>& history, PairSums& sums,
                            std::vector<Vec3>& pair_force, std::vector<PairSums>& local,
                            std::vector<ContactStiffness>* stiffness = nullptr,
                            std::vector<ContactRecord>* records = nullptr,
                            const std::vector<std::int32_t>* history_slot = nullptr) {
  const std::size_t n_particles = p.size();
  // Small systems stay on one thread: a parallel region costs more than their whole loop (and far more when the
  // cores are shared). The split depends only on the pair count, so results stay reproducible.
  const int nthreads = active.size() >= 2048 ? omp_get_max_threads() : 1;
  local.resize(nthreads);
  resize_with_headroom(pair_force, active.size());
  if (stiffness) stiffness->resize(active.size());
  ContactStiffness* const pair_stiffness = stiffness ? stiffness->data() : nullptr;
  if (records) resize_with_headroom(*records, history_slot ? history.size() : active.size());
  ContactRecord* const pair_record = records ? records->data() : nullptr;
  sums.force.resize(n_particles);
  sums.torque.resize(n_particles);
  bool beyond = false;  // a pair without a history slot came into contact (or-reduced over the threads)
#pragma omp parallel num_threads(nthreads) reduction(|| : beyond)
  {
    const int t = omp_get_thread_num();
    PairSums& mine = local[t];
    const std::size_t np = active.size();
    const std::size_t begin = np * t / nthreads, end = np * (t + 1) / nthreads;
    // Thread 0 sums straight into the result; every other thread into its own array, which covers only the
    // particles its pairs touch (index offset .. offset + size - 1: for a list sorted by i with i < j, about the
    // upper (nthreads - t) / nthreads of the particles), so that less is zeroed and summed per call.
    Vec3 *force, *torque;  // force[i - offset] is particle i's
    std::uint32_t offset = 0;
    if (t == 0) {
      std::fill(sums.force.begin(), sums.force.end(), Vec3::Zero());
      std::fill(sums.torque.begin(), sums.torque.end(), Vec3::Zero());
      force = sums.force.data();
      torque = sums.torque.data();
      mine.offset = 0;
      mine.force.clear();
      mine.torque.clear();
    } else {
      std::uint32_t lo = begin < end ? active[begin].i : 0, hi = lo;
      for (std::size_t k = begin; k < end; ++k) {
        lo = std::min({lo, active[k].i, active[k].j});
        hi = std::max({hi, active[k].i, active[k].j});
      }
      const std::size_t span = begin < end ? std::size_t{hi} - lo + 1 : 0;
      offset = lo;
      mine.offset = lo;
      resize_with_headroom(mine.force, span);  // the span changes a little from call to call
      resize_with_headroom(mine.torque, span);
      std::fill(mine.force.begin(), mine.force.end(), Vec3::Zero());
      std::fill(mine.torque.begin(), mine.torque.end(), Vec3::Zero());
      force = mine.force.data();
      torque = mine.torque.data();
    }
    // Scalars and the virial are summed on the thread's stack and stored once: the PairSums of neighbouring
    // threads are adjacent in `local`, and writing them per pair would bounce cache lines between cores.
    StressTensors virial;
    std::size_t contacts = 0, elastic = 0;
    double max_overlap = 0.0, compliance = 0.0;
    std::uint32_t max_i = 0, max_j = 0;
    PairHistory spare;
    for (std::size_t k = begin; k < end; ++k) {
      const ActivePair& pr = active[k];
      const RelativeMotion m{p.velocity[pr.i], p.velocity[pr.j] - Vec3(pr.y_images * image_velocity, 0.0, 0.0),
                             p.angular_velocity[pr.i], p.angular_velocity[pr.j]};
      const std::int32_t slot = history_slot ? (*history_slot)[k] : static_cast<std::int32_t>(k);
      if (slot < 0) spare = PairHistory{};
      PairHistory& h = slot < 0 ? spare : history[static_cast<std::size_t>(slot)];
      const PairGeometry g = pr.geometry();
      const PairForce f = law(p.species[pr.i], p.species[pr.j], g, m, dt, h);
      if (slot < 0 && spare.in_contact) beyond = true;
      const Vec3 fj = f.total_on_j();
      pair_force[k] = fj;
      if (pair_stiffness) pair_stiffness[k] = {f.normal_stiffness, f.tangential_stiffness, f.slip_direction};
      if (f.normal_stiffness > 0.0) {
        compliance += std::abs(f[Contribution::contact_normal].dot(g.n)) / f.normal_stiffness;
        ++elastic;
      }
      force[pr.j - offset] += fj;
      force[pr.i - offset] -= fj;
      torque[pr.i - offset] += f.torque_i;
      torque[pr.j - offset] += f.torque_j;
      for (std::size_t c = 0; c < contribution_count; ++c)
        if (f.on_j[c].squaredNorm() > 0.0) virial.part[c] -= sym_outer(pr.d, f.on_j[c]);
      // A contact: the contact law exerts a normal force (overlap for the spring laws, a gap below the roughness
      // height for Hertz + adhesion).
      const bool contact = f[Contribution::contact_normal].squaredNorm() > 0.0;
      if (contact) ++contacts;
      if (pair_record && slot >= 0)
        pair_record[slot] = {f[Contribution::contact_normal], f[Contribution::contact_tangential], contact, f.sliding};
      if (slot < 0 && contact) beyond = true;
      const double overlap = -pr.gap();
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
    // The other threads' arrays added to thread 0's sums, in thread order for every particle (the same order for
    // every particle split; a particle outside a thread's range gets no term, where an exact zero was added).
    if (nthreads > 1) {
#pragma omp barrier
      std::size_t first = n_particles, last = 0;  // the particles any other thread touched
      for (int u = 1; u < nthreads; ++u)
        if (!local[u].force.empty()) {
          first = std::min(first, local[u].offset);
          last = std::max(last, local[u].offset + local[u].force.size());
        }
#pragma omp for schedule(static) nowait  // the end of the parallel region is the barrier
      for (std::ptrdiff_t i = static_cast<std::ptrdiff_t>(first); i < static_cast<std::ptrdiff_t>(last); ++i) {
        Vec3 f = sums.force[i], tq = sums.torque[i];
        for (int u = 1; u < nthreads; ++u) {
          const PairSums& l = local[u];
          const std::size_t at = static_cast<std::size_t>(i) - l.offset;
          if (static_cast<std::size_t>(i) >= l.offset && at < l.force.size()) {
            f += l.force[at];
            tq += l.torque[at];
          }
        }
        sums.force[i] = f;
        sums.torque[i] = tq;
      }
    }
  }
  if (beyond)
    throw NumericalError("contact stage: a pair beyond the contact law's range came into contact (its history would "
                         "be lost); the law's range() must cover every gap at which it starts a contact");
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

// The contact stage of a step, shared by every hydrodynamic model (Simulation): neighbour list
// (rebuilt on its skin criterion), the pairs within the interaction range with their Lees-Edwards geometry, their
// contact histories, the contact and surface forces of the shared contact module, the overlap check, and after the
// move the histories stored back (docs/architecture.md section 2, run-time flow).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/box.hpp"
#include "core/particles.hpp"
#include "dem/contact/contact_law.hpp"
#include "dem/contact_history.hpp"
#include "dem/integrate/time_step_control.hpp"
#include "dem/pair_forces.hpp"
#include "dem/verlet_list.hpp"

namespace suspend {

class ContactStage {
 public:
  ContactStage() = default;
  // range: the largest surface gap at which a pair interacts (contacts, surface forces, lubrication); skin of the
  // neighbour list; the particles' radii set the history bound; `stored` restores a checkpoint's histories.
  ContactStage(double range, double skin, const Particles& p, const std::vector<ContactHistory::Entry>& stored);

  // Pairs, histories and forces for the current configuration. Contacts see the velocities in p (the last step's),
  // the image of j across a sheared face moving at u_j - y_images image_velocity x, and integrate their springs
  // over last_dt. With `stiffness`, also each pair's tangent stiffnesses (implicit contacts). Returns a message when
  // an overlap exceeds max_overlap (the caller stops the run with it), else nothing.
  std::optional<std::string> evaluate(const Particles& p, const Box& box, double image_velocity, const ContactLaw& law,
                                      double last_dt, bool stiffness, double max_overlap);
  // After the move: the pair histories go back to the per-particle store.
  void store_histories() { history_.scatter(history_pairs_, pair_history_); }
  void record_motion(const std::vector<Vec3>& nonaffine, double strain_change) {
    list_.record_motion(nonaffine, strain_change);
  }

  std::vector<ContactHistory::Entry> histories() const { return history_.entries(); }
  const std::vector<ActivePair>& pairs() const { return active_; }
  const PairSums& sums() const { return sums_; }
  const std::vector<ContactStiffness>& stiffness() const { return stiffness_; }
  // Force on j of each pair (same order as pairs()); the engines add the implicit contact changes.
  const std::vector<Vec3>& pair_forces() const { return pair_force_; }
  ContactRecords records() const { return {records_, &history_slot_}; }
  // The implicit contact step's change of pair k's contact force on j (normal and tangential parts by the pair's
  // normal), added to its force and record.
  void add_contact_change(std::size_t k, const Vec3& change_on_j) {
    pair_force_[k] += change_on_j;
    const std::int32_t slot = history_slot_[k];  // a pair with a contact stiffness is within the law's range
    if (slot < 0) return;
    const Vec3 n = active_[k].geometry().n;
    const Vec3 normal = n.dot(change_on_j) * n;
    records_[slot].normal += normal;
    records_[slot].tangential += change_on_j - normal;
  }
  const VerletList& neighbours() const { return list_; }
  double range() const { return range_; }

 private:
  double range_ = 0.0;
  VerletList list_;
  ContactHistory history_;
  std::vector<ActivePair> active_;
  // Histories only for the pairs that can be in contact (within the contact law's range, or in contact before):
  // each active pair's slot in pair_history_ (-1: none), and the slotted pairs' (i, j) for the store.
  std::vector<std::int32_t> history_slot_;
  std::vector<NeighbourPair> history_pairs_;
  std::vector<PairHistory> pair_history_;
  std::vector<Vec3> pair_force_;
  std::vector<ContactStiffness> stiffness_;
  std::vector<ContactRecord> records_;  // per history slot
  PairSums sums_;
  std::vector<PairSums> scratch_;
};

// The speed |U - U_inf| that the displacement bound applies to, U_inf(x) = velocity(x) of the caller's flow: the
// fastest of every `fastest_of` particles (bounding_speed, time_step_control.hpp); `speeds` is scratch.
template <class Flow>
double nonaffine_bounding_speed(const Particles& p, const Flow& flow, int fastest_of, std::vector<double>& speeds) {
  speeds.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) speeds[i] = (p.velocity[i] - flow.velocity(p.position[i])).norm();
  return bounding_speed(speeds, fastest_of);
}

}  // namespace suspend

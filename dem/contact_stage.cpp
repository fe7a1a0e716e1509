#include "dem/contact_stage.hpp"

#include <algorithm>
#include <sstream>

#include "core/capacity.hpp"

namespace suspend {

ContactStage::ContactStage(double range, double skin, const Particles& p,
                           const std::vector<ContactHistory::Entry>& stored)
    : range_(range), list_(range, skin) {
  const auto [a_min, a_max] = std::minmax_element(p.radius.begin(), p.radius.end());
  history_ = ContactHistory(p.size(), ContactHistory::capacity_for(*a_min, *a_max));
  history_.restore(stored);
}

std::optional<std::string> ContactStage::evaluate(const Particles& p, const Box& box, double image_velocity,
                                                  const ContactLaw& law, double last_dt, bool stiffness,
                                                  double max_overlap) {
  list_.update(p.position, p.radius, box);
  compact_active_pairs(list_.pairs(), p, box, range_, active_);
  // A history slot for each pair the contact law can touch: within its range, or stored (a bond that persists).
  const double reach = contact_range(law);
  resize_with_headroom(history_slot_, active_.size());
  std::int32_t slots = 0;
  for (std::size_t k = 0; k < active_.size(); ++k) {
    const ActivePair& pr = active_[k];
    const bool near = pr.gap() <= reach || history_.contains(pr.i, pr.j);
    history_slot_[k] = near ? slots++ : -1;
  }
  resize_with_headroom(history_pairs_, static_cast<std::size_t>(slots));
  for (std::size_t k = 0; k < active_.size(); ++k)
    if (history_slot_[k] >= 0) history_pairs_[static_cast<std::size_t>(history_slot_[k])] = {active_[k].i, active_[k].j};
  resize_with_headroom(pair_history_, static_cast<std::size_t>(slots));
  history_.gather(history_pairs_, pair_history_);
  with_law(law, [&](const auto& l) {
    accumulate_pair_forces(active_, p, image_velocity, l, last_dt, pair_history_, sums_, pair_force_, scratch_,
                           stiffness ? &stiffness_ : nullptr, &records_, &history_slot_);
  });
  if (!(sums_.max_overlap > max_overlap)) return std::nullopt;
  std::ostringstream s;
  s << "overlap " << sums_.max_overlap << " a_1 between particles " << sums_.max_overlap_i << " and "
    << sums_.max_overlap_j << " exceeds the bound " << max_overlap
    << " (run.max_overlap x smallest radius); reduce the time step or stiffen the contacts";
  return s.str();
}

}  // namespace suspend

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
  resize_with_headroom(active_index_, active_.size());
  for (std::size_t k = 0; k < active_.size(); ++k) active_index_[k] = {active_[k].i, active_[k].j};
  resize_with_headroom(pair_history_, active_.size());
  history_.gather(active_index_, pair_history_);
  with_law(law, [&](const auto& l) {
    accumulate_pair_forces(active_, p, image_velocity, l, last_dt, pair_history_, sums_, pair_force_, scratch_,
                           stiffness ? &stiffness_ : nullptr, &records_);
  });
  if (!(sums_.max_overlap > max_overlap)) return std::nullopt;
  std::ostringstream s;
  s << "overlap " << sums_.max_overlap << " a_1 between particles " << sums_.max_overlap_i << " and "
    << sums_.max_overlap_j << " exceeds the bound " << max_overlap
    << " (run.max_overlap x smallest radius); reduce the time step or stiffen the contacts";
  return s.str();
}

}  // namespace suspend

#include "dem/verlet_list.hpp"

#include <algorithm>
#include <cmath>

namespace suspend {

bool VerletList::update(const std::vector<Vec3>& position, const std::vector<double>& radius, const Box& box,
                        bool force) {
  if (valid_ && !force && drift_.size() == position.size()) {
    double max1 = 0.0, max2 = 0.0;  // the two largest drifts bound any pair's relative drift
    for (const Vec3& d : drift_) {
      const double m = d.norm();
      if (m > max1) {
        max2 = max1;
        max1 = m;
      } else if (m > max2) {
        max2 = m;
      }
    }
    if (max1 + max2 + std::abs(strain_since_build_) * reach_ < skin_) return false;
  }
  search_.find_pairs(position, radius, box, gap_ + skin_, pairs_);
  const double a_max = radius.empty() ? 0.0 : *std::max_element(radius.begin(), radius.end());
  reach_ = 2.0 * a_max + gap_ + skin_;
  drift_.assign(position.size(), Vec3::Zero());
  strain_since_build_ = 0.0;
  valid_ = true;
  ++builds_;
  return true;
}

void VerletList::record_motion(const std::vector<Vec3>& nonaffine_displacement, double strain_increment) {
  for (std::size_t i = 0; i < drift_.size() && i < nonaffine_displacement.size(); ++i)
    drift_[i] += nonaffine_displacement[i];
  strain_since_build_ += strain_increment;
}

}  // namespace suspend

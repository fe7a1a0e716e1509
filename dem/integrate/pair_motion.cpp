#include "dem/integrate/pair_motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "dem/contact/pair_geometry.hpp"
#include "dem/integrate/time_step_control.hpp"

namespace suspend {

double pair_motion_rate(const std::vector<ActivePair>& pairs, const Particles& p, double image_velocity,
                        const ContactRecords& records, const PairMotionLimits& limits, std::size_t rank,
                        KthLargest* ranking) {
  const bool ranked = rank > 1 && ranking != nullptr;
  if (ranked) ranking->reset(rank);
  double rate = 0.0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ActivePair& pr = pairs[k];
    const PairGeometry& g = pr.geometry();
    const RelativeMotion m{p.velocity[pr.i], p.velocity[pr.j] - Vec3(pr.y_images * image_velocity, 0.0, 0.0),
                           p.angular_velocity[pr.i], p.angular_velocity[pr.j]};
    const double normal = std::abs((m.u_j - m.u_i).dot(g.n));
    double pair_rate;
    if (records.contact(k)) {
      const Vec3 u_c = m.contact_velocity(g);
      const double slip = (u_c - u_c.dot(g.n) * g.n).norm();
      pair_rate = std::max(normal / limits.contact_displacement, slip / limits.slip);
    } else {
      const double distance = std::max(g.gap() - limits.range, 0.0);
      pair_rate = normal / (limits.contact_displacement + limits.gap_change * distance);
    }
    if (ranked)
      ranking->add(pair_rate);
    else
      rate = std::max(rate, pair_rate);
  }
  return ranked ? ranking->value() : rate;
}

}  // namespace suspend

#include "dem/integrate/pair_motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "dem/contact/pair_geometry.hpp"
#include "dem/integrate/time_step_control.hpp"

namespace suspend {

double pair_motion_rate(const std::vector<ActivePair>& pairs, const Particles& p, double image_velocity,
                        const ContactRecords& records, const PairMotionLimits& limits, std::size_t rank,
                        KthLargest* ranking, StepLimit* limit) {
  const bool ranked = rank > 1 && ranking != nullptr;
  if (ranked) ranking->reset(rank);
  double rate = 0.0;
  StepLimit rate_limit = StepLimit::approach;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ActivePair& pr = pairs[k];
    const PairGeometry& g = pr.geometry();
    const RelativeMotion m{p.velocity[pr.i], p.velocity[pr.j] - Vec3(pr.y_images * image_velocity, 0.0, 0.0),
                           p.angular_velocity[pr.i], p.angular_velocity[pr.j]};
    const double normal = std::abs((m.u_j - m.u_i).dot(g.n));
    double pair_rate;
    StepLimit kind = StepLimit::approach;
    if (records.contact(k)) {
      const Vec3 u_c = m.contact_velocity(g);
      const double normal_rate = normal / limits.contact_displacement;
      const double slip_rate = (u_c - u_c.dot(g.n) * g.n).norm() / limits.slip;
      kind = slip_rate > normal_rate ? StepLimit::slip : StepLimit::contact_normal;
      pair_rate = std::max(normal_rate, slip_rate);
    } else {
      const double distance = std::max(g.gap() - limits.range, 0.0);
      pair_rate = normal / (limits.contact_displacement + limits.gap_change * distance);
    }
    if (ranked) {
      ranking->add(pair_rate, static_cast<int>(kind));
    } else if (pair_rate > rate) {
      rate = pair_rate;
      rate_limit = kind;
    }
  }
  if (ranked) {
    rate = ranking->value();
    if (ranking->tag() >= 0) rate_limit = static_cast<StepLimit>(ranking->tag());
  }
  if (limit && rate > 0.0) *limit = rate_limit;
  return rate;
}

}  // namespace suspend

#include "dem/pair_forces.hpp"

namespace suspend {

void compact_active_pairs(const std::vector<NeighbourPair>& list, const Particles& p, const Box& box,
                          double interaction_gap, std::vector<ActivePair>& active) {
  active.clear();
  for (const NeighbourPair& pr : list) {
    const MinimumImage m = box.minimum_image(p.position[pr.i], p.position[pr.j]);
    const double reach = p.radius[pr.i] + p.radius[pr.j] + interaction_gap;
    if (m.d.squaredNorm() >= reach * reach) continue;
    active.push_back({pr.i, pr.j, m.y_images, PairGeometry::from(m.d, p.radius[pr.i], p.radius[pr.j])});
  }
}

}  // namespace suspend

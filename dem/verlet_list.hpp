// Neighbour list with a skin (Verlet list) on top of the cell-list search.
// Under shear every particle is advected, so the rebuild criterion uses the NON-AFFINE displacement since the last
// build plus the affine shear of the closest pairs: a pair within reach r_c can close by at most
//   |dx_i^na| + |dx_j^na| + (strain since build) * r_c,
// so the list stays complete while 2 max|dx^na| + dstrain * r_c < skin.
// Results never depend on when the list was rebuilt: drivers filter pairs by their exact interaction range.
#pragma once
#include <vector>

#include "dem/neighbour_search.hpp"

namespace suspend {

class VerletList {
 public:
  VerletList() = default;
  VerletList(double interaction_gap, double skin) : gap_(interaction_gap), skin_(skin) {}

  // Rebuilds if needed (or if forced); returns true if it did.
  bool update(const std::vector<Vec3>& position, const std::vector<double>& radius, const Box& box,
              bool force = false);
  // Records one step of motion: the non-affine displacement of each particle and the strain increment.
  void record_motion(const std::vector<Vec3>& nonaffine_displacement, double strain_increment);

  const std::vector<NeighbourPair>& pairs() const { return pairs_; }
  long builds() const { return builds_; }
  double interaction_gap() const { return gap_; }
  double skin() const { return skin_; }

 private:
  double gap_ = 0.0, skin_ = 0.5;
  double reach_ = 0.0;  // largest centre distance of an interacting pair
  CellListSearch search_;
  std::vector<NeighbourPair> pairs_;
  std::vector<Vec3> drift_;  // accumulated non-affine displacement since the last build
  double strain_since_build_ = 0.0;
  bool valid_ = false;
  long builds_ = 0;
};

}  // namespace suspend

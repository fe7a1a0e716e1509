// The step bound of the overdamped step from the relative motion of the interacting pairs (run.time_step.bound =
// pairs, the default; docs/overdamped.md section 4c). Forces depend on positions only through the pairs' gaps and
// contact stretches, so a step is accurate when no pair's gap or contact changes much in it, however fast whole
// groups of particles move together. Per active pair (the contact stage's list, Lees-Edwards image velocities):
//   in contact (the contact law exerts a normal force):
//       |(U_j - U_i).n| dt <= contact_displacement   (a tenth of the law's range, a few compliance lengths)
//       |slip at the contact point| dt <= slip          (the tangential spring's path, frame invariant)
//   out of contact:
//       |(U_j - U_i).n| dt <= contact_displacement + gap_change x (gap - range),
//     so an approaching pair closes at most a fraction gap_change of its distance to contact per step (the
//     lubrication resistance ~ 1/gap changes by about as much) and enters the contact range by at most what a
//     contact may move.
// The caller adds the particle bound (largest non-affine displacement) and the strain increment.
// Units: lengths a_1, velocities gammadot_ref a_1, times 1/gammadot_ref.
#pragma once
#include <cstddef>
#include <vector>

#include "core/particles.hpp"
#include "dem/integrate/step_limit.hpp"
#include "dem/pair_forces.hpp"

namespace suspend {

class KthLargest;  // time_step_control.hpp

struct PairMotionLimits {
  double contact_displacement;  // a contact's normal displacement per step (a_1), > 0
  double slip;                  // a contact's tangential slip per step (a_1), > 0
  double range;                 // the contact law's range (Hertz: h_r; 0 for laws acting on overlap)
  double gap_change;            // the fraction of its distance to contact a pair may close per step, > 0
};

// The rank-th largest over pairs (the largest for rank 1) of (relative speed / allowed displacement): the step must
// be at most its inverse (0: no pair moves). image_velocity: the Lees-Edwards velocity of the image of j per y image
// (gammadot L_y); records: the contact stage's per-pair records (which pairs are in contact), same order as pairs;
// ranking: kept by the caller for rank > 1 (time_step_control.hpp, bound_rank); `limit`, if given, receives the
// kind of bound of the pair that sets the rate (contact_normal, slip or approach; unchanged if no pair moves).
double pair_motion_rate(const std::vector<ActivePair>& pairs, const Particles& p, double image_velocity,
                        const ContactRecords& records, const PairMotionLimits& limits,
                        std::size_t rank = 1, KthLargest* ranking = nullptr, StepLimit* limit = nullptr);

}  // namespace suspend

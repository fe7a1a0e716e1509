// Time-step control of the overdamped step, shared by the pairwise engine and the FCM coupling (docs/overdamped.md;
// docs/overdamped.md). Units: time in 1/gammadot_ref, lengths in a_1.
//
// Adaptive mode bounds dt by
//  * the strain increment: |gammadot| dt <= max;
//  * the non-affine displacement of the particles: |U - U_inf| dt <= max_displacement for the fastest of every
//    `fastest_of` particles (the k-th fastest, k = N / fastest_of, at least 1; bounding_speed()). The fastest of N is
//    an extreme value that grows with N (sqrt(ln N) for Gaussian tails), so a bound on it alone makes the step of a
//    larger box shorter at the same physics; the k-th fastest is a quantile and does not. Below 2 fastest_of
//    particles it is the fastest of all, as before this rule; fastest_of = 0: the fastest of all at any N;
//  * bound = pairs (default): the relative motion of the interacting pairs (pair_motion.hpp): a contact's normal
//    displacement at most the contact displacement below, its slip at most max_displacement, and an approaching
//    pair closes at most a fraction gap_change of its distance to contact; for all but the fastest of every
//    `fastest_of` particles' pairs (the k-th fastest pair, the same k as for the particles), for the same reason.
//    bound = particles (the rule before issue 35): every particle's non-affine displacement at most the contact
//    displacement, which is what a pair in contact needs, so the fastest particle anywhere sets the step for all;
//  * the contact displacement: max_displacement, for a law with a finite contact range such as the Hertz roughness
//    layer h_r at most a tenth of that range (so a pair cannot cross the layer in a step), and with implicit
//    contacts at most `displacement_per_compliance` mean contact compliance lengths (F_n / (dF_n/d delta), the mean
//    overlap of linear springs): with steps much longer than the overlaps a force chain's contacts open and close
//    every step (each closing is an explicit, unresolved collision) and lose their friction history;
//  * explicit contacts: the fastest contact relaxation, dt <= stability x 6 pi eta a_min / k (k: stiffness_scale);
//  * implicit contacts (implicit_contacts.hpp): no stability bound, the stiff modes are unconditionally stable. The
//    step is taken before its velocities are known, from the previous step's velocities and this step's contacts,
//    and may grow by at most a factor `growth` per step; the first step of a run uses the explicit bound.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "dem/contact/contact_law.hpp"
#include "dem/integrate/step_limit.hpp"

namespace suspend {

struct TimeStepParams {
  enum class Mode { fixed, adaptive };
  Mode mode = Mode::adaptive;
  double fixed = 1.0e-3;             // time step when mode == fixed (1/gammadot)
  double max_displacement = 2.0e-3;  // adaptive: largest non-affine displacement per step (a_1)
  double max = 1.0e-2;               // adaptive: largest strain increment per step, gammadot dt
  double stability = 0.2;            // dt <= stability * (fastest relaxation or oscillation time)
  bool implicit_contacts = false;    // overdamped: backward-Euler contact springs (implicit_contacts.hpp)
  double growth = 1.5;               // implicit contacts: largest ratio of one step to the last
  double displacement_per_compliance = 4.0;  // implicit contacts: displacement bound in mean compliance lengths
  // Implicit contacts: the compliance bound never below this (a_1). Where the flow stops (the turning points of an
  // oscillation) the contacts relax and their compliance goes to zero, and the step with it; 0: no floor.
  double min_displacement = 0.0;
  enum class Bound { pairs, particles };
  Bound bound = Bound::pairs;  // adaptive: what the contact displacement bounds (see above)
  double gap_change = 0.1;     // bound = pairs: fraction of its distance to contact a pair may close per step
  int fastest_of = 500;        // adaptive: max_displacement bounds the fastest of every fastest_of particles; 0: of all
  void validate() const {
    if (mode == Mode::fixed && !(fixed > 0.0)) throw InputError("run.time_step.fixed must be > 0");
    if (!(max_displacement > 0.0)) throw InputError("run.time_step.max_displacement must be > 0");
    if (!(max > 0.0)) throw InputError("run.time_step.max must be > 0");
    if (!(growth > 1.0)) throw InputError("run.time_step.growth must be > 1");
    if (!(displacement_per_compliance > 0.0))
      throw InputError("run.time_step.displacement_per_compliance must be > 0");
    if (!(min_displacement >= 0.0 && min_displacement <= max_displacement))
      throw InputError("run.time_step.min_displacement must lie in [0, max_displacement]");
    if (!(gap_change > 0.0 && gap_change <= 1.0)) throw InputError("run.time_step.gap_change must lie in (0, 1]");
    if (fastest_of < 0) throw InputError("run.time_step.fastest_of must be >= 0");
  }
};

// The rank the motion bounds apply to: the fastest of every fastest_of particles, i.e. the k-th fastest particle and
// the k-th fastest pair, k = N / fastest_of, at least 1 (1 when fastest_of is 0).
inline std::size_t bound_rank(std::size_t particles, int fastest_of) {
  return fastest_of > 0 ? std::max<std::size_t>(1, particles / static_cast<std::size_t>(fastest_of)) : 1;
}

// The k-th largest of `values` (k >= 1; 0 if empty); reorders them.
inline double kth_largest(std::vector<double>& values, std::size_t k) {
  if (values.empty()) return 0.0;
  if (k <= 1) return *std::max_element(values.begin(), values.end());
  const auto kth = values.begin() + static_cast<std::ptrdiff_t>(std::min(k, values.size()) - 1);
  std::nth_element(values.begin(), kth, values.end(), std::greater<>());
  return *kth;
}

// The k-th largest of a stream of values (kth_largest without the values: the k largest seen, in a min-heap), so
// that ranking the pairs costs k numbers instead of one per pair, each with a tag (what kind of value it is). Fewer
// than k values: the smallest; none: 0 (tag -1).
class KthLargest {
 public:
  void reset(std::size_t k) {
    k_ = std::max<std::size_t>(k, 1);
    heap_.clear();
  }
  void add(double v, int tag = 0) {
    if (heap_.size() < k_) {
      heap_.push_back({v, tag});
      std::push_heap(heap_.begin(), heap_.end(), later);
    } else if (v > heap_.front().value) {
      std::pop_heap(heap_.begin(), heap_.end(), later);
      heap_.back() = {v, tag};
      std::push_heap(heap_.begin(), heap_.end(), later);
    }
  }
  double value() const { return heap_.empty() ? 0.0 : heap_.front().value; }
  int tag() const { return heap_.empty() ? -1 : heap_.front().tag; }

 private:
  struct Tagged {
    double value;
    int tag;
  };
  static bool later(const Tagged& a, const Tagged& b) { return a.value > b.value; }
  std::size_t k_ = 1;
  std::vector<Tagged> heap_;
};

// The speed the displacement bound applies to (see above): the k-th largest of the particles' `speeds`, k =
// bound_rank. Reorders `speeds`.
inline double bounding_speed(std::vector<double>& speeds, int fastest_of) {
  return kth_largest(speeds, bound_rank(speeds.size(), fastest_of));
}

// The contact law's own range (no surface forces): the Hertz roughness height, 0 for laws acting on overlap.
inline double contact_range(const ContactLaw& law) {
  return std::visit([](const auto& l) { return l.contact_range(); }, law);
}

// The most steps a run may need to reach run.strain: more is refused at check time (io/case.cpp) and stops a run
// whose step collapsed (io/runner.cpp).
inline constexpr double max_run_steps = 1e9;

// Explicit contacts: the fastest contact relaxation bounds the step, dt <= stability x 6 pi eta a_min / k.
inline double explicit_contact_time_step(const TimeStepParams& ts, const ContactLaw& law, double a_min) {
  return ts.stability * 6.0 * std::numbers::pi * a_min / stiffness_scale(law);
}

// The normal displacement a contact may take in one step (a_1): max_displacement, at most a tenth of the law's range,
// and with implicit contacts at most displacement_per_compliance x `compliance` (the mean contact compliance length,
// PairSums::mean_compliance; 0 without contacts), floored at min_displacement.
inline double contact_displacement(const TimeStepParams& ts, const ContactLaw& law, double compliance) {
  double displacement = ts.max_displacement;
  const double range = contact_range(law);
  if (range > 0.0) displacement = std::min(displacement, 0.1 * range);
  if (ts.implicit_contacts && compliance > 0.0)
    displacement = std::max(std::min(displacement, ts.displacement_per_compliance * compliance), ts.min_displacement);
  return displacement;
}

// The pair bound of the overdamped step: pair_motion_rate() and the kind of the pair that sets it.
struct PairBound {
  double rate = 0.0;                        // 1 / the longest step the pairs allow; 0: no pair moves
  StepLimit limit = StepLimit::approach;    // contact_normal, slip or approach
};

// Adaptive overdamped step for shear rate `rate`, largest non-affine speed `max_speed` and, with bound = pairs,
// `pair` from pair_motion_rate() with the contact displacement above (both of this step for explicit contacts, of
// the last one for implicit contacts, whose step precedes the solve); `compliance`: the mean contact compliance
// length. `limit`, if given, receives the bound that set the step (the first of equal ones in the order above).
inline double overdamped_time_step(const TimeStepParams& ts, const ContactLaw& law, double rate, double max_speed,
                                   double a_min, double last_dt, double compliance = 0.0, PairBound pair = {},
                                   StepLimit* limit = nullptr) {
  StepBound step{ts.fixed, StepLimit::fixed};
  if (ts.mode == TimeStepParams::Mode::adaptive) {
    step = {std::abs(rate) > 0.0 ? ts.max / std::abs(rate) : ts.max, StepLimit::strain};
    const bool pairs = ts.bound == TimeStepParams::Bound::pairs;
    const double displacement = pairs ? ts.max_displacement : contact_displacement(ts, law, compliance);
    if (max_speed > 0.0) step.at_most(displacement / max_speed, StepLimit::particles);
    if (pairs && pair.rate > 0.0) step.at_most(1.0 / pair.rate, pair.limit);
    if (ts.implicit_contacts && last_dt > 0.0)
      step.at_most(ts.growth * last_dt, StepLimit::growth);
    else
      step.at_most(explicit_contact_time_step(ts, law, a_min), StepLimit::contact_stiffness);
  }
  if (limit) *limit = step.limit;
  return step.dt;
}

}  // namespace suspend

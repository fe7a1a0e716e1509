// What set the length of a step: the smallest of the adaptive bounds of time_step_control.hpp (or the fixed step,
// or the flow's own events). `suspend run` prints the share of the steps each one set, so that a user sees which
// bound to loosen or to tighten (docs/overdamped.md section 4c).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace suspend {

enum class StepLimit {
  strain,            // the strain increment run.time_step.max
  particles,         // a particle's non-affine displacement (max_displacement; with bound = particles the contact one)
  contact_normal,    // a contact's normal displacement (bound = pairs)
  slip,              // a contact's slip (bound = pairs: max_displacement)
  approach,          // an approaching pair's closing (bound = pairs: gap_change)
  contact_stiffness, // explicit contacts: the stability of the fastest contact relaxation (inertial: oscillation)
  growth,            // implicit contacts: the largest ratio of one step to the last
  flow,              // the flow's own step (an oscillation's period, a protocol's stage) or an output event
  fixed,             // run.time_step.mode = fixed
  count
};

inline const char* step_limit_name(StepLimit limit) {
  static constexpr std::array<const char*, static_cast<std::size_t>(StepLimit::count)> names = {
      "strain", "particles", "contact_normal", "slip", "approach", "contact_stiffness", "growth", "flow", "fixed"};
  return names[static_cast<std::size_t>(limit)];
}

// A step and what set it, shortened bound by bound (`at_most`); the first of equal bounds keeps it.
struct StepBound {
  double dt = 0.0;
  StepLimit limit = StepLimit::fixed;
  void at_most(double candidate, StepLimit by) {
    if (candidate < dt) {
      dt = candidate;
      limit = by;
    }
  }
};

// Steps counted by what set them.
class StepLimitCounts {
 public:
  void add(StepLimit limit) { ++counts_[static_cast<std::size_t>(limit)]; }
  std::int64_t operator[](StepLimit limit) const { return counts_[static_cast<std::size_t>(limit)]; }
  std::int64_t total() const {
    std::int64_t t = 0;
    for (std::int64_t c : counts_) t += c;
    return t;
  }
  // "slip 80%, approach 12%, ..." by share, largest first, leaving out bounds that set no step; "" without steps.
  std::string shares() const;

 private:
  std::array<std::int64_t, static_cast<std::size_t>(StepLimit::count)> counts_{};
};

}  // namespace suspend

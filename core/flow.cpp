#include "core/flow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.hpp"

namespace suspend {

namespace {
constexpr double infinity = std::numeric_limits<double>::infinity();
}

// The first reversal strain not yet passed. A step ends exactly on a reversal strain (next_reversal), after which
// it counts as passed: the tolerance absorbs the round-off of landing on it.
std::vector<double>::const_iterator Flow::first_reversal_ahead(double accumulated_strain) const {
  return std::upper_bound(reverse_at.begin(), reverse_at.end(), accumulated_strain * (1.0 + 1e-12));
}

void Flow::validate() const {
  if (!std::isfinite(shear_rate)) throw InputError("flow.shear_rate must be finite");
  if (control == FlowControl::stress && !std::isfinite(shear_stress))
    throw InputError("flow.shear_stress must be finite");
  if (!std::isfinite(wave_amplitude)) throw InputError("flow.amplitude must be finite");
  if (wave_amplitude != 0.0 && wave_periods < 1)
    throw InputError("flow.periods must be >= 1 for a wavy shear (flow.amplitude != 0)");
  if (oscillatory()) {
    if (!(angular_frequency > 0.0 && std::isfinite(angular_frequency)))
      throw InputError("flow.angular_frequency must be > 0 for flow.type = oscillatory");
    if (control == FlowControl::rate && !(strain_amplitude > 0.0 && std::isfinite(strain_amplitude)))
      throw InputError("flow.strain_amplitude must be > 0 for flow.type = oscillatory");
    if (control == FlowControl::stress && !(stress_amplitude > 0.0 && std::isfinite(stress_amplitude)))
      throw InputError("flow.stress_amplitude must be > 0 for flow.type = oscillatory with control = stress");
    if (steps_per_cycle < 8) throw InputError("flow.steps_per_cycle must be >= 8");
  }
  if (protocol == FlowProtocol::reversal) {
    if (reverse_at.empty())
      throw InputError("flow.reverse_at: missing; give the accumulated strain(s) at which to reverse");
    for (std::size_t k = 0; k < reverse_at.size(); ++k)
      if (!(reverse_at[k] > (k ? reverse_at[k - 1] : 0.0)) || !std::isfinite(reverse_at[k]))
        throw InputError("flow.reverse_at: the strains must increase (finite, > 0, in increasing order)");
  }
  if (!steady() && wave_amplitude != 0.0)
    throw InputError("flow.type = " + protocol_name(protocol) + " is a simple shear; it has no wave amplitude");
}

double Flow::direction(double accumulated_strain) const {
  if (protocol != FlowProtocol::reversal) return 1.0;
  return (first_reversal_ahead(accumulated_strain) - reverse_at.begin()) % 2 == 0 ? 1.0 : -1.0;
}

double Flow::rate(double time, double accumulated_strain) const {
  if (oscillatory()) return strain_amplitude * angular_frequency * std::cos(angular_frequency * time);
  return direction(accumulated_strain) * shear_rate;
}

double Flow::stress(double time, double accumulated_strain) const {
  if (oscillatory()) return stress_amplitude * std::sin(angular_frequency * time);
  return direction(accumulated_strain) * shear_stress;
}

double Flow::period() const { return oscillatory() ? 2.0 * std::numbers::pi / angular_frequency : 0.0; }

double Flow::max_time_step() const { return oscillatory() ? period() / steps_per_cycle : infinity; }

double Flow::next_reversal(double accumulated_strain) const {
  if (protocol != FlowProtocol::reversal) return infinity;
  const auto it = first_reversal_ahead(accumulated_strain);
  return it == reverse_at.end() ? infinity : *it;
}

double Flow::progress_rate(double rate) const { return steady() ? rate : std::abs(rate); }

std::string protocol_name(FlowProtocol p) {
  switch (p) {
    case FlowProtocol::oscillatory: return "oscillatory";
    case FlowProtocol::reversal: return "reversal";
    default: return "steady";
  }
}

}  // namespace suspend

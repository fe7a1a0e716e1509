#include "core/flow.hpp"

#include <cmath>

#include "core/error.hpp"

namespace suspend {

double FlowProtocol::rate(const Flow& flow, double, double) const { return flow.shear_rate; }
double FlowProtocol::stress(const Flow& flow, double, double) const { return flow.shear_stress; }
double FlowProtocol::largest_target(const Flow& flow) const {
  return std::abs(flow.control == FlowControl::stress ? flow.shear_stress : flow.shear_rate);
}

std::shared_ptr<const FlowProtocol> steady_shear() {
  static const auto steady = std::make_shared<const FlowProtocol>();
  return steady;
}

void Flow::validate() const {
  if (!std::isfinite(shear_rate)) throw InputError("flow.shear_rate must be finite");
  if (control == FlowControl::stress && !std::isfinite(shear_stress))
    throw InputError("flow.shear_stress must be finite");
  if (!std::isfinite(wave_amplitude)) throw InputError("flow.amplitude must be finite");
  if (wave_amplitude != 0.0 && wave_periods < 1)
    throw InputError("flow.periods must be >= 1 for a wavy shear (flow.amplitude != 0)");
  protocol->validate(*this);
}

double Flow::progress_rate(double rate) const { return counts_signed_strain() ? rate : std::abs(rate); }

}  // namespace suspend

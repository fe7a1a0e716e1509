// Steady simple shear (flow.type simple_shear): gammadot = shear_rate, or Sigma_xy = shear_stress (or sigma_star).
// The engine's part is FlowProtocol's defaults (core/flow.hpp).
#include "io/protocols/protocol.hpp"

namespace suspend::io {

namespace {
class SimpleShear : public Protocol {};
}  // namespace

std::shared_ptr<const Protocol> simple_shear_protocol() {
  static const auto steady = std::make_shared<const SimpleShear>();
  return steady;
}

namespace protocols_read {
std::shared_ptr<const Protocol> simple_shear(ProtocolKeys& k) {
  read_steady_levels(k);
  return simple_shear_protocol();
}
}  // namespace protocols_read

}  // namespace suspend::io

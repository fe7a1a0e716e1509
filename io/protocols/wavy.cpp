// The wavy shear of paper 000 eq. 17 (flow.type wavy): U_inf = (gammadot y + U sin(k y), 0, 0), k = 2 pi n / L_y,
// steady under rate control; the shape is the flow's (dem/hydro/ambient_flow.hpp), the protocol steady.
#include "core/range.hpp"
#include "io/protocols/protocol.hpp"

namespace suspend::io {

namespace {
class Wavy : public Protocol {
 public:
  std::string name() const override { return "wavy"; }
  void write(const Flow& flow, YAML::Node& keys) const override {
    Protocol::write(flow, keys);
    keys["amplitude"] = number_node(flow.wave_amplitude);
    keys["periods"] = flow.wave_periods;
  }
};
}  // namespace

namespace protocols_read {
std::shared_ptr<const Protocol> wavy(ProtocolKeys& k) {
  read_steady_levels(k, false, "stress control is available for flow.type = simple_shear only");
  k.flow.wave_amplitude = k.keys.number("amplitude", Range{});
  k.flow.wave_periods = static_cast<int>(k.keys.integer("periods", 1, 1, 1'000'000));
  return std::make_shared<const Wavy>();
}
}  // namespace protocols_read

}  // namespace suspend::io

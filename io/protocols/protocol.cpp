#include "io/protocols/protocol.hpp"

#include "core/range.hpp"

namespace suspend::io {

void Protocol::write(const Flow& flow, YAML::Node& keys) const {
  keys["shear_rate"] = number_node(flow.shear_rate);
  if (flow.control == FlowControl::stress) keys["shear_stress"] = number_node(flow.shear_stress);
}

void refuse_stress_targets(SchemaReader& f) {
  for (const char* key : {"shear_stress", "sigma_star", "stress_amplitude"})
    if (f.has(key)) f.fail(key, "is a target of flow.control = stress; with control = rate give shear_rate only");
}

void read_stress_level(ProtocolKeys& k) {
  SchemaReader& f = k.keys;
  if (f.has("sigma_star") && f.has("shear_stress"))
    f.fail("sigma_star", "give either shear_stress or sigma_star (adhesive laws), not both");
  if (f.has("sigma_star"))
    k.sigma_star = f.number("sigma_star", Range::positive());
  else
    k.flow.shear_stress = f.number("shear_stress", Range::positive());
}

void read_stress_protocol_levels(ProtocolKeys& k) {
  k.keys.choice("control", "stress", {"stress"});
  k.flow.control = FlowControl::stress;
  k.flow.shear_rate = k.keys.number("shear_rate", 1.0, Range::positive());
  read_stress_level(k);
}

void read_steady_levels(ProtocolKeys& k, bool stress_allowed, const std::string& why) {
  SchemaReader& f = k.keys;
  Flow& fl = k.flow;
  fl.control = f.choice("control", "rate", {"rate", "stress"}) == "stress" ? FlowControl::stress : FlowControl::rate;
  fl.shear_rate = f.number("shear_rate", 1.0, Range::positive());
  if (fl.control == FlowControl::stress) {
    read_stress_level(k);
    if (!stress_allowed) f.fail("control", why);
  } else {
    refuse_stress_targets(f);
  }
}

}  // namespace suspend::io

// The flow protocols a case can name (flow.type): one line each. A new protocol is one file in this folder that
// defines its reader, plus its line here (docs/architecture.md, "Add a flow protocol").
#include "io/protocols/protocol.hpp"

namespace suspend::io {

namespace protocols_read {
ProtocolRead simple_shear, wavy, oscillatory, reversal, creep, stress_ramp;
}

const std::vector<ProtocolEntry>& protocols() {
  static const std::vector<ProtocolEntry> all = {
      {"simple_shear", protocols_read::simple_shear},
      {"wavy", protocols_read::wavy},
      {"oscillatory", protocols_read::oscillatory},
      {"reversal", protocols_read::reversal},
      {"creep", protocols_read::creep},
      {"stress_ramp", protocols_read::stress_ramp},
  };
  return all;
}

std::vector<std::string> protocol_types() {
  std::vector<std::string> names;
  for (const ProtocolEntry& e : protocols()) names.emplace_back(e.type);
  return names;
}

std::shared_ptr<const Protocol> read_protocol(const std::string& type, ProtocolKeys& k) {
  for (const ProtocolEntry& e : protocols())
    if (type == e.type) return e.read(k);
  k.keys.fail("type", "unknown protocol '" + type + "'");
}

}  // namespace suspend::io

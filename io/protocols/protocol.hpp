// A flow protocol as the input/output side sees it: the engine's FlowProtocol (core/flow.hpp) plus its entry in
// the resolved case and its block in summary.json. A protocol is one file in this folder that defines its class and
// a reader of its flow.* keys, registered by one line in registry.cpp (docs/architecture.md, "Add a flow protocol").
#pragma once
#include <yaml-cpp/yaml.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/flow.hpp"
#include "io/hdf5.hpp"
#include "io/schema_reader.hpp"
#include "io/statistics.hpp"

namespace suspend::io {

struct SummaryContext;

// What a protocol's summary block is computed from: the run file, its context, the series' progress-strain and
// shear_rate columns and the rows of the averaging window.
struct SummaryInputs {
  hid_t file;
  const SummaryContext& context;
  const std::vector<double>& strain;
  const std::vector<double>& rate;
  const std::vector<std::size_t>& window;
};

class Protocol : public FlowProtocol {
 public:
  // Its keys in the resolved case (`suspend check`, run.h5), beside flow.type and flow.control. The default
  // writes flow.shear_rate and, under stress control, flow.shear_stress.
  virtual void write(const Flow& flow, YAML::Node& keys) const;
  // What eta_r, N1, N2 and Pi are divided by, when it is neither each row's imposed rate (rate control) nor the
  // window's mean rate (stress control): an oscillation's rate amplitude.
  virtual std::optional<MeanWithError> rate_scale(const SummaryInputs&) const { return std::nullopt; }
  // Adds or replaces entries of summary.json (an oscillation's eta', a reversal's transients, a creep's J(t)).
  virtual void summarise(const SummaryInputs&, nlohmann::json&) const {}
};

// What a reader fills: the flow (control, levels, shape) and, when the stress is given as sigma* (adhesive laws,
// resolved once the contact law is read), sigma_star.
struct ProtocolKeys {
  SchemaReader& keys;  // the flow mapping; flow.type is read
  Flow& flow;
  std::optional<double>& sigma_star;
};
using ProtocolRead = std::shared_ptr<const Protocol>(ProtocolKeys&);
using ProtocolReader = ProtocolRead*;

struct ProtocolEntry {
  const char* type;  // flow.type
  ProtocolReader read;
};

// Every protocol, in the order docs/flow.md lists them (registry.cpp).
const std::vector<ProtocolEntry>& protocols();
std::vector<std::string> protocol_types();
// Reads the protocol named by flow.type with its keys (not flow.type itself); InputError names the key.
std::shared_ptr<const Protocol> read_protocol(const std::string& type, ProtocolKeys& k);
// Steady simple shear at the flow's levels (a Case nobody read).
std::shared_ptr<const Protocol> simple_shear_protocol();

// The keys of a steadily imposed flow, shared by the protocols that have them: flow.control, flow.shear_rate and,
// under stress control, flow.shear_stress or flow.sigma_star. `stress_allowed` false: control = stress is refused
// with `why`.
void read_steady_levels(ProtocolKeys& k, bool stress_allowed = true, const std::string& why = "");
// Under rate control: refuses the stress targets (shear_stress, sigma_star, stress_amplitude) naming the key.
void refuse_stress_targets(SchemaReader& keys);
// Sigma_xy's level: flow.shear_stress, or flow.sigma_star for adhesive laws (not both).
void read_stress_level(ProtocolKeys& k);
// The keys of a protocol that imposes a stress only (creep, ramp): flow.control (stress), flow.shear_rate (the first
// step's guess) and the stress level.
void read_stress_protocol_levels(ProtocolKeys& k);

}  // namespace suspend::io

// Stress ramp (flow.type stress_ramp): Sigma_xy rises linearly from initial_stress S_0 (default 0) at t = 0 to
// shear_stress S_1 at ramp_time T, then holds at S_1; steps are at most T / steps_per_ramp while it rises and one
// ends on T; series rows come at least 4 per bin of stress in time while it rises. It reads a flow curve, and the
// stress at which a sample at rest starts to flow, in one run. While the stress rises, a sample that does not move
// is not judged arrested (the target is still to change); once it holds, run.jammed applies as under steady
// stress. summary.json gains `ramp`: over `bins` equal bins of stress during the rise, the mean stress, mean shear
// rate and apparent viscosity Sigma_xy / gammadot of the rows in each bin, and `flow_onset_stress`, the first bin's
// stress whose viscosity falls below onset_viscosity (the flow curve's departure from arrest: a static yield stress
// as a ramp sees it, which depends on the ramp's rate). docs/flow.md.
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/range.hpp"
#include "io/protocols/protocol.hpp"
#include "io/run_file.hpp"
#include "io/summary.hpp"

namespace suspend::io {

namespace {
class StressRamp : public Protocol {
 public:
  double initial_stress = 0.0;  // S_0
  double ramp_time = 1.0;       // T
  int steps_per_ramp = 200;
  int bins = 20;
  double onset_viscosity = 1.0e3;

  std::string name() const override { return "stress_ramp"; }
  void validate(const Flow& flow) const override {
    if (!(flow.shear_stress > initial_stress))
      throw InputError("flow.shear_stress must exceed flow.initial_stress: a ramp rises from one to the other");
  }
  double stress(const Flow& flow, double time, double) const override {
    if (!rising(time)) return flow.shear_stress;
    return initial_stress + (flow.shear_stress - initial_stress) * (time / ramp_time);
  }
  double largest_target(const Flow& flow) const override { return flow.shear_stress; }
  double max_time_step(double time) const override { return rising(time) ? ramp_time / steps_per_ramp : never; }
  double next_event_time(double time) const override { return rising(time) ? ramp_time : never; }
  // Four rows per bin of stress while it rises, whether the sample moves or not.
  double series_time_interval(double time) const override {
    return rising(time) ? ramp_time / (4.0 * bins) : never;
  }

  void write(const Flow& flow, YAML::Node& keys) const override {
    Protocol::write(flow, keys);
    keys["initial_stress"] = number_node(initial_stress);
    keys["ramp_time"] = number_node(ramp_time);
    keys["steps_per_ramp"] = steps_per_ramp;
    keys["bins"] = bins;
    keys["onset_viscosity"] = number_node(onset_viscosity);
  }

  void summarise(const SummaryInputs& in, nlohmann::json& j) const override {
    const double s1 = in.context.flow.shear_stress, width = (s1 - initial_stress) / bins;
    const std::vector<double> t = read_series(in.file, "time"), sxy = read_series(in.file, "stress/total", 3);
    std::vector<double> sum_s(bins, 0.0), sum_rate(bins, 0.0);
    std::vector<int> rows(bins, 0);
    for (std::size_t r = 0; r < t.size(); ++r) {
      if (!rising(t[r]) || !(sxy[r] > initial_stress)) continue;
      const int b = std::min(bins - 1, static_cast<int>((sxy[r] - initial_stress) / width));
      sum_s[b] += sxy[r];
      sum_rate[b] += in.rate[r];
      ++rows[b];
    }
    nlohmann::json stress = nlohmann::json::array(), rate = nlohmann::json::array(), eta = nlohmann::json::array();
    nlohmann::json onset;  // null: the sample did not flow during the rise
    for (int b = 0; b < bins; ++b) {
      if (rows[b] == 0) continue;
      const double s = sum_s[b] / rows[b], g = sum_rate[b] / rows[b];
      stress.push_back(s);
      rate.push_back(g);
      eta.push_back(g > 0.0 ? nlohmann::json(s / g) : nlohmann::json());
      if (onset.is_null() && g > 0.0 && s / g < onset_viscosity) onset = s;
    }
    j["ramp"] = {{"initial_stress", initial_stress}, {"shear_stress", s1}, {"ramp_time", ramp_time},
                 {"stress", stress}, {"shear_rate", rate}, {"viscosity", eta}, {"flow_onset_stress", onset},
                 {"onset_viscosity", onset_viscosity}};
  }

 private:
  // Before T; the step that ends on T counts as after it.
  bool rising(double time) const { return time < ramp_time * (1.0 - 1e-12); }
};
}  // namespace

namespace protocols_read {
std::shared_ptr<const Protocol> stress_ramp(ProtocolKeys& k) {
  SchemaReader& f = k.keys;
  read_stress_protocol_levels(k);
  auto p = std::make_shared<StressRamp>();
  p->initial_stress = f.number("initial_stress", 0.0, Range::non_negative());
  p->ramp_time = f.number("ramp_time", Range::positive());
  p->steps_per_ramp = static_cast<int>(f.integer("steps_per_ramp", p->steps_per_ramp, 10, 1'000'000'000));
  p->bins = static_cast<int>(f.integer("bins", p->bins, 1, 10'000));
  p->onset_viscosity = f.number("onset_viscosity", p->onset_viscosity, Range::positive());
  return p;
}
}  // namespace protocols_read

}  // namespace suspend::io

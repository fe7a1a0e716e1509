// Step-stress creep (flow.type creep): Sigma_xy stepped to shear_stress S at step_time t_1 (default 0), from
// initial_stress S_0 (default 0) before it; a step ends on t_1. The strain gamma(t) is the series' strain column, with
// rows evenly in log(t - t_1) as well as in strain;
// summary.json gains `creep`: the compliance J(t) = (gamma(t) - gamma(t_1)) / S at about 30 times spaced evenly in
// log(t - t_1) (from rest, or from a sample arrested under S_0, the creep compliance; a sample that flowed under S_0
// keeps that flow in it), and eta_r = S / the mean shear rate of the averaging window (a flowing sample; below the
// yield stress the run arrests and ends as jammed, its `jammed` block beside `creep`). docs/flow.md.
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/range.hpp"
#include "io/protocols/protocol.hpp"
#include "io/run_file.hpp"
#include "io/summary.hpp"

namespace suspend::io {

namespace {
class Creep : public Protocol {
 public:
  double initial_stress = 0.0;  // S_0
  double step_time = 0.0;       // t_1

  std::string name() const override { return "creep"; }
  void validate(const Flow& flow) const override {
    if (flow.shear_stress == initial_stress)
      throw InputError("flow.initial_stress equals flow.shear_stress: a creep steps the stress; make them differ");
  }
  double stress(const Flow& flow, double time, double) const override {
    return before_step(time) ? initial_stress : flow.shear_stress;
  }
  double largest_target(const Flow& flow) const override { return std::max(initial_stress, flow.shear_stress); }
  double next_event_time(double time) const override { return before_step(time) ? step_time : never; }
  // Rows evenly in log(t - t_1) after the step besides those in strain (36 a decade: the interval is a quarter of
  // the decade's power of ten), so J(t) is sampled from the first steps on and through an arrest, where the strain
  // stops and writes no rows.
  double series_time_interval(double time) const override {
    const double since = time - step_time;
    if (before_step(time) || !(since > 0.0)) return never;
    return 0.25 * std::pow(10.0, std::floor(std::log10(since)));
  }

  void write(const Flow& flow, YAML::Node& keys) const override {
    Protocol::write(flow, keys);
    keys["initial_stress"] = number_node(initial_stress);
    keys["step_time"] = number_node(step_time);
  }

  void summarise(const SummaryInputs& in, nlohmann::json& j) const override {
    const double s = in.context.flow.shear_stress;
    const std::vector<double> t = read_series(in.file, "time");
    nlohmann::json c = {{"shear_stress", s}, {"initial_stress", initial_stress}, {"step_time", step_time}};
    // gamma(t_1): the row at the step (a step ends on it), else the first row.
    std::size_t first = 0;
    while (first < t.size() && before_step(t[first])) ++first;
    if (first < t.size()) {
      const double gamma_1 = in.strain[first];
      const double t_end = t.back() - t[first];
      std::vector<double> times, compliance;
      if (first + 1 < t.size()) {
        // The first row after the step, then the first row at or past each of 29 times evenly spaced in log(t - t_1)
        // up to the end.
        const double dt0 = t[first + 1] - t[first];
        const double ratio = std::pow(std::max(t_end / dt0, 1.0), 1.0 / 29.0);
        double next = dt0;
        for (std::size_t r = first + 1; r < t.size(); ++r) {
          const double dt = t[r] - t[first];
          if (dt < next * (1.0 - 1e-12) && r + 1 < t.size()) continue;
          times.push_back(dt);
          compliance.push_back((in.strain[r] - gamma_1) / s);
          while (next <= dt * (1.0 + 1e-12)) next *= ratio;
          if (ratio == 1.0) break;
        }
      }
      c["compliance"] = {{"time_since_step", times}, {"J", compliance}};
      c["strain_since_step"] = in.strain.back() - gamma_1;
      c["time_since_step"] = t_end;
    }
    std::vector<double> window_rate;
    for (std::size_t r : in.window) window_rate.push_back(in.rate[r]);
    const MeanWithError g = block_average(window_rate);
    if (!window_rate.empty() && g.mean > 0.0)
      c["eta_r"] = summary_entry({s / g.mean, s * g.sem / (g.mean * g.mean)});
    j["creep"] = c;
  }

 private:
  // Before t_1; the step that ends on t_1 counts as after it (the round-off of landing on it).
  bool before_step(double time) const { return time < step_time * (1.0 - 1e-12); }
};
}  // namespace

namespace protocols_read {
std::shared_ptr<const Protocol> creep(ProtocolKeys& k) {
  SchemaReader& f = k.keys;
  read_stress_protocol_levels(k);
  auto p = std::make_shared<Creep>();
  p->initial_stress = f.number("initial_stress", 0.0, Range::non_negative());
  p->step_time = f.number("step_time", 0.0, Range::non_negative());
  if (p->initial_stress > 0.0 && p->step_time == 0.0)
    f.fail("initial_stress", "is the stress before step_time; give step_time > 0 with it");
  return p;
}
}  // namespace protocols_read

}  // namespace suspend::io

// Oscillatory shear (flow.type oscillatory): rate control gamma(t) = gamma_0 sin(omega t), gammadot(t) =
// gamma_0 omega cos(omega t); stress control Sigma_xy(t) = Sigma_0 sin(omega t). Steps are at most a period /
// steps_per_cycle; run.strain and the windows count accumulated strain. summary.json gains `oscillatory`
// (eta', eta'', moduli, harmonics; io/oscillatory_response.hpp), its eta_r is eta', and N1, N2, Pi are divided
// by the rate amplitude (docs/flow.md).
#include <cmath>
#include <numbers>
#include <optional>

#include "core/range.hpp"
#include "core/stress.hpp"
#include "io/oscillatory_response.hpp"
#include "io/protocols/protocol.hpp"
#include "io/run_file.hpp"

namespace suspend::io {

namespace {
nlohmann::json optional_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

class Oscillatory : public Protocol {
 public:
  double strain_amplitude = 0.0;  // rate control: gamma_0
  double stress_amplitude = 0.0;  // stress control: Sigma_0
  double angular_frequency = 0.0;
  int steps_per_cycle = 400;
  bool stress_control = false;

  std::string name() const override { return "oscillatory"; }
  double rate(const Flow&, double time, double) const override {
    return strain_amplitude * angular_frequency * std::cos(angular_frequency * time);
  }
  double stress(const Flow&, double time, double) const override {
    return stress_amplitude * std::sin(angular_frequency * time);
  }
  double largest_target(const Flow&) const override {
    return stress_control ? stress_amplitude : strain_amplitude * angular_frequency;
  }
  double period() const override { return 2.0 * std::numbers::pi / angular_frequency; }
  double max_time_step(double) const override { return period() / steps_per_cycle; }
  bool counts_signed_strain() const override { return false; }

  void write(const Flow& flow, YAML::Node& keys) const override {
    if (stress_control) {
      keys["shear_rate"] = number_node(flow.shear_rate);
      keys["stress_amplitude"] = number_node(stress_amplitude);
    } else {
      keys["strain_amplitude"] = number_node(strain_amplitude);
    }
    keys["angular_frequency"] = number_node(angular_frequency);
    keys["steps_per_cycle"] = steps_per_cycle;
  }

  std::optional<MeanWithError> rate_scale(const SummaryInputs& in) const override {
    return MeanWithError{response(in, cycles_of(in), "stress/total").strain_amplitude * angular_frequency, 0.0};
  }

  void summarise(const SummaryInputs& in, nlohmann::json& j) const override {
    const Cycles w = cycles_of(in);
    const double omega = angular_frequency;
    const OscillatoryResponse total = response(in, w, "stress/total");
    nlohmann::json o;
    o["angular_frequency"] = omega;
    o["period"] = period();
    o["cycles"] = total.cycles;
    o["from_time"] = w.from_time;
    auto both = [](const OscillatoryResponse& r) {
      return nlohmann::json{
          {"eta_prime", {{"mean", optional_number(r.eta_prime.mean)}, {"sem", optional_number(r.eta_prime.sem)}}},
          {"eta_double_prime",
           {{"mean", optional_number(r.eta_double_prime.mean)}, {"sem", optional_number(r.eta_double_prime.sem)}}}};
    };
    o.update(both(total));
    o["G_prime"] = optional_number(omega * total.eta_double_prime.mean);
    o["G_double_prime"] = optional_number(omega * total.eta_prime.mean);
    o["strain_amplitude"] = optional_number(total.strain_amplitude);
    o["stress_amplitude"] = optional_number(total.stress_amplitude);
    o["harmonics"] = {{"response", stress_control ? "shear_rate" : "shear_stress"},
                      {"I3_I1", optional_number(total.harmonics[0])},
                      {"I5_I1", optional_number(total.harmonics[1])},
                      {"I7_I1", optional_number(total.harmonics[2])}};
    for (auto name : contribution_names)
      o["contributions"][std::string(name)] = both(response(in, w, "stress/" + std::string(name)));

    // N1, N2, Pi are over the rate amplitude (rate_scale); eta_r is eta'.
    j["note"] =
        "oscillatory shear: eta_r is eta' (io/oscillatory_response.hpp); N1, N2, Pi are window means divided by "
        "eta_0 times the shear-rate amplitude";
    j["eta_r"] = o["eta_prime"];
    for (auto name : contribution_names)
      j["contributions"][std::string(name)]["eta_r"] = o["contributions"][std::string(name)]["eta_prime"];
    j["oscillatory"] = o;
  }

 private:
  // The whole cycles analysed: the series' time column and the time the window starts at.
  struct Cycles {
    std::vector<double> t;
    double from_time;
  };
  Cycles cycles_of(const SummaryInputs& in) const {
    std::vector<double> t = read_series(in.file, "time");
    const double from = in.window.empty() ? (t.empty() ? 0.0 : t.back()) : t[in.window.front()];
    return {std::move(t), from};
  }
  OscillatoryResponse response(const SummaryInputs& in, const Cycles& w, const std::string& series) const {
    return oscillatory_response(w.t, read_series(in.file, series, 3), in.rate, angular_frequency, w.from_time,
                                stress_control);
  }
};
}  // namespace

namespace protocols_read {
std::shared_ptr<const Protocol> oscillatory(ProtocolKeys& k) {
  SchemaReader& f = k.keys;
  auto p = std::make_shared<Oscillatory>();
  Flow& fl = k.flow;
  fl.control = f.choice("control", "rate", {"rate", "stress"}) == "stress" ? FlowControl::stress : FlowControl::rate;
  p->stress_control = fl.control == FlowControl::stress;
  if (!p->stress_control && f.has("shear_rate"))
    f.fail("shear_rate", "an oscillation's rate is strain_amplitude x angular_frequency x cos(omega t); give those "
                         "and remove shear_rate (--set flow.shear_rate=null)");
  fl.shear_rate = f.number("shear_rate", 1.0, Range::positive());
  p->angular_frequency = f.number("angular_frequency", Range::positive());
  p->steps_per_cycle = static_cast<int>(f.integer("steps_per_cycle", p->steps_per_cycle, 8, 1'000'000'000));
  if (p->stress_control) {
    for (const char* key : {"shear_stress", "sigma_star", "strain_amplitude"})
      if (f.has(key))
        f.fail(key, "an oscillation under stress control is Sigma_xy = stress_amplitude sin(omega t); give "
                    "stress_amplitude");
    p->stress_amplitude = f.number("stress_amplitude", Range::positive());
  } else {
    refuse_stress_targets(f);
    p->strain_amplitude = f.number("strain_amplitude", Range::positive());
  }
  return p;
}
}  // namespace protocols_read

}  // namespace suspend::io

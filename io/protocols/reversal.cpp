// Shear reversal (flow.type reversal; Gadala-Maria & Acrivos 1980, cited by paper 004 section III E): steady shear
// at +-shear_rate (or +-shear_stress) whose direction flips each time the accumulated strain passes one of
// reverse_at; steps end on those strains. summary.json gains `reversals`, the transient after each.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/range.hpp"
#include "io/protocols/protocol.hpp"
#include "io/run_file.hpp"
#include "io/statistics.hpp"
#include "io/summary.hpp"

namespace suspend::io {

namespace {
class Reversal : public Protocol {
 public:
  std::vector<double> reverse_at;  // accumulated strains, increasing

  std::string name() const override { return "reversal"; }
  void validate(const Flow&) const override {
    if (reverse_at.empty())
      throw InputError("flow.reverse_at: missing; give the accumulated strain(s) at which to reverse");
    for (std::size_t k = 0; k < reverse_at.size(); ++k)
      if (!(reverse_at[k] > (k ? reverse_at[k - 1] : 0.0)) || !std::isfinite(reverse_at[k]))
        throw InputError("flow.reverse_at: the strains must increase (finite, > 0, in increasing order)");
  }
  double rate(const Flow& flow, double, double accumulated_strain) const override {
    return direction(accumulated_strain) * flow.shear_rate;
  }
  double stress(const Flow& flow, double, double accumulated_strain) const override {
    return direction(accumulated_strain) * flow.shear_stress;
  }
  double next_event_strain(double accumulated_strain) const override {
    const auto it = first_reversal_ahead(accumulated_strain);
    return it == reverse_at.end() ? never : *it;
  }
  bool counts_signed_strain() const override { return false; }

  void write(const Flow& flow, YAML::Node& keys) const override {
    Protocol::write(flow, keys);
    YAML::Node at(YAML::NodeType::Sequence);
    for (double x : reverse_at) at.push_back(number_node(x));
    keys["reverse_at"] = at;
  }

  // Each reversal's transient: the viscosity Sigma_xy / gammadot over the last strain unit before it, its minimum
  // after it and where, and its mean over the last strain unit before the next reversal or the end.
  void summarise(const SummaryInputs& in, nlohmann::json& j) const override {
    const std::vector<double>& strain = in.strain;
    const std::vector<double>& rate = in.rate;
    const std::vector<double> sxy = read_series(in.file, "stress/total", 3);
    nlohmann::json out = nlohmann::json::array();
    const std::vector<double>& at = reverse_at;
    const double end = strain.empty() ? 0.0 : strain.back();
    for (std::size_t k = 0; k < at.size() && at[k] < end; ++k) {
      const double next = k + 1 < at.size() ? std::min(at[k + 1], end) : end;
      std::vector<double> before, after;
      double eta_min = std::numeric_limits<double>::infinity(), strain_of_min = 0.0;
      for (std::size_t r = 0; r < strain.size(); ++r) {
        const double eta = sxy[r] / rate[r];
        if (strain[r] >= at[k] - 1.0 && strain[r] < at[k] * (1.0 - 1e-12)) before.push_back(eta);
        if (strain[r] > at[k] * (1.0 + 1e-12) && strain[r] <= next) {
          if (eta < eta_min) eta_min = eta, strain_of_min = strain[r] - at[k];
          if (strain[r] >= next - 1.0) after.push_back(eta);
        }
      }
      out.push_back({{"at_strain", at[k]},
                     {"eta_before", before.empty() ? nlohmann::json() : summary_entry(block_average(before, 4))},
                     {"eta_min", std::isfinite(eta_min) ? nlohmann::json(eta_min) : nlohmann::json()},
                     {"strain_of_min", strain_of_min},
                     {"eta_after", after.empty() ? nlohmann::json() : summary_entry(block_average(after, 4))},
                     {"after_to_strain", next}});
    }
    j["reversals"] = out;
  }

 private:
  // +1 before the first reversal, -1 after it, +1 after the second...
  double direction(double accumulated_strain) const {
    return (first_reversal_ahead(accumulated_strain) - reverse_at.begin()) % 2 == 0 ? 1.0 : -1.0;
  }
  // The first reversal strain not yet passed. A step ends exactly on a reversal strain (next_event_strain), after
  // which it counts as passed: the tolerance absorbs the round-off of landing on it.
  std::vector<double>::const_iterator first_reversal_ahead(double accumulated_strain) const {
    return std::upper_bound(reverse_at.begin(), reverse_at.end(), accumulated_strain * (1.0 + 1e-12));
  }
};
}  // namespace

namespace protocols_read {
std::shared_ptr<const Protocol> reversal(ProtocolKeys& k) {
  read_steady_levels(k);
  auto p = std::make_shared<Reversal>();
  p->reverse_at = k.keys.number_list("reverse_at", Range::positive());  // validate() checks the order
  return p;
}
}  // namespace protocols_read

}  // namespace suspend::io

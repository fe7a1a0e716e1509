// The imposed flow of a run as one value: what is controlled (shear rate or shear stress), how it varies in time
// (the protocol) and its spatial shape (simple shear, or the wavy shear of paper 000 eq. 17). Every hydrodynamic
// model and the runner ask it for this step's rate or stress target; none hard-codes a protocol.
//
// A protocol is an object (FlowProtocol) that owns its targets, its step limit and the events steps must end on;
// each is one file in io/protocols/ with its keys, its resolved-case entry and its summary block, registered by one
// line in io/protocols/registry.cpp (docs/flow.md, docs/architecture.md). The base class is steady shear.
// Strains: `strain` is the signed strain the Lees-Edwards cell follows; the accumulated strain is the integral of
// |gammadot| dt. Steady runs (and creep) count their length in signed strain, the others in accumulated strain
// (run.strain, outputs and averaging windows), so an oscillation of amplitude gamma_0 covers 4 gamma_0 per cycle.
// Units: rates in gammadot_ref, stresses in eta_0 gammadot_ref, time in 1/gammadot_ref.
#pragma once
#include <limits>
#include <memory>
#include <string>

#include "core/ambient_flow.hpp"

namespace suspend {

enum class FlowControl { rate, stress };

struct Flow;

class FlowProtocol {
 public:
  static constexpr double never = std::numeric_limits<double>::infinity();
  virtual ~FlowProtocol() = default;

  // Its flow.type.
  virtual std::string name() const { return "simple_shear"; }
  // Throws InputError naming the flow.* key of an impossible setting.
  virtual void validate(const Flow&) const {}
  // The imposed shear rate (rate control) and the target Sigma_xy (stress control) at this time and accumulated
  // strain; steady shear: the flow's shear_rate and shear_stress.
  virtual double rate(const Flow& flow, double time, double accumulated_strain) const;
  virtual double stress(const Flow& flow, double time, double accumulated_strain) const;
  // The largest |rate| (rate control) or |stress| (stress control) it imposes at any time.
  virtual double largest_target(const Flow& flow) const;
  // Longest time step it allows at this time (an oscillation: a fraction of the period; a ramp while it rises).
  virtual double max_time_step(double) const { return never; }
  // The first accumulated strain after `accumulated_strain`, and the first time after `time`, that a step must
  // end on (a reversal, a stress step, the end of a ramp); `never` when none. While a time event is ahead the
  // target is still to change, so a flow that stops is not judged arrested (io/run_observers.cpp).
  virtual double next_event_strain(double) const { return never; }
  virtual double next_event_time(double) const { return never; }
  // Series rows at least this often in time at this time (a ramp while it rises: rows where the strain hardly
  // moves), besides the rows by strain; `never`: rows by strain (or period) only.
  virtual double series_time_interval(double) const { return never; }
  // Period of a periodic protocol (series rows evenly in time); 0 otherwise.
  virtual double period() const { return 0.0; }
  // Whether run.strain, the averaging window and the output intervals count the signed strain (steady, creep)
  // rather than the accumulated strain.
  virtual bool counts_signed_strain() const { return true; }
};

// The protocol of a Flow nobody set: steady shear.
std::shared_ptr<const FlowProtocol> steady_shear();

struct Flow {
  FlowControl control = FlowControl::rate;
  std::shared_ptr<const FlowProtocol> protocol = steady_shear();
  double shear_rate = 1.0;      // rate control: the protocol's level; stress control: the first step's guess
  double shear_stress = 1.0;    // stress control: the protocol's level (target Sigma_xy of steady shear)
  double wave_amplitude = 0.0;  // wavy shear (paper 000 eq. 17): U (gammadot_ref a_1); 0: simple shear
  int wave_periods = 0;         // n, periods across L_y

  void validate() const;  // throws InputError naming the flow.* key

  std::string protocol_name() const { return protocol->name(); }
  bool periodic() const { return protocol->period() > 0.0; }
  bool counts_signed_strain() const { return protocol->counts_signed_strain(); }
  double rate(double time, double accumulated_strain) const { return protocol->rate(*this, time, accumulated_strain); }
  double stress(double time, double accumulated_strain) const {
    return protocol->stress(*this, time, accumulated_strain);
  }
  double max_time_step(double time) const { return protocol->max_time_step(time); }
  double next_event_strain(double accumulated_strain) const { return protocol->next_event_strain(accumulated_strain); }
  double next_event_time(double time) const { return protocol->next_event_time(time); }
  double period() const { return protocol->period(); }
  // The ambient flow at shear rate `rate` in a box of height L_y: simple shear (L = rate e_x e_y) with this flow's
  // wave. The one place a rate becomes U_inf, Omega_inf and E_inf, for every hydrodynamic model.
  AmbientFlow ambient(double rate, double box_height) const {
    return AmbientFlow::wavy_shear(rate, wave_amplitude, wave_periods, box_height);
  }
  // The rate of a run's progress strain: signed for steady shear, |gammadot| for the other protocols.
  double progress_rate(double rate) const;
};

}  // namespace suspend

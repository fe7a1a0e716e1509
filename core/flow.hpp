// The imposed flow of a run as one value: what is controlled (shear rate or shear stress), how it varies in time
// (the protocol) and its spatial shape (simple shear, or the wavy shear of paper 000 eq. 17). Every hydrodynamic
// model and the runner ask it for this step's rate or stress target; none hard-codes a protocol.
//
// Protocols (docs/flow.md):
//   steady       rate control: gammadot = shear_rate;  stress control: Sigma_xy = shear_stress
//   oscillatory  rate control: gamma(t) = gamma_0 sin(omega t), gammadot(t) = gamma_0 omega cos(omega t);
//                stress control: Sigma_xy(t) = Sigma_0 sin(omega t)
//   reversal     steady shear whose direction flips each time the accumulated strain passes one of reverse_at
//                (the shear-reversal experiment, Gadala-Maria & Acrivos 1980; paper 004 section III E cites it)
// Strains: `strain` is the signed strain the Lees-Edwards cell follows; the accumulated strain is the integral of
// |gammadot| dt. Steady runs count their length in signed strain (as they always have), the others in accumulated
// strain (run.strain, outputs and averaging windows), so an oscillation of amplitude gamma_0 covers 4 gamma_0 per
// cycle.
// Units: rates in gammadot_ref, stresses in eta_0 gammadot_ref, time in 1/gammadot_ref.
#pragma once
#include <string>
#include <vector>

namespace suspend {

enum class FlowControl { rate, stress };
enum class FlowProtocol { steady, oscillatory, reversal };

struct Flow {
  FlowControl control = FlowControl::rate;
  FlowProtocol protocol = FlowProtocol::steady;
  double shear_rate = 1.0;     // rate control: imposed (steady, reversal); stress control: the first step's guess
  double shear_stress = 1.0;   // stress control: target Sigma_xy (steady, reversal)
  double wave_amplitude = 0.0;  // wavy shear (paper 000 eq. 17): U (gammadot_ref a_1); 0: simple shear
  int wave_periods = 0;         // n, periods across L_y
  double strain_amplitude = 0.0;   // oscillatory, rate control: gamma_0
  double stress_amplitude = 0.0;   // oscillatory, stress control: Sigma_0
  double angular_frequency = 0.0;  // oscillatory: omega (gammadot_ref)
  int steps_per_cycle = 400;       // oscillatory: the time step is at most one cycle / steps_per_cycle
  std::vector<double> reverse_at;  // reversal: accumulated strains, increasing

  void validate() const;  // throws InputError naming the flow.* key

  bool steady() const { return protocol == FlowProtocol::steady; }
  bool oscillatory() const { return protocol == FlowProtocol::oscillatory; }
  // +1 before the first reversal, -1 after it, +1 after the second...
  double direction(double accumulated_strain) const;
  // The imposed shear rate (rate control) at this time and accumulated strain.
  double rate(double time, double accumulated_strain) const;
  // The target Sigma_xy (stress control) at this time and accumulated strain.
  double stress(double time, double accumulated_strain) const;
  // Longest time step the protocol allows (oscillation: a fraction of the period); infinite otherwise.
  double max_time_step() const;
  // Accumulated strain of the next reversal after `accumulated_strain` (infinite when none): steps end on it.
  double next_reversal(double accumulated_strain) const;
  // Period 2 pi / omega of the oscillation (0 for the other protocols).
  double period() const;
  // The rate of a run's progress strain: signed for steady shear, |gammadot| for the other protocols.
  double progress_rate(double shear_rate) const;

 private:
  std::vector<double>::const_iterator first_reversal_ahead(double accumulated_strain) const;
};

std::string protocol_name(FlowProtocol p);

}  // namespace suspend

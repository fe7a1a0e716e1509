// DIR/summary.json: steady-state means and standard errors of every observable (eta_r, N1, N2, Pi, total and per
// contribution) over the averaging window, read back from run.h5 so that restarted runs summarise the whole run.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "core/flow.hpp"
#include "io/hdf5.hpp"

namespace suspend::io {

struct SummaryContext {
  double phi = 0.0;
  std::size_t particles = 0;
  double average_from = 0.0;
  // Imposed shear stress: eta_r, N1, N2, Pi are divided by the mean shear rate of the window (not row by row).
  bool stress_control = false;
  // F_adh of adhesive contacts (0: none); adds sigma* = 6 pi Sigma_xy a_1^2 / F_adh and G_adh.
  double adhesion_force = 0.0;
  // The imposed flow: steady windows count the signed strain, the other protocols the accumulated strain; an
  // oscillation adds `oscillatory` (eta', eta'', harmonics; io/oscillatory_response.hpp) and reports eta_r = eta',
  // N1, N2, Pi divided by the rate amplitude; a reversal adds `reversals` (the transient after each).
  Flow flow;
};

nlohmann::json summarize(hid_t run_file, const SummaryContext& context);

}  // namespace suspend::io

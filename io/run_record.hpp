// A run's record on disk while it runs: run.h5 (series and snapshots), checkpoint.h5, run.xdmf and summary.json,
// and the state at the start of the last two steps, which a numerical failure checkpoints.
#pragma once
#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

#include "core/rng.hpp"
#include "dem/simulation.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "io/run_file.hpp"

namespace suspend::io {

// The strain a run's length, outputs and averaging window count: signed for steady shear, accumulated for the
// other protocols (core/flow.hpp).
double progress_strain(const Flow& flow, const SimulationState& st);

// The simulation's particles and contacts as run.h5 stores a snapshot.
Snapshot snapshot_of(const Simulation& sim);

class RunRecord {
 public:
  // `checkpoint_strain`: the strain of the checkpoint already on disk for this run.h5, negative when there is none.
  RunRecord(const Case& c, const Simulation& sim, RunFile file, const std::string& dir, OutputClock& clock,
            const Rng& rng, std::string fingerprint, int threads, std::chrono::steady_clock::time_point started,
            double checkpoint_strain);

  RunFile& file() { return file_; }
  const std::string& run_path() const { return run_path_; }
  const std::string& checkpoint_path() const { return checkpoint_path_; }
  double strain() const { return progress_strain(case_.simulation.flow, sim_.state()); }
  // Strain of the last complete checkpoint on disk, negative when none was written yet.
  double checkpoint_strain() const { return checkpoint_strain_; }

  // A checkpoint of the present state, with the output clock's row and snapshot counts brought up to date.
  void save();
  // Keeps the state at the start of this step (and of the one before), as a checkpoint would hold them.
  void remember_step_start();
  // After a numerical failure: checkpoints the state before the failing step (the step before this one when the
  // failure was found evaluating the state this step was given) and returns it.
  const SimulationState& save_state_before_failure(bool found_evaluating);
  // At the end: the checkpoint of the state before the last step when that step was clipped to end on run.strain
  // (continued to a longer strain, the run takes the full step there), else of the final state.
  void save_final(bool last_step_clipped);
  void finish_outputs();  // flush run.h5 and write run.xdmf
  nlohmann::json write_summary(double average_from, const nlohmann::json& extra);
  // A run that ends before run.strain (stopped, jammed, failed) still summarises what it did: from
  // run.average_from, or from half its strain when it did not get there. Returns the window's start.
  double write_partial_summary(const char* status, nlohmann::json extra);

 private:
  struct StepStart {
    SimulationState state;
    OutputClock clock;
    bool valid = false;
  };
  void save_step_start(const StepStart& s);

  const Case& case_;
  const Simulation& sim_;
  RunFile file_;
  std::string run_path_, checkpoint_path_, summary_path_, xdmf_path_;
  OutputClock& clock_;
  const Rng& rng_;
  std::string fingerprint_;
  int threads_;
  std::chrono::steady_clock::time_point started_;
  double checkpoint_strain_;
  StepStart this_step_, previous_step_;
};

}  // namespace suspend::io

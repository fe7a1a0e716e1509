// What a run does besides stepping, as observers of the run loop (io/runner.cpp): each owns one concern (series,
// snapshots, progress, the pace guard, stop signals, jamming detection, periodic checkpoints) and its trigger. The
// loop calls every observer after a step is evaluated (`evaluated`: the state's forces and stress are known, the
// step not yet taken) and after it is taken (`advanced`: an exit code ends the run). Observers run in the order
// they are listed, which is the order the outputs were always written in (results and checkpoints are unchanged).
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "dem/simulation.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "io/output_room.hpp"
#include "io/progress.hpp"
#include "io/run_record.hpp"

namespace suspend::io {

// Strains (and, for oscillation, times in units of the series interval) within this of a target count as there.
inline constexpr double strain_tolerance = 1e-9;

// First multiple of `every` strictly above `clock`.
double next_multiple(double clock, double every);

// Fires when a clock (strain or time) reaches `next`, within `tolerance`; then `next` moves to the first multiple
// of `every` above the clock. `next` is a field of the output clock, so a checkpoint carries the schedule.
class IntervalTrigger {
 public:
  IntervalTrigger(double& next, double every, double tolerance) : next_(next), every_(every), tolerance_(tolerance) {}
  bool due(double clock) const { return clock >= next_ - tolerance_; }
  void fire(double clock) { next_ = next_multiple(clock, every_); }

 private:
  double& next_;
  double every_, tolerance_;
};

// Fires on every step count that is a multiple of `every` (0: never). The step count is part of the state, so a
// checkpoint carries the schedule by itself.
class StepTrigger {
 public:
  explicit StepTrigger(long every) : every_(every) {}
  bool due(std::int64_t step) const { return every_ > 0 && step % every_ == 0; }

 private:
  long every_;
};

struct RunContext {
  const Case& c;
  Simulation& sim;
  RunRecord& record;
  OutputClock& clock;
  Progress& progress;
  int threads;
  double step_start_strain = 0.0;  // the progress strain before the step just taken
  bool quiet = false;             // no summary line at the end
  double strain() const { return record.strain(); }
  bool before_end() const { return strain() < c.run.strain - strain_tolerance; }
};

// Ends an imposed-stress run whose flow stopped: final snapshot, checkpoint, summary with its `jammed` block.
int end_jammed(RunContext& r, double rate, double over_time);

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void evaluated(RunContext&) {}
  virtual std::optional<int> advanced(RunContext&) { return std::nullopt; }
};

// One row of run.h5's series every run.output.series_every of strain (oscillation: series_per_cycle rows per
// period, evenly in time, as io/oscillatory_response.hpp integrates over them); keeps the running eta_r.
class SeriesWriter final : public RunObserver {
 public:
  explicit SeriesWriter(RunContext& r);
  void evaluated(RunContext& r) override;
  // <Sigma_xy> / <gammadot> over the rows since run.average_from, else the present value.
  double running_viscosity(const Simulation& sim) const;

 private:
  bool by_time_;
  IntervalTrigger trigger_;
  double stress_sum_ = 0.0, rate_sum_ = 0.0;
};

// A snapshot every run.output.snapshot_every of strain, and every snapshot_every_steps steps when that is set.
class SnapshotWriter final : public RunObserver {
 public:
  explicit SnapshotWriter(RunContext& r);
  void evaluated(RunContext& r) override;

 private:
  IntervalTrigger trigger_;
  StepTrigger steps_;
};

class ProgressReporter final : public RunObserver {
 public:
  explicit ProgressReporter(const SeriesWriter& series) : series_(series) {}
  void evaluated(RunContext& r) override;

 private:
  const SeriesWriter& series_;
};

// A step or rate that collapsed mid-run (the time step a case implies is checked before it starts): 1000 steps in
// a row at a pace that would need more than max_run_steps stop the run; under imposed stress a flow that stopped is
// a jammed point, also before the jamming window closes.
class PaceGuard final : public RunObserver {
 public:
  explicit PaceGuard(RunContext& r);
  std::optional<int> advanced(RunContext& r) override;

 private:
  int slow_steps_ = 0;
  double slow_start_strain_, slow_start_time_;
};

// Ctrl-C, kill, a closed terminal or pipe (install_stop_handlers): a checkpoint, a summary, the restart command.
// A signal on the step that reaches run.strain lets the run end as done: a "stopped" checkpoint at run.strain could
// not be continued.
class StopOnSignal final : public RunObserver {
 public:
  std::optional<int> advanced(RunContext& r) override;
};

// Imposed steady (or reversing) stress: jammed when the mean rate over a window of run.jammed.strain x
// run.jammed.viscosity / Sigma time stays below Sigma / run.jammed.viscosity.
class JammingDetector final : public RunObserver {
 public:
  std::optional<int> advanced(RunContext& r) override;
};

// A checkpoint every run.output.checkpoint_every of strain or checkpoint_seconds of wall time, never at run.strain
// (the end writes summary.json, then that checkpoint); stops at a checkpoint when the next interval may not fit on
// the disk.
class PeriodicCheckpoint final : public RunObserver {
 public:
  explicit PeriodicCheckpoint(RunContext& r);
  std::optional<int> advanced(RunContext& r) override;

 private:
  IntervalTrigger trigger_;
  std::chrono::steady_clock::time_point wall0_;
  OutputRoom room_;
};

// The observers of a run of case `r.c`, in the order they act.
std::vector<std::unique_ptr<RunObserver>> run_observers(RunContext& r);

}  // namespace suspend::io

#include "io/run_observers.hpp"

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "core/error.hpp"
#include "dem/integrate/time_step_control.hpp"
#include "io/runner.hpp"

namespace suspend::io {

namespace {
std::atomic<int> stop_signal{0};
extern "C" void on_stop_signal(int sig) { stop_signal.store(sig); }

// Imposed steady (or reversing) stress: a flow that stops is a jammed point, its mean rate below this one.
bool detects_jamming(const Flow& flow) { return flow.control == FlowControl::stress && !flow.periodic(); }
double jamming_rate(const Case& c) { return c.simulation.flow.shear_stress / c.run.jammed_viscosity; }

// Series rows: every series_every of strain, or series_per_cycle per period of an oscillation (in time).
double series_interval(const Case& c) {
  const Flow& flow = c.simulation.flow;
  return flow.periodic() ? flow.period() / c.run.output.series_per_cycle : c.run.output.series_every;
}
}  // namespace

// Ctrl-C, kill, a closed terminal (SIGHUP) and a closed pipe for the progress lines (`suspend run ... | head`,
// SIGPIPE) all stop the run at a checkpoint; left at their defaults, the last two killed it with run.h5 open.
void install_stop_handlers() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) std::signal(sig, on_stop_signal);
}

double next_multiple(double clock, double every) { return (std::floor(clock / every + 1e-9) + 1.0) * every; }

int end_jammed(RunContext& r, double rate, double over_time) {
  RunRecord& record = r.record;
  const double threshold = jamming_rate(r.c);
  record.file().write_snapshot(snapshot_of(r.sim));
  record.save();
  record.finish_outputs();
  r.progress.finish();
  const double from = record.write_partial_summary(
      "jammed", {{"jammed",
                  {{"mean_shear_rate", rate},
                   {"over_time", over_time},
                   {"threshold", threshold},
                   // Arrest of a state that flowed, or of one that never did (a packing arrested at once):
                   // it flowed first when it sheared by more than one jamming window before it stopped.
                   {"strain_reached", r.strain()},
                   {"flowed_first", r.strain() > r.c.run.jammed_strain}}}});
  std::fprintf(stderr,
               "jammed: the mean shear rate was %.3g over the last %.4g time units (threshold "
               "Sigma/run.jammed.viscosity = %.3g) at strain %.4g; summary.json averages from strain %.4g\n",
               rate, over_time, threshold, r.strain(), from);
  record.file().close();
  return exit_jammed;
}

SeriesWriter::SeriesWriter(RunContext& r)
    : by_time_(r.c.simulation.flow.periodic()),
      trigger_(r.clock.next_series, series_interval(r.c), strain_tolerance * (by_time_ ? series_interval(r.c) : 1.0)) {}

void SeriesWriter::evaluated(RunContext& r) {
  const Simulation& sim = r.sim;
  const double strain = r.strain();
  const double clock = by_time_ ? sim.state().time : strain;
  // A protocol's time rows: this step crossed a multiple of its interval (from the state alone, so a restart
  // writes the same rows).
  const double t = sim.state().time, every = r.c.simulation.flow.protocol->series_time_interval(t);
  const bool time_row =
      every < FlowProtocol::never && std::floor(t / every) > std::floor((t - sim.state().last_dt) / every);
  if (!trigger_.due(clock) && !time_row) return;
  SeriesRow row;
  row.step = sim.state().step;
  row.time = sim.state().time;
  row.strain = sim.state().strain;
  row.accumulated_strain = sim.state().accumulated_strain;
  row.shear_rate = sim.shear_rate();
  row.dt = sim.time_step();
  row.contacts = static_cast<double>(sim.contact_count());
  row.max_overlap = sim.max_overlap();
  row.solver_iterations = sim.solver_iterations();
  row.solver_residual = sim.solver_residual();
  row.stress = sim.stress();
  r.record.file().append(row);
  trigger_.fire(clock);
  if (strain >= r.c.run.average_from) {
    stress_sum_ += row.stress.total()(0, 1);
    rate_sum_ += row.shear_rate;
  }
}

double SeriesWriter::running_viscosity(const Simulation& sim) const {
  return rate_sum_ != 0.0 ? stress_sum_ / rate_sum_ : sim.stress().total()(0, 1) / sim.shear_rate();
}

SnapshotWriter::SnapshotWriter(RunContext& r)
    : trigger_(r.clock.next_snapshot, r.c.run.output.snapshot_every, strain_tolerance),
      steps_(r.c.run.output.snapshot_every_steps) {}

void SnapshotWriter::evaluated(RunContext& r) {
  const double strain = r.strain();
  const bool by_strain = trigger_.due(strain);
  if (!by_strain && !steps_.due(r.sim.state().step)) return;
  r.record.file().write_snapshot(snapshot_of(r.sim));
  if (by_strain) trigger_.fire(strain);
}

void ProgressReporter::evaluated(RunContext& r) {
  r.progress.update(r.strain(), r.sim.state().step, series_.running_viscosity(r.sim));
}

PaceGuard::PaceGuard(RunContext& r) : slow_start_strain_(r.strain()), slow_start_time_(r.sim.state().time) {}

std::optional<int> PaceGuard::advanced(RunContext& r) {
  constexpr int slow_steps_allowed = 1000;
  const double strain = r.strain(), end = r.c.run.strain;
  // Slow steps while the protocol's target is still to change at a known time (a ramp rising from below the
  // yield stress, a creep before its step) are what the protocol asked for.
  const bool target_to_change = r.c.simulation.flow.next_event_time(r.sim.state().time) < FlowProtocol::never;
  if (target_to_change || std::abs(strain - r.step_start_strain) * max_run_steps >= end) {
    slow_steps_ = 0;
    slow_start_strain_ = strain;
    slow_start_time_ = r.sim.state().time;
    return std::nullopt;
  }
  if (++slow_steps_ < slow_steps_allowed) return std::nullopt;
  const double over = r.sim.state().time - slow_start_time_;
  const double rate = std::abs(strain - slow_start_strain_) / over;
  if (detects_jamming(r.c.simulation.flow) && over > 0.0 && rate < jamming_rate(r.c)) return end_jammed(r, rate, over);
  std::ostringstream s;
  s << "no progress: the last " << slow_steps_ << " steps advanced the strain by "
    << std::abs(strain - slow_start_strain_) << " in all (time step " << r.sim.time_step() << ", shear rate "
    << r.sim.shear_rate() << "); at this pace run.strain = " << end << " needs more than " << max_run_steps
    << " steps";
  throw NumericalError(s.str());
}

std::optional<int> StopOnSignal::advanced(RunContext& r) {
  const int sig = stop_signal.load();
  if (!sig || !r.before_end()) return std::nullopt;
  r.record.save();
  r.record.finish_outputs();
  r.progress.finish();
  r.record.write_partial_summary("stopped", {});
  std::cerr << "stopped by signal " << sig << " at strain " << r.strain()
            << "; continue with: " << restart_command(r.c, r.record.checkpoint_path(), r.threads) << "\n";
  return 128 + sig;
}

std::optional<int> JammingDetector::advanced(RunContext& r) {
  const Flow& flow = r.c.simulation.flow;
  const double window = r.c.run.jammed_strain * r.c.run.jammed_viscosity / flow.shear_stress;
  const SimulationState& st = r.sim.state();
  // A window never spans a change of the protocol's target still to come or just made (a creep's stress step, a
  // ramp): it starts again once the target holds.
  if (flow.next_event_time(r.clock.jam_window_time) < FlowProtocol::never) {
    r.clock.jam_window_time = st.time;
    r.clock.jam_window_strain = r.strain();
    return std::nullopt;
  }
  if (st.time - r.clock.jam_window_time < window) return std::nullopt;
  if (r.strain() - r.clock.jam_window_strain < r.c.run.jammed_strain)
    return end_jammed(r, (r.strain() - r.clock.jam_window_strain) / (st.time - r.clock.jam_window_time),
                      st.time - r.clock.jam_window_time);
  r.clock.jam_window_time = st.time;
  r.clock.jam_window_strain = r.strain();
  return std::nullopt;
}

PeriodicCheckpoint::PeriodicCheckpoint(RunContext& r)
    : trigger_(r.clock.next_checkpoint, r.c.run.output.checkpoint_every, strain_tolerance),
      wall0_(std::chrono::steady_clock::now()) {}

std::optional<int> PeriodicCheckpoint::advanced(RunContext& r) {
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0_).count();
  const double strain = r.strain();
  if (!r.before_end() || !(trigger_.due(strain) || wall >= r.c.run.output.checkpoint_seconds)) return std::nullopt;
  trigger_.fire(strain);
  r.record.save();
  wall0_ = std::chrono::steady_clock::now();
  if (const std::optional<std::string> full = room_.after_checkpoint(r.record.run_path(), r.record.checkpoint_path())) {
    r.progress.finish();
    std::cerr << "error: " << *full << "; stopped at the checkpoint of strain " << strain
              << " while everything is complete; once there is room, continue with: "
              << restart_command(r.c, r.record.checkpoint_path(), r.threads) << "\n";
    return exit_output_error;
  }
  return std::nullopt;
}

std::vector<std::unique_ptr<RunObserver>> run_observers(RunContext& r) {
  std::vector<std::unique_ptr<RunObserver>> list;
  auto series = std::make_unique<SeriesWriter>(r);
  const SeriesWriter& rows = *series;
  list.push_back(std::move(series));
  list.push_back(std::make_unique<SnapshotWriter>(r));
  list.push_back(std::make_unique<ProgressReporter>(rows));
  list.push_back(std::make_unique<PaceGuard>(r));
  list.push_back(std::make_unique<StopOnSignal>());
  if (detects_jamming(r.c.simulation.flow)) list.push_back(std::make_unique<JammingDetector>());
  list.push_back(std::make_unique<PeriodicCheckpoint>(r));
  return list;
}

}  // namespace suspend::io

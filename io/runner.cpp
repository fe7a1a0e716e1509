#include "io/runner.hpp"

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/exact_tables.hpp"
#include "io/hydrodynamic_models.hpp"
#include "io/run_observers.hpp"
#include "io/run_record.hpp"
#include "io/run_start.hpp"
#include "io/schema_reader.hpp"

namespace suspend::io {

namespace fs = std::filesystem;

namespace {
// A step that leaves a non-finite position, time or strain (e.g. a fixed time step far too large) is a numerical
// failure, never a finished run.
void check_finite(const SimulationState& st) {
  if (!std::isfinite(st.time) || !std::isfinite(st.strain))
    throw NumericalError("time or strain became non-finite at step " + std::to_string(st.step) +
                         "; reduce run.time_step");
  const auto& x = st.particles.position;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!x[i].allFinite()) {
      std::ostringstream s;
      s << "position of particle " << i << " became non-finite at step " << st.step << " (strain " << st.strain
        << "); reduce run.time_step";
      throw NumericalError(s.str());
    }
}

// The last step ends on run.strain, not past it (returns true when it was shortened: that step is for the output
// only, see RunRecord::save_final); a step ends on the protocol's events (a reversal's strain, a stress step's time).
bool clip_step(Simulation& sim, const Flow& flow, double strain, double end) {
  bool clipped = false;
  const double pace = flow.progress_rate(sim.shear_rate());
  if (const double left = end - strain; pace * sim.time_step() > left) {
    sim.clip_time_step(left / pace);
    clipped = true;
  }
  if (const double left = flow.next_event_strain(sim.state().accumulated_strain) - sim.state().accumulated_strain;
      std::abs(sim.shear_rate()) * sim.time_step() > left)
    sim.clip_time_step(left / std::abs(sim.shear_rate()));
  if (const double left = flow.next_event_time(sim.state().time) - sim.state().time; sim.time_step() > left)
    sim.clip_time_step(left);
  return clipped;
}

// The run loop: evaluate, let the observers write what is due, step; every exit path leaves a checkpoint that
// continues the run and a summary of what was done.
int run_loop(RunContext& r) {
  const std::vector<std::unique_ptr<RunObserver>> observers = run_observers(r);
  RunRecord& record = r.record;
  Simulation& sim = r.sim;
  const Flow& flow = r.c.simulation.flow;
  bool last_step_clipped = false, evaluating = false;
  install_stop_handlers();
  try {
    for (;;) {
      record.remember_step_start();
      evaluating = true;
      sim.evaluate();
      evaluating = false;
      for (const auto& o : observers) o->evaluated(r);
      const double strain = r.strain();
      if (strain >= r.c.run.strain - strain_tolerance) {
        RunFile& file = record.file();
        if (file.snapshot_count() == 0 || file.snapshots().back().time < sim.state().time)
          file.write_snapshot(snapshot_of(sim));  // the final state, also when run.strain is between snapshots
        break;
      }
      last_step_clipped = clip_step(sim, flow, strain, r.c.run.strain);
      r.step_start_strain = strain;
      sim.advance();
      check_finite(sim.state());
      for (const auto& o : observers)
        if (const std::optional<int> code = o->advanced(r)) return *code;
    }
  } catch (const OutputError& e) {
    // Disk full or a size limit: nothing more can be written, so nothing more is tried; the checkpoint is
    // replaced atomically, so the last complete one is still there.
    r.progress.finish();
    std::cerr << "error: " << e.what() << "\n";
    if (record.checkpoint_strain() >= 0.0)
      std::cerr << "the last complete checkpoint (strain " << record.checkpoint_strain() << ") is kept in "
                << record.checkpoint_path() << "; once there is room, continue with: "
                << restart_command(r.c, record.checkpoint_path(), r.threads)
                << " (should run.h5 be damaged beyond repair, add --out NEW_DIR)\n";
    else
      std::cerr << "no checkpoint was written yet; once there is room, remove the incomplete " << record.run_path()
                << " and start again\n";
    return exit_output_error;
  } catch (const NumericalError& e) {
    r.progress.finish();
    record.file().write_snapshot(snapshot_of(sim));  // the failing state, to look at
    const SimulationState& good = record.save_state_before_failure(evaluating);
    record.finish_outputs();
    record.write_partial_summary("failed", {{"error", e.what()}});
    std::cerr << "error: " << e.what() << "\nthe state before the failing step (strain "
              << progress_strain(flow, good) << ", step " << good.step << ") is in " << record.checkpoint_path()
              << "; the failing state is snapshot " << record.file().snapshot_count() - 1 << " of "
              << record.run_path() << "\n";
    return exit_numerical_error;
  }
  r.progress.finish();
  // The summary before the last checkpoint: a run killed in between continues from the checkpoint before and
  // writes it again; a checkpoint at run.strain always has its summary.json.
  record.finish_outputs();
  const nlohmann::json summary = record.write_summary(r.c.run.average_from, {{"status", "done"}});
  record.save_final(last_step_clipped);
  record.file().close();
  if (r.quiet) return 0;
  // JSON has no NaN: an undefined mean or error (too few samples) is null there, nan here.
  auto v = [&](const char* key, const char* part) {
    const nlohmann::json& x = summary[key][part];
    return x.is_number() ? x.get<double>() : std::nan("");
  };
  if (summary.contains("sigma_star"))
    std::printf("sigma* = %.5g +- %.2g   G_adh = %.4g +- %.2g\n", v("sigma_star", "mean"), v("sigma_star", "sem"),
                v("G_adh", "mean"), v("G_adh", "sem"));
  std::printf("eta_r = %.5g +- %.2g   N1 = %.4g +- %.2g   N2 = %.4g +- %.2g   Pi = %.4g +- %.2g   (strain %.3g-%.3g, "
              "%zu samples)\n",
              v("eta_r", "mean"), v("eta_r", "sem"), v("N1", "mean"), v("N1", "sem"), v("N2", "mean"), v("N2", "sem"),
              v("Pi", "mean"), v("Pi", "sem"), r.c.run.average_from, r.strain(),
              summary["samples"].get<std::size_t>());
  if (const StepLimitCounts& limits = sim.step_limits(); limits.total() > 0)
    std::printf("steps set by: %s (%lld steps of this run)\n", limits.shares().c_str(),
                static_cast<long long>(limits.total()));
  return 0;
}
}  // namespace

std::string restart_command(const Case& c, const std::string& checkpoint, int threads) {
  // Single quotes keep YAML values ({from: file, ...}, 'text') intact in a POSIX shell.
  auto quoted = [](const std::string& a) {
    if (a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._/=+-") == std::string::npos)
      return a;
    std::string q = "'";
    for (char ch : a) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
  };
  std::string command = "suspend run " + quoted(c.source);
  for (const std::string& o : c.overrides) command += " --set " + quoted(o);
  // The thread count too: the continuation is bit-identical only on the same number of threads.
  return command + " --restart " + quoted(checkpoint) + " --threads " + std::to_string(threads);
}

int run_case(const Case& c, const RunOptions& o) {
  const auto started = std::chrono::steady_clock::now();
  const int cores = omp_get_num_procs();
  int threads = o.threads > 0 ? o.threads : (c.run.threads > 0 ? static_cast<int>(c.run.threads) : cores);
  if (threads > cores) {  // more threads than cores only wait for each other (4096 ran 120x slower)
    std::fprintf(stderr, "warning: %d threads asked for, %d cores here: running on %d\n", threads, cores, cores);
    threads = cores;
  }
  omp_set_num_threads(threads);
  const std::string fingerprint = physics_fingerprint(c);
  // Everything that can fail on input happens before the output directory is touched.
  RunStart start = prepare_run_start(c, o, threads, fingerprint);
  const fs::path& dir = start.dir;
  const Flow& flow = c.simulation.flow;
  if (progress_strain(flow, start.state) >= c.run.strain)
    throw InputError("run.strain = " + exact(c.run.strain) + " is already reached by the checkpoint (strain " +
                     exact(progress_strain(flow, start.state)) + "); raise it with --set run.strain=...");
  Simulation sim = hydrodynamic_model(c.hydrodynamics).build(std::move(start.state), start.box, c);
  {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
      throw InputError("--out: cannot create the directory '" + dir.string() + "'" +
                       (ec ? " (" + ec.message() + ")" : "") + "; give a writable folder");
  }
  const bool continuing = start.restarting && !start.branching;  // run.h5 continues in its own folder
  if (!start.lock.held()) {
    start.lock = lock_run_folder(dir);
    // Another process may have started a run here since the checks above.
    if (!continuing && fs::exists(dir / "run.h5"))
      throw InputError("--out: " + dir.string() + " already holds a run (started by another process meanwhile); "
                       "continue it with --restart " + (dir / "checkpoint.h5").string() + " or choose another directory");
  }
  remove_stale_temporaries(dir.string());
  const std::string run_path = (dir / "run.h5").string();
  OutputClock& clock = start.clock;
  RunFile file = continuing ? RunFile::reopen(run_path, clock.series_rows, clock.snapshots)
                            : RunFile::create(run_path, {to_yaml_text(c), threads});
  const double start_strain = progress_strain(flow, sim.state());
  RunRecord record(c, sim, std::move(file), dir.string(), clock, start.rng, fingerprint, threads, started,
                   continuing ? start_strain : -1.0);
  Progress progress(Progress::detect(o.quiet), c.run.strain, start_strain);
  progress.message(start.origin);
  if (!record.file().salvaged().empty())
    progress.message("note: " + run_path + " was damaged (" + record.file().salvaged() + "); rebuilt from the " +
                     std::to_string(clock.series_rows) + " series rows and " + std::to_string(clock.snapshots) +
                     " snapshots the checkpoint knew, the damaged file kept as run.h5.damaged");
  progress.message("writing " + dir.string() + "/{run.h5, run.xdmf, summary.json, checkpoint.h5} on " +
                   std::to_string(threads) + " thread(s)");
  for (const std::string& note : exact_table_notes(c)) progress.message("note: " + note);
  RunContext r{c, sim, record, clock, progress, threads, start_strain, o.quiet};
  return run_loop(r);
}

}  // namespace suspend::io

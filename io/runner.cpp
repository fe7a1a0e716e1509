#include "io/runner.hpp"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "core/version.hpp"
#include "dem/integrate/time_step_control.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/folder_lock.hpp"
#include "io/output_folder.hpp"
#include "io/exact_tables.hpp"
#include "io/initial_configuration.hpp"
#include "io/output_room.hpp"
#include "io/progress.hpp"
#include "io/run_file.hpp"
#include "io/schema_reader.hpp"
#include "io/summary.hpp"
#include "io/xdmf.hpp"
#include "io/yaml_json.hpp"

namespace suspend::io {

namespace fs = std::filesystem;

namespace {
std::atomic<int> stop_signal{0};
extern "C" void on_stop_signal(int sig) { stop_signal.store(sig); }

std::string join(const fs::path& dir, const char* name) { return (dir / name).string(); }

// The strain a run's length, outputs and averaging window count: signed for steady shear, accumulated for the
// other protocols (core/flow.hpp).
double progress_strain(const Flow& flow, const SimulationState& st) {
  return flow.steady() ? st.strain : st.accumulated_strain;
}

// First multiple of `every` strictly above `strain`.
double next_multiple(double strain, double every) { return (std::floor(strain / every + 1e-9) + 1.0) * every; }

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

Snapshot snapshot_of(const Simulation& sim) {
  Snapshot s;
  const SimulationState& st = sim.state();
  s.step = st.step;
  s.time = st.time;
  s.strain = st.strain;
  s.accumulated_strain = st.accumulated_strain;
  s.box = sim.box();
  s.particles = &st.particles;
  const std::vector<Vec3>& f = sim.pair_forces();
  const auto& pairs = sim.active_pairs();
  const std::vector<ContactRecord>& records = sim.contact_records();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (!records[k].contact) continue;  // lubrication-range pairs without contact force are not contacts
    const PairGeometry& g = pairs[k].geometry;
    s.contact_pairs.push_back(pairs[k].i);
    s.contact_pairs.push_back(pairs[k].j);
    for (int a = 0; a < 3; ++a) s.contact_force.push_back(f[k][a]);
    s.contact_gap.push_back(g.gap());
    s.contact_normal_force.push_back(records[k].normal.dot(g.n));
    for (int a = 0; a < 3; ++a) s.contact_tangential_force.push_back(records[k].tangential[a]);
    s.contact_sliding.push_back(records[k].sliding ? 1 : 0);
  }
  return s;
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

// Ctrl-C, kill, a closed terminal (SIGHUP) and a closed pipe for the progress lines (`suspend run ... | head`,
// SIGPIPE) all stop the run at a checkpoint; left at their defaults, the last two killed it with run.h5 open.
void install_stop_handlers() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) std::signal(sig, on_stop_signal);
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
  const OutputCase& every = c.run.output;

  // Everything that can fail on input happens before the output directory is touched.
  const bool restarting = !o.restart.empty();
  bool branching = false;  // restarting into a new folder
  fs::path dir = o.out_dir.empty() && restarting ? fs::path(o.restart).parent_path() : fs::path(o.out_dir);
  if (dir.empty()) throw InputError("--out: missing; give the directory to write the run to");
  SimulationState state;
  Box box;
  OutputClock clock;
  Rng rng(static_cast<std::uint64_t>(c.run.seed));
  std::string origin;
  const Composition composition = c.particles.initial == "random" ? composition_of(c) : Composition{};
  // One process per run folder (io/folder_lock.hpp): a folder that holds a run is locked before anything in it is
  // read, so that a second process is refused instead of continuing from a checkpoint the first is replacing. A new
  // folder is locked once created, below.
  FolderLock lock;
  auto lock_folder = [&] {
    lock = FolderLock(dir / ".run.lock", "suspend run");
    if (!lock.held())
      throw InputError("--out: " + dir.string() + " is in use by " + lock.holder() +
                       "; wait for it to end or give another directory");
  };
  refuse_foreign_folder(dir, FolderKind::run);
  // Continuing in the checkpoint's own folder (another folder holding a run is refused below, untouched).
  const bool own_folder = restarting && fs::weakly_canonical(fs::absolute(dir)) ==
                                            fs::weakly_canonical(fs::absolute(o.restart)).parent_path();
  if (own_folder && (fs::is_regular_file(dir / "run.h5") || fs::is_regular_file(dir / "checkpoint.h5"))) lock_folder();
  if (restarting) {
    if (!fs::is_regular_file(o.restart)) throw InputError("--restart: '" + o.restart + "' does not exist");
    Checkpoint cp = read_checkpoint(o.restart, fingerprint);
    // Into a folder without run.h5 (another --out than the checkpoint's): a new record that starts at the
    // checkpoint's strain; into the checkpoint's own folder, its run.h5 continues.
    // Never into another run's folder: its record would be cut to the checkpoint's rows.
    if (!own_folder)
      for (const char* f : {"run.h5", "checkpoint.h5", "summary.json", "point.json"})
        if (fs::exists(dir / f))
          throw InputError("--out: " + dir.string() + " holds another run (" + f + "); continue " + o.restart +
                           " in its own folder (leave out --out) or into a new one");
    branching = !own_folder;
    if (!branching && !fs::is_regular_file(dir / "run.h5"))
      throw InputError("--restart: " + join(dir, "run.h5") + " is missing; the checkpoint continues that file (or "
                       "give another --out to continue into a new one)");
    for (std::size_t i = 0; i < cp.state.particles.size(); ++i)
      if (static_cast<std::size_t>(cp.state.particles.species[i]) >= c.particles.species.size())
        throw InputError("--restart: " + o.restart + ": particle " + std::to_string(i) + " is of species " +
                         std::to_string(cp.state.particles.species[i]) + ", the case has " +
                         std::to_string(c.particles.species.size()));
    // Checksums can be recomputed by hand: the particles themselves must be the case's (count, radii, species).
    const bool random = c.particles.initial == "random";
    const InitialConfiguration from_file = random ? InitialConfiguration{} : build_initial_configuration(c);
    {
      const std::vector<double>& radius = random ? composition.radius : from_file.particles.radius;
      const Particles& q = cp.state.particles;
      if (q.size() != radius.size())
        throw InputError("--restart: " + o.restart + " holds " + std::to_string(q.size()) + " particles, the case " +
                         std::to_string(radius.size()));
      for (std::size_t i = 0; i < q.size(); ++i)
        if (q.radius[i] != radius[i] || (random && q.species[i] != composition.species[i]))
          throw InputError("--restart: " + o.restart + ": particle " + std::to_string(i) + " has radius " +
                           exact(q.radius[i]) + " (species " + std::to_string(q.species[i]) + "), the case " +
                           exact(radius[i]) + (random ? " (species " + std::to_string(composition.species[i]) + ")"
                                                      : std::string()));
    }
    state = std::move(cp.state);
    clock = cp.clock;
    if (branching) clock.series_rows = clock.snapshots = 0;
    rng = deserialize_rng(cp.rng);
    box = random ? composition.box : from_file.box;
    if (cp.threads != threads)
      std::cerr << "warning: the checkpoint was written with " << cp.threads << " threads and this run uses "
                << threads << "; the continuation is exact only on the same thread count\n";
    std::ostringstream s;
    s << "restarting from " << o.restart << " at strain " << state.strain << " (step " << state.step << ")"
      << (branching ? "; a new run.h5 in " + dir.string() + " starts there" : std::string());
    origin = s.str();
  } else {
    if (const auto holder = FolderLock::holder_of(dir / ".run.lock"))
      throw InputError("--out: " + dir.string() + " is in use by " + *holder +
                       "; wait for it to end or give another directory");
    if (fs::exists(dir / "run.h5"))
      throw InputError("--out: " + dir.string() + " already holds a run; continue it with --restart " +
                       join(dir, "checkpoint.h5") + " or choose another directory");
    InitialConfiguration ic = build_initial_configuration(c);
    state.particles = std::move(ic.particles);
    box = ic.box;
    origin = ic.origin;
    clock.next_series = 0.0;
    clock.next_snapshot = 0.0;
    clock.next_checkpoint = every.checkpoint_every;
  }
  const Flow& flow = c.simulation.flow;
  if (progress_strain(flow, state) >= c.run.strain)
    throw InputError("run.strain = " + exact(c.run.strain) + " is already reached by the checkpoint (strain " +
                     exact(progress_strain(flow, state)) + "); raise it with --set run.strain=...");
  auto run = [&](Simulation& sim) -> int {

    {
      std::error_code ec;
      fs::create_directories(dir, ec);
      if (ec || !fs::is_directory(dir))
        throw InputError("--out: cannot create the directory '" + dir.string() + "'" +
                         (ec ? " (" + ec.message() + ")" : "") + "; give a writable folder");
    }
    if (!lock.held()) {
      lock_folder();
      // Another process may have started a run here since the checks above.
      if ((!restarting || branching) && fs::exists(dir / "run.h5"))
        throw InputError("--out: " + dir.string() + " already holds a run (started by another process meanwhile); "
                         "continue it with --restart " + join(dir, "checkpoint.h5") + " or choose another directory");
    }
    remove_stale_temporaries(dir.string());
    const std::string run_path = join(dir, "run.h5"), checkpoint_path = join(dir, "checkpoint.h5");
    RunFile file = restarting && !branching ? RunFile::reopen(run_path, clock.series_rows, clock.snapshots)
                              : RunFile::create(run_path, {to_yaml_text(c), threads});
    auto progress_of = [&] { return progress_strain(flow, sim.state()); };
    Progress progress(Progress::detect(o.quiet), c.run.strain, progress_of());
    progress.message(origin);
    if (!file.salvaged().empty())
      progress.message("note: " + run_path + " was damaged (" + file.salvaged() + "); rebuilt from the " +
                       std::to_string(clock.series_rows) + " series rows and " + std::to_string(clock.snapshots) +
                       " snapshots the checkpoint knew, the damaged file kept as run.h5.damaged");
    progress.message("writing " + dir.string() + "/{run.h5, run.xdmf, summary.json, checkpoint.h5} on " +
                     std::to_string(threads) + " thread(s)");
    for (const std::string& note : exact_table_notes(c)) progress.message("note: " + note);

    OutputRoom room;
    // Strain of the last complete checkpoint on disk (none yet: negative).
    double checkpoint_strain = restarting && !branching ? progress_of() : -1.0;
    auto save = [&] {
      file.flush();
      clock.series_rows = static_cast<std::int64_t>(file.series_rows());
      clock.snapshots = static_cast<std::int64_t>(file.snapshot_count());
      write_checkpoint(checkpoint_path, {sim.state_with_contacts(), clock, fingerprint, serialize(rng), threads});
      checkpoint_strain = progress_of();
    };
    auto finish_outputs = [&] {
      file.flush();
      write_text_atomically(join(dir, "run.xdmf"), xdmf_text("run.h5", file.snapshots()));
    };

    auto write_summary = [&](double average_from, const nlohmann::json& extra) {
      nlohmann::json summary =
          summarize(file.id(), {sim.state().particles.volume() / sim.box().volume(), sim.state().particles.size(),
                                average_from, flow.control == FlowControl::stress,
                                adhesion_force(c.simulation.contact), flow});
      summary.update(extra);
      // What produced it: the resolved case, the program and this invocation's wall time and threads.
      summary["case"] = yaml_to_json(to_yaml(c));
      summary["version"] = std::string(suspend::version);
      summary["git_commit"] = std::string(suspend::git_commit);
      summary["threads"] = threads;
      summary["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      if (const auto* fcm = dynamic_cast<const FcmModel*>(&sim.model())) {
        const auto steps = fcm->evaluated_steps(), solves = fcm->total_stokes_solves();
        summary["fcm"] = {{"steps", steps}, {"stokes_solves", solves},
                          {"stokes_solves_per_step", steps > 0 ? static_cast<double>(solves) / steps : 0.0}};
      }
      write_text_atomically(join(dir, "summary.json"), summary.dump(2) + "\n");
      return summary;
    };

    // A run that ends before run.strain (stopped, jammed, failed) still summarises what it did: from
    // run.average_from, or from half its strain when it did not get there. Returns the window's start.
    auto write_partial_summary = [&](const char* status, nlohmann::json extra) {
      const double from = std::min(c.run.average_from, 0.5 * progress_of());
      extra["status"] = status;
      try {
        write_summary(from, extra);
      } catch (const std::exception& e) {
        std::cerr << "warning: no summary.json: " << e.what() << "\n";
      }
      return from;
    };

    // The state at the start of this step and of the step before, as a checkpoint would hold them: on a
    // numerical failure the checkpoint gets the state before the failing step (the failing one goes to run.h5 as
    // the last snapshot, to look at). A copy per step: small beside the step itself.
    struct StepStart {
      SimulationState state;
      OutputClock clock;
      bool valid = false;
    } this_step, previous_step;
    bool last_step_clipped = false;  // then previous_step, at the end, is the state before that step
    bool evaluating = false;
    auto remember_step_start = [&] {
      std::swap(previous_step, this_step);
      this_step.state = sim.state_with_contacts();
      this_step.clock = clock;
      this_step.clock.series_rows = static_cast<std::int64_t>(file.series_rows());
      this_step.clock.snapshots = static_cast<std::int64_t>(file.snapshot_count());
      this_step.valid = true;
    };
    // The checkpoint of a step's start (the output clock as it was then: continued, the step is taken again).
    auto save_step_start = [&](const StepStart& s) {
      file.flush();
      write_checkpoint(checkpoint_path, {s.state, s.clock, fingerprint, serialize(rng), threads});
    };

    auto wall0 = std::chrono::steady_clock::now();
    install_stop_handlers();
    double stress_sum = 0.0, rate_sum = 0.0;  // running eta_r = <Sigma_xy> / <gammadot>
    constexpr double max_steps = max_run_steps;
    constexpr int slow_steps_allowed = 1000;    // steps in a row at a pace beyond max_steps before the run stops
    int slow_steps = 0;
    double slow_start_strain = progress_of(), slow_start_time = sim.state().time;
    // Imposed steady (or reversing) stress: a point whose mean rate stays below Sigma / run.jammed.viscosity jams.
    const bool jam_test = flow.control == FlowControl::stress && !flow.oscillatory();
    const double jam_rate = flow.shear_stress / c.run.jammed_viscosity;
    auto end_jammed = [&](double rate, double over_time) {
      file.write_snapshot(snapshot_of(sim));
      save();
      finish_outputs();
      progress.finish();
      const double from = write_partial_summary(
          "jammed", {{"jammed",
                      {{"mean_shear_rate", rate},
                       {"over_time", over_time},
                       {"threshold", jam_rate},
                       // Arrest of a state that flowed, or of one that never did (a packing arrested at once):
                       // it flowed first when it sheared by more than one jamming window before it stopped.
                       {"strain_reached", progress_of()},
                       {"flowed_first", progress_of() > c.run.jammed_strain}}}});
      std::fprintf(stderr,
                   "jammed: the mean shear rate was %.3g over the last %.4g time units (threshold "
                   "Sigma/run.jammed.viscosity = %.3g) at strain %.4g; summary.json averages from strain %.4g\n",
                   rate, over_time, jam_rate, progress_of(), from);
      file.close();
      return exit_jammed;
    };
    try {
      for (;;) {
        remember_step_start();
        evaluating = true;
        sim.evaluate();
        evaluating = false;
        const double strain = progress_of();
        const double eps = 1e-9;
        // Oscillation: series rows evenly in time, run.output.series_per_cycle per cycle (the harmonic analysis
        // of io/oscillatory_response.hpp integrates over them); otherwise every series_every of strain.
        const double series_clock = flow.oscillatory() ? sim.state().time : strain;
        const double series_every = flow.oscillatory() ? flow.period() / every.series_per_cycle : every.series_every;
        if (series_clock >= clock.next_series - eps * (flow.oscillatory() ? series_every : 1.0)) {
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
          file.append(row);
          clock.next_series = next_multiple(series_clock, series_every);
          if (strain >= c.run.average_from) {
            stress_sum += row.stress.total()(0, 1);
            rate_sum += row.shear_rate;
          }
        }
        if (strain >= clock.next_snapshot - eps) {
          file.write_snapshot(snapshot_of(sim));
          clock.next_snapshot = next_multiple(strain, every.snapshot_every);
        }
        progress.update(strain, sim.state().step,
                        rate_sum != 0.0 ? stress_sum / rate_sum : sim.stress().total()(0, 1) / sim.shear_rate());
        if (strain >= c.run.strain - eps) {
          if (file.snapshot_count() == 0 || file.snapshots().back().time < sim.state().time)
            file.write_snapshot(snapshot_of(sim));  // the final state, also when run.strain is between snapshots
          break;
        }

        // The last step ends on run.strain, not past it; a reversal step ends on its strain. The clipped step is
        // for the output only: the final checkpoint is the state before it (continued to a longer strain, the run
        // takes the full step there, as one run straight to that strain does).
        const double pace = flow.progress_rate(sim.shear_rate());
        last_step_clipped = false;
        if (const double left = c.run.strain - strain; pace * sim.time_step() > left) {
          sim.clip_time_step(left / pace);
          last_step_clipped = true;
        }
        if (const double left = flow.next_reversal(sim.state().accumulated_strain) - sim.state().accumulated_strain;
            std::abs(sim.shear_rate()) * sim.time_step() > left)
          sim.clip_time_step(left / std::abs(sim.shear_rate()));
        sim.advance();
        check_finite(sim.state());
        // A step or rate that collapsed mid-run (the time step a case implies is checked before it starts).
        if (std::abs(progress_of() - strain) * max_steps < c.run.strain) {
          if (++slow_steps == slow_steps_allowed) {
            // Under imposed stress a flow that stopped is a jammed point, also before the jamming window closes.
            const double over = sim.state().time - slow_start_time;
            const double rate = std::abs(progress_of() - slow_start_strain) / over;
            if (jam_test && over > 0.0 && rate < jam_rate)
              return end_jammed(rate, over);
            std::ostringstream s;
            s << "no progress: the last " << slow_steps << " steps advanced the strain by "
              << std::abs(progress_of() - slow_start_strain) << " in all (time step " << sim.time_step()
              << ", shear rate " << sim.shear_rate() << "); at this pace run.strain = " << c.run.strain
              << " needs more than " << max_steps << " steps";
            throw NumericalError(s.str());
          }
        } else {
          slow_steps = 0;
          slow_start_strain = progress_of();
          slow_start_time = sim.state().time;
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        // A signal on the step that reaches run.strain lets the run end as done: a "stopped" checkpoint at
        // run.strain could not be continued.
        if (const int sig = stop_signal.load(); sig && progress_of() < c.run.strain - eps) {
          save();
          finish_outputs();
          progress.finish();
          write_partial_summary("stopped", {});
          std::cerr << "stopped by signal " << sig << " at strain " << progress_of()
                    << "; continue with: " << restart_command(c, checkpoint_path, threads) << "\n";
          return 128 + sig;
        }
        if (jam_test) {
          // Jammed below the yield stress: the mean rate over a window stays below Sigma / jammed_viscosity.
          const double window = c.run.jammed_strain * c.run.jammed_viscosity / flow.shear_stress;
          const SimulationState& st = sim.state();
          if (st.time - clock.jam_window_time >= window) {
            if (progress_of() - clock.jam_window_strain < c.run.jammed_strain)
              return end_jammed((progress_of() - clock.jam_window_strain) / (st.time - clock.jam_window_time),
                                st.time - clock.jam_window_time);
            clock.jam_window_time = st.time;
            clock.jam_window_strain = progress_of();
          }
        }
        // Not at run.strain: the end writes summary.json, then that checkpoint (a checkpoint at run.strain without
        // its summary could not be continued).
        if (progress_of() < c.run.strain - eps &&
            (progress_of() >= clock.next_checkpoint - eps || wall >= every.checkpoint_seconds)) {
          clock.next_checkpoint = next_multiple(progress_of(), every.checkpoint_every);
          save();
          wall0 = std::chrono::steady_clock::now();
          if (const std::optional<std::string> full = room.after_checkpoint(run_path, checkpoint_path)) {
            progress.finish();
            std::cerr << "error: " << *full << "; stopped at the checkpoint of strain " << progress_of()
                      << " while everything is complete; once there is room, continue with: "
                      << restart_command(c, checkpoint_path, threads) << "\n";
            return exit_output_error;
          }
        }
      }
    } catch (const OutputError& e) {
      // Disk full or a size limit: nothing more can be written, so nothing more is tried; the checkpoint is
      // replaced atomically, so the last complete one is still there.
      progress.finish();
      std::cerr << "error: " << e.what() << "\n";
      if (checkpoint_strain >= 0.0)
        std::cerr << "the last complete checkpoint (strain " << checkpoint_strain << ") is kept in " << checkpoint_path
                  << "; once there is room, continue with: " << restart_command(c, checkpoint_path, threads)
                  << " (should run.h5 be damaged beyond repair, add --out NEW_DIR)\n";
      else
        std::cerr << "no checkpoint was written yet; once there is room, remove the incomplete " << run_path
                  << " and start again\n";
      return exit_output_error;
    } catch (const NumericalError& e) {
      progress.finish();
      // evaluate() found the state it was given bad: the step that made it is the failing one.
      const StepStart& good = evaluating && previous_step.valid ? previous_step : this_step;
      file.write_snapshot(snapshot_of(sim));
      save_step_start(good);
      finish_outputs();
      write_partial_summary("failed", {{"error", e.what()}});
      std::cerr << "error: " << e.what() << "\nthe state before the failing step (strain "
                << progress_strain(flow, good.state)
                << ", step " << good.state.step << ") is in " << checkpoint_path << "; the failing state is snapshot "
                << file.snapshot_count() - 1 << " of " << run_path << "\n";
      return exit_numerical_error;
    }
    progress.finish();
    // The summary before the last checkpoint: a run killed in between continues from the checkpoint before and
    // writes it again; a checkpoint at run.strain always has its summary.json.
    finish_outputs();
    const nlohmann::json summary = write_summary(c.run.average_from, {{"status", "done"}});
    if (last_step_clipped)
      save_step_start(previous_step);
    else
      save();
    file.close();
    if (o.quiet) return 0;
    // JSON has no NaN: an undefined mean or error (too few samples) is null there, nan here.
    auto v = [&](const char* key, const char* part) {
      const nlohmann::json& x = summary[key][part];
      return x.is_number() ? x.get<double>() : std::nan("");
    };
    if (summary.contains("sigma_star"))
      std::printf("sigma* = %.5g +- %.2g   G_adh = %.4g +- %.2g\n", v("sigma_star", "mean"), v("sigma_star", "sem"),
                  v("G_adh", "mean"), v("G_adh", "sem"));
    std::printf("eta_r = %.5g +- %.2g   N1 = %.4g +- %.2g   N2 = %.4g +- %.2g   Pi = %.4g +- %.2g   (strain %.3g-%.3g, %zu samples)\n",
                v("eta_r", "mean"), v("eta_r", "sem"), v("N1", "mean"), v("N1", "sem"), v("N2", "mean"),
                v("N2", "sem"), v("Pi", "mean"), v("Pi", "sem"), c.run.average_from, progress_of(),
                summary["samples"].get<std::size_t>());
    return 0;
  };
  Simulation sim = c.hydrodynamics == "fcm" ? fcm_simulation(std::move(state), box, c.simulation, c.fcm)
                                             : Simulation(std::move(state), box, c.simulation);
  return run(sim);
}

}  // namespace suspend::io

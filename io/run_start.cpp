#include "io/run_start.hpp"

#include <iostream>
#include <sstream>

#include "core/error.hpp"
#include "io/initial_configuration.hpp"
#include "io/output_folder.hpp"
#include "io/schema_reader.hpp"

namespace suspend::io {

namespace fs = std::filesystem;

FolderLock lock_run_folder(const fs::path& dir) {
  FolderLock lock(dir / ".run.lock", "suspend run");
  if (!lock.held())
    throw InputError("--out: " + dir.string() + " is in use by " + lock.holder() +
                     "; wait for it to end or give another directory");
  return lock;
}

namespace {
std::string join(const fs::path& dir, const char* name) { return (dir / name).string(); }

void check_species_of(const Case& c, const std::string& restart, const Particles& q) {
  for (std::size_t i = 0; i < q.size(); ++i)
    if (static_cast<std::size_t>(q.species[i]) >= c.particles.species.size())
      throw InputError("--restart: " + restart + ": particle " + std::to_string(i) + " is of species " +
                       std::to_string(q.species[i]) + ", the case has " + std::to_string(c.particles.species.size()));
}

// Checksums can be recomputed by hand: the particles themselves must be the case's (count, radii, species).
void check_radii_of(const std::string& restart, const Particles& q, const std::vector<double>& radius,
                    const std::vector<int>* species) {
  if (q.size() != radius.size())
    throw InputError("--restart: " + restart + " holds " + std::to_string(q.size()) + " particles, the case " +
                     std::to_string(radius.size()));
  for (std::size_t i = 0; i < q.size(); ++i)
    if (q.radius[i] != radius[i] || (species && q.species[i] != (*species)[i]))
      throw InputError("--restart: " + restart + ": particle " + std::to_string(i) + " has radius " +
                       exact(q.radius[i]) + " (species " + std::to_string(q.species[i]) + "), the case " +
                       exact(radius[i]) + (species ? " (species " + std::to_string((*species)[i]) + ")"
                                                   : std::string()));
}
}  // namespace

RunStart prepare_run_start(const Case& c, const RunOptions& o, int threads, const std::string& fingerprint) {
  RunStart s;
  s.restarting = !o.restart.empty();
  s.dir = o.out_dir.empty() && s.restarting ? fs::path(o.restart).parent_path() : fs::path(o.out_dir);
  const fs::path& dir = s.dir;
  if (dir.empty()) throw InputError("--out: missing; give the directory to write the run to");
  s.rng = Rng(static_cast<std::uint64_t>(c.run.seed));
  const Composition composition = c.particles.initial == "random" ? composition_of(c) : Composition{};
  // One process per run folder (io/folder_lock.hpp): a folder that holds a run is locked before anything in it is
  // read, so that a second process is refused instead of continuing from a checkpoint the first is replacing. A new
  // folder is locked once created (io/runner.cpp).
  refuse_foreign_folder(dir, FolderKind::run);
  // Continuing in the checkpoint's own folder (another folder holding a run is refused below, untouched).
  const bool own_folder = s.restarting && fs::weakly_canonical(fs::absolute(dir)) ==
                                              fs::weakly_canonical(fs::absolute(o.restart)).parent_path();
  if (own_folder && (fs::is_regular_file(dir / "run.h5") || fs::is_regular_file(dir / "checkpoint.h5")))
    s.lock = lock_run_folder(dir);
  if (!s.restarting) {
    if (const auto holder = FolderLock::holder_of(dir / ".run.lock"))
      throw InputError("--out: " + dir.string() + " is in use by " + *holder +
                       "; wait for it to end or give another directory");
    if (fs::exists(dir / "run.h5"))
      throw InputError("--out: " + dir.string() + " already holds a run; continue it with --restart " +
                       join(dir, "checkpoint.h5") + " or choose another directory");
    InitialConfiguration ic = build_initial_configuration(c);
    s.state.particles = std::move(ic.particles);
    s.box = ic.box;
    s.origin = ic.origin;
    s.clock.next_series = 0.0;
    s.clock.next_snapshot = 0.0;
    s.clock.next_checkpoint = c.run.output.checkpoint_every;
    return s;
  }
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
  s.branching = !own_folder;
  if (!s.branching && !fs::is_regular_file(dir / "run.h5"))
    throw InputError("--restart: " + join(dir, "run.h5") + " is missing; the checkpoint continues that file (or "
                     "give another --out to continue into a new one)");
  check_species_of(c, o.restart, cp.state.particles);
  const bool random = c.particles.initial == "random";
  const InitialConfiguration from_file = random ? InitialConfiguration{} : build_initial_configuration(c);
  check_radii_of(o.restart, cp.state.particles, random ? composition.radius : from_file.particles.radius,
                 random ? &composition.species : nullptr);
  s.state = std::move(cp.state);
  s.clock = cp.clock;
  if (s.branching) s.clock.series_rows = s.clock.snapshots = 0;
  s.rng = deserialize_rng(cp.rng);
  s.box = random ? composition.box : from_file.box;
  if (cp.threads != threads)
    std::cerr << "warning: the checkpoint was written with " << cp.threads << " threads and this run uses " << threads
              << "; the continuation is exact only on the same thread count\n";
  std::ostringstream line;
  line << "restarting from " << o.restart << " at strain " << s.state.strain << " (step " << s.state.step << ")"
       << (s.branching ? "; a new run.h5 in " + dir.string() + " starts there" : std::string());
  s.origin = line.str();
  return s;
}

}  // namespace suspend::io

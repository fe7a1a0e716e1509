// A simulation case: every setting of a run, read from YAML (docs/cases.md), validated, with defaults filled in.
// The papers' dimensionless groups are accepted as the papers give them and converted to the code's units
// (docs/units.md) here, in one place.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/vec.hpp"
#include "dem/packing.hpp"
#include "coupling/fcm_model.hpp"
#include "dem/simulation.hpp"
#include "io/protocols/protocol.hpp"

namespace suspend::io {

struct ParticlesCase {
  double phi = 0.0;
  std::optional<long> count;  // total number; with phi it fixes the (cubic) box
  std::vector<Species> species;
  std::string initial = "random";  // "random" or "file"
  std::string initial_file;        // x y z radius table, or an HDF5 run/checkpoint
  bool compress = false;           // rescale the file's state uniformly to phi (a flowing state made denser)
  double min_gap = 1.0e-3;         // smallest surface gap of a generated packing (a_1)
};

struct OutputCase {
  double series_every = 0.01;     // strain between time-series rows
  int series_per_cycle = 100;     // oscillatory flow: time-series rows per cycle, evenly in time
  double snapshot_every = 1.0;    // strain between snapshots
  long snapshot_every_steps = 0;  // also a snapshot every this many steps (0: none): a blow-up or a creep, step by step
  double checkpoint_every = 1.0;  // strain between checkpoints
  double checkpoint_seconds = 600.0;  // wall-clock seconds between checkpoints
};

struct RunCase {
  double strain = 10.0;
  double average_from = 2.0;  // strain at which the steady-state averaging window starts
  long seed = 1;
  long threads = 0;  // 0: all cores
  OutputCase output;
  // Imposed stress only: the run ends as jammed when, over a time in which a suspension of viscosity
  // jammed_viscosity would shear by jammed_strain, it sheared by less (mean rate below Sigma / jammed_viscosity).
  double jammed_viscosity = 1.0e3;
  double jammed_strain = 0.5;
};

struct Case {
  std::string title;
  std::string source;  // the file it was read from
  std::vector<std::string> overrides;  // the --set assignments applied to it (to print a restart command)
  ParticlesCase particles;
  std::optional<Vec3> box;  // given box, else derived from count and phi
  // The flow's protocol (flow.type: its name) with its input/output side (the same object as
  // simulation.flow.protocol).
  std::shared_ptr<const Protocol> protocol = simple_shear_protocol();
  std::string hydrodynamics = "pairwise";  // "pairwise" or "fcm"
  SimulationParams simulation;
  FcmParams fcm;  // hydrodynamics.fcm (model fcm only)
  RunCase run;
};

// Reads and validates a case file with `--set key=value` overrides applied first. Throws InputError.
Case load_case(const std::string& path, const std::vector<std::string>& overrides = {});
Case parse_case(const YAML::Node& root, const std::string& source);

// The fully resolved case as YAML (every key, defaults filled in): printed by `suspend check`, stored in run.h5.
YAML::Node to_yaml(const Case& c);
std::string to_yaml_text(const Case& c);

// What a run's results depend on: the resolved case less the thread count and the FCM cache folder (YAML text).
// Two runs with the same identity give the same results (bit for bit on the same thread count).
std::string result_identity(const Case& c);

// The resolved physics of a case (everything but run length, output and threads): checkpoints must match it.
std::string physics_fingerprint(const Case& c);

// The keys whose values differ between two YAML texts (dotted paths, "key old -> new", at most four named):
// how refusals name what changed.
std::string yaml_differences(const std::string& old_yaml, const std::string& new_yaml);

// How a resolved case recorded earlier (a checkpoint's fingerprint, a sweep's point, a run's case), perhaps by an
// older version, differs from the case now resolved by `resolve` (result_identity, physics_fingerprint) as `now`:
// "" when it is the same case. The recorded text is read again by this version and resolved, and numbers are
// compared to 1e-12 relative, so a key the resolved form gained with the value the older form implied
// (contact.friction: coulomb) or a group recomputed in its last digit is no change.
std::string case_changes(const std::string& recorded, const std::string& now, std::string (*resolve)(const Case&));

}  // namespace suspend::io

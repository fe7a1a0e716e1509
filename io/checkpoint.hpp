// DIR/checkpoint.h5: everything needed to continue a run exactly (docs/output.md).
// Written atomically (temporary file + rename), so a kill at any moment leaves the previous checkpoint intact.
// Holds the dynamical state, the case fingerprint (the resolved physics of the case: a checkpoint of another case
// is refused), the output bookkeeping (series rows, snapshots, next output strains) and the RNG state.
#pragma once
#include <cstdint>
#include <string>

#include "dem/simulation.hpp"

namespace suspend::io {

struct OutputClock {
  double next_series = 0.0;      // strain of the next series row
  double next_snapshot = 0.0;    // strain of the next snapshot
  double next_checkpoint = 0.0;  // strain of the next periodic checkpoint
  std::int64_t series_rows = 0;
  std::int64_t snapshots = 0;
  // Imposed stress: time and strain at the start of the current jammed-detection window (RunCase::jammed_*).
  double jam_window_time = 0.0;
  double jam_window_strain = 0.0;
};

struct Checkpoint {
  SimulationState state;
  OutputClock clock;
  std::string fingerprint;
  std::string rng;
  int threads = 1;
};

void write_checkpoint(const std::string& path, const Checkpoint& c);
// Throws InputError if the file is unreadable, corrupt, non-finite, or its fingerprint differs from `fingerprint`.
Checkpoint read_checkpoint(const std::string& path, const std::string& fingerprint);

}  // namespace suspend::io

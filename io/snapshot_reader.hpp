// Reads a snapshot of run.h5 (docs/output.md) back as an analysis::Configuration.
#pragma once
#include <hdf5.h>

#include <cstddef>

#include "analysis/configuration.hpp"

namespace suspend::io {

// Snapshots in the file (the groups /snapshots/000000, 000001, ...).
std::size_t snapshot_count(hid_t run_file);
// The snapshot with this index; throws InputError naming the file's count if there is none.
analysis::Configuration read_configuration(hid_t run_file, std::size_t index);

}  // namespace suspend::io

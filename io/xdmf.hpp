// DIR/run.xdmf: lets ParaView open the snapshots of run.h5 as a time series in strain (docs/output.md): three blocks,
// `particles` (points with radius, species, velocity, angular velocity; a Glyph filter scaled by radius draws the
// spheres), `contacts` (a line segment per contact with its forces, gap and sliding state as cell data) and `box`
// (the sheared periodic cell).
#pragma once
#include <string>
#include <vector>

#include "io/run_file.hpp"

namespace suspend::io {

std::string xdmf_text(const std::string& h5_name, const std::vector<SnapshotInfo>& snapshots);

}  // namespace suspend::io

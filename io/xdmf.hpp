// DIR/run.xdmf: lets ParaView open the snapshots of run.h5 as a time series of spheres (point clouds with radius,
// velocity and angular velocity; use a Glyph filter with scale by "radius" to draw spheres).
#pragma once
#include <string>
#include <vector>

#include "io/run_file.hpp"

namespace suspend::io {

std::string xdmf_text(const std::string& h5_name, const std::vector<SnapshotInfo>& snapshots);

}  // namespace suspend::io

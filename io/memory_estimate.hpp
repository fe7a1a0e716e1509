// What a case needs in memory, estimated before anything is allocated, so that a box of 10^9 particles or an FCM
// grid of 10^12 nodes is refused at check time (exit 2, naming the key) instead of dying in std::bad_alloc.
// The estimate is a floor, from measured sizes (docs/performance.md section (d) and the FCM runs of docs/fcm.md):
// about 2 KB per particle (inertial or without lubrication; 5-6 KB with the overdamped resistance solve) and about
// 200 bytes per FCM grid node (velocity, force and spectral fields). A case whose floor exceeds the machine's
// physical memory cannot run.
#pragma once
#include <cstddef>

#include "core/box.hpp"
#include "io/case.hpp"

namespace suspend::io {

// Throws InputError naming the key (particles / box, or hydrodynamics.fcm.grid_spacing) when the floor exceeds
// `memory_bytes` (default: this machine's physical memory). smallest_radius: of the particles (FCM default spacing).
void refuse_what_cannot_fit(const Case& c, double particles, const Vec3& box_lengths, double smallest_radius,
                            double memory_bytes = 0.0);

}  // namespace suspend::io

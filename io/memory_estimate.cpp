#include "io/memory_estimate.hpp"

#include <unistd.h>

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "io/hydrodynamic_models.hpp"

namespace suspend::io {

namespace {
constexpr double bytes_per_particle = 2048.0;
constexpr double bytes_per_fcm_node = 200.0;

std::string size_text(double bytes) {
  std::ostringstream s;
  s.precision(3);
  if (bytes >= 1e12) s << bytes / 1e12 << " TB";
  else if (bytes >= 1e9) s << bytes / 1e9 << " GB";
  else s << bytes / 1e6 << " MB";
  return s.str();
}
}  // namespace

void refuse_what_cannot_fit(const Case& c, double particles, const Vec3& box_lengths, double smallest_radius,
                            double memory_bytes) {
  // Positions are doubles and the neighbour search bins the box: a side beyond 1e6 a_1 (a count at a vanishing
  // phi, or a box given outright) is no suspension this program can follow.
  constexpr double largest_side = 1e6;
  for (int a = 0; a < 3; ++a)
    if (!(box_lengths[a] <= largest_side)) {
      std::ostringstream m;
      m << (c.particles.count ? "particles.phi" : "box") << ": the box side would be " << box_lengths[a]
        << " a_1 (" << particles << " particles at phi = " << c.particles.phi << "); allowed: at most "
        << largest_side << " a_1";
      throw InputError(m.str());
    }
  if (memory_bytes <= 0.0)
    memory_bytes = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  const double for_particles = particles * bytes_per_particle;
  const double nodes = hydrodynamic_model(c.hydrodynamics).grid_nodes(c, box_lengths, smallest_radius);
  const double for_grid = nodes * bytes_per_fcm_node;
  if (for_particles + for_grid <= memory_bytes) return;
  std::ostringstream m;
  m.precision(4);
  if (for_grid > for_particles)
    m << "hydrodynamics.fcm.grid_spacing: a grid of " << nodes << " nodes for a box of " << box_lengths.x() << " x "
      << box_lengths.y() << " x " << box_lengths.z() << " needs at least " << size_text(for_grid + for_particles)
      << " of memory and this machine has " << size_text(memory_bytes) << "; use a coarser grid or a smaller box";
  else
    m << (c.particles.count ? "particles.count" : "box") << ": " << particles << " particles need at least "
      << size_text(for_grid + for_particles) << " of memory (about 2 KB each) and this machine has "
      << size_text(memory_bytes) << "; use fewer particles or a smaller box";
  throw InputError(m.str());
}

}  // namespace suspend::io

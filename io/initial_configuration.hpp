// The configuration a run starts from: a generated random packing, or particles loaded from a file
// (a plain "x y z radius" table, or an HDF5 run/checkpoint of an earlier run).
#pragma once
#include <optional>
#include <string>

#include "core/box.hpp"
#include "core/particles.hpp"
#include "dem/packing.hpp"
#include "io/case.hpp"

namespace suspend::io {

struct InitialConfiguration {
  Particles particles;
  Box box;
  double phi = 0.0;           // reached volume fraction
  PackingReport packing;      // when generated
  std::string origin;         // a line saying where it came from
};

// Particle counts, radii and box of a case (no positions yet).
struct Composition {
  std::vector<std::size_t> counts;
  std::vector<double> radius;
  std::vector<int> species;
  Box box;
  double phi = 0.0;
};
Composition composition_of(const Case& c);

// Throws InputError for anything wrong with the case or the file.
InitialConfiguration build_initial_configuration(const Case& c);

// "x y z radius" per line, '#' comments; every line checked.
Particles read_particle_table(const std::string& path);
// The last snapshot of a run.h5 (with its box, Lees-Edwards offset and the phi its run asked for), or the particles
// of a checkpoint.h5 (with its strain; the box is the case's).
struct StoredParticles {
  Particles particles;
  std::optional<Vec3> box;              // a snapshot's
  std::optional<double> shear_offset;   // a snapshot's
  std::optional<double> strain;         // a checkpoint's
  std::optional<double> requested_phi;  // particles.phi of the run that wrote the snapshot
};
StoredParticles read_particles_h5(const std::string& path);

}  // namespace suspend::io

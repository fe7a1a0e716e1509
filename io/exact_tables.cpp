#include "io/exact_tables.hpp"

#include <cstdio>

#include "dem/hydro/exact_remainder.hpp"
#include "io/hydrodynamic_models.hpp"

namespace suspend::io {

std::vector<std::string> exact_table_notes(const Case& c) {
  std::vector<std::string> notes;
  const std::string user = hydrodynamic_model(c.hydrodynamics).exact_table_user(c);
  if (user.empty()) return notes;
  const auto& species = c.particles.species;
  for (std::size_t s = 0; s < species.size(); ++s)
    for (std::size_t t = s; t < species.size(); ++t) {
      const double lambda = species[t].radius / species[s].radius;
      if (hydro::ExactRemainder::for_ratio(lambda) != nullptr) continue;
      char line[320];
      std::snprintf(line, sizeof line,
                    "species pair of radii %g and %g (lambda = %.6g): no exact two-sphere table (shipped for lambda = "
                    "%s); its %s keeps the singular lubrication terms",
                    species[s].radius, species[t].radius, lambda, hydro::ExactRemainder::shipped_ratios().c_str(),
                    user.c_str());
      notes.emplace_back(line);
    }
  return notes;
}

}  // namespace suspend::io

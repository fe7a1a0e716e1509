#include "dem/integrate/species_lubrication.hpp"

#include <cmath>

#include "core/error.hpp"

namespace suspend {

SpeciesLubrication::SpeciesLubrication(std::vector<double> species_radius, const hydro::LubricationParams& params,
                                       std::string owner)
    : radius_(std::move(species_radius)), owner_(std::move(owner)) {
  params.validate();
  if (radius_.empty()) throw InputError(owner_ + ": at least one species radius is needed");
  laws_.reserve(radius_.size() * radius_.size());
  for (double a_i : radius_)
    for (double a_j : radius_) laws_.emplace_back(a_i, a_j, params);
}

void SpeciesLubrication::check(const Particles& p, const std::vector<int>& species,
                               const std::vector<ActivePair>& pairs) const {
  const std::size_t n = p.size();
  const double a_tolerance = 1e-12;
  for (std::size_t i = 0; i < n; ++i) {
    const int s = species[i];
    if (s < 0 || static_cast<std::size_t>(s) >= radius_.size() ||
        std::abs(p.radius[i] - radius_[s]) > a_tolerance * radius_[s])
      throw InputError(owner_ + ": particle " + std::to_string(i) + " has species " + std::to_string(s) +
                       " and radius " + std::to_string(p.radius[i]) + " inconsistent with the species radii");
  }
  for (const ActivePair& pr : pairs)
    if (pr.i >= n || pr.j >= n || pr.i == pr.j) throw InputError(owner_ + ": invalid pair in the list");
}

}  // namespace suspend

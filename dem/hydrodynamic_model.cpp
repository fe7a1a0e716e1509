#include "dem/hydrodynamic_model.hpp"

#include <algorithm>

namespace suspend {

RadiusClasses::RadiusClasses(const std::vector<double>& particle_radius) : radius(particle_radius) {
  std::sort(radius.begin(), radius.end());
  radius.erase(std::unique(radius.begin(), radius.end()), radius.end());
  of_particle.resize(particle_radius.size());
  for (std::size_t i = 0; i < particle_radius.size(); ++i)
    of_particle[i] = static_cast<int>(std::lower_bound(radius.begin(), radius.end(), particle_radius[i]) -
                                      radius.begin());
}

}  // namespace suspend

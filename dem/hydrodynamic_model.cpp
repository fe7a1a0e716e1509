#include "dem/hydrodynamic_model.hpp"

#include <algorithm>
#include <stdexcept>

namespace suspend {

const ExplicitResponse& HydrodynamicModel::explicit_forces(const HydroLoad&, double, const Eigen::VectorXd&,
                                                           const std::vector<double>&, const std::vector<double>&) {
  throw std::logic_error("this hydrodynamic model has no explicit (inertial) forces");
}

RadiusClasses::RadiusClasses(const std::vector<double>& particle_radius) : radius(particle_radius) {
  std::sort(radius.begin(), radius.end());
  radius.erase(std::unique(radius.begin(), radius.end()), radius.end());
  of_particle.resize(particle_radius.size());
  for (std::size_t i = 0; i < particle_radius.size(); ++i)
    of_particle[i] = static_cast<int>(std::lower_bound(radius.begin(), radius.end(), particle_radius[i]) -
                                      radius.begin());
}

}  // namespace suspend

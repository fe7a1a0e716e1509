// The pairwise lubrication law of every species pair, and the check that a step's particles and pairs match the
// species radii the laws were built for: shared by the resistance solve (resistance_solver.*) and the explicit
// inertial forces (explicit_hydrodynamics.*). What each then builds from a pair's tensors differs (matrix blocks,
// matrix-free forces), the physics does not: both read hydro::PairLubrication here.
#pragma once
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "dem/hydro/lubrication.hpp"
#include "dem/pair_forces.hpp"

namespace suspend {

class SpeciesLubrication {
 public:
  // owner names the user in messages ("resistance solver"). Throws InputError without radii.
  SpeciesLubrication(std::vector<double> species_radius, const hydro::LubricationParams& params, std::string owner);

  const hydro::PairLubrication& operator()(int si, int sj) const { return laws_[si * radius_.size() + sj]; }
  bool active(const ActivePair& pr, const std::vector<int>& species) const {
    return (*this)(species[pr.i], species[pr.j]).active(pr.gap());
  }
  // Throws InputError when species[i] does not index a radius equal to p.radius[i] (1e-12 relative) or a pair has an
  // end outside the particles or twice the same particle.
  void check(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs) const;

 private:
  std::vector<double> radius_;
  std::string owner_;
  std::vector<hydro::PairLubrication> laws_;
};

}  // namespace suspend

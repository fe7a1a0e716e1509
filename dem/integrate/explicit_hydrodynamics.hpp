// Matrix-free hydrodynamic force of the inertial integrator (paper 000 eq. 15, the modified velocity-Verlet
// scheme of section 2.1): the forces are explicit in the half-step velocities, so no resistance matrix is needed.
//
// CONTRACT
//  * Input: disturbance velocities dv_i = (U_i - U_inf(x_i), Omega_i - Omega_inf(x_i)), 6 per particle (the
//    Lees-Edwards image of a particle has the same dv, so ActivePair::y_images is not used).
//  * Output, per particle, the hydrodynamic force and torque ON it (paper 000 eqs. 3 and A.1):
//        F_H,i = F_Faxen,i - R_Stokes,i dv_i + sum_pairs [ -R_lub (dv_i, dv_j) + R_FE : E_inf ]_i
//    F_Faxen,i = (6 pi a_i)(a_i^2/6) lap U_inf(x_i); the pair terms from hydro::PairLubrication::resistance and
//    strain_forces (dem/hydro/lubrication.hpp) for pairs with gap <= outer cutoff. This is
//    ResistanceSolver::explicit_forces without the assembled matrix (equal to round-off; test_explicit_hydrodynamics).
//  * Stress SUMS as ResistanceSolver reports them (not divided by the volume; the caller adds 2 E_inf):
//      hydrodynamic: sum_i (20/3) pi a_i^3 (E_inf + (a_i^2/10) lap E_inf)(x_i)              (paper 000 eq. 9a)
//      lubrication, force_dipole: sum_pairs -sym(d F_j^lub), F_j^lub the lubrication force on j    (eq. 9b)
//      lubrication, stresslet:    sum_pairs (S_i + S_j) of hydro::PairLubrication::evaluate
//  * Relaxation rate: the Gershgorin bound of M^-1 (R_Stokes + R_lub), max over block rows of the absolute row
//    sum of that row (diagonal block = Stokes + the pair self blocks, summed first; plus the coupling blocks)
//    divided by the row's mass or moment of inertia; the same bound as ResistanceSolver::relaxation_rate. The
//    explicit scheme is stable for dt < 2 / rate.
// Units: eta_0 = 1, lengths in a_1, velocities in gammadot a_1, forces eta_0 gammadot a_1^2, torques and stresses
// eta_0 gammadot a_1^3, rates in gammadot.
//
// Method: a gather over particles. Each particle visits its lubricated pairs (an incidence list, both ends, in pair
// order) and evaluates the pair law itself, so every pair is evaluated twice (once per end) and nothing per pair is
// stored but its index: memory is 4 B per particle + 8 B per lubricated pair, against 1 KB per pair for the
// assembled matrix. Each particle writes only its own force; stress and rate are reduced over fixed chunks of
// particles in chunk order. Deterministic: the result is bit-identical for any thread count.
// Workspaces are members: no allocation once the largest pair count has been seen.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/particles.hpp"
#include "core/stress.hpp"
#include "core/ambient_flow.hpp"
#include "dem/hydro/lubrication.hpp"
#include "dem/integrate/resistance_solver.hpp"
#include "dem/integrate/species_lubrication.hpp"
#include "dem/pair_forces.hpp"

namespace suspend {

// Force and torque (6 per particle), hydrodynamic and lubrication stress sums, and the Gershgorin bound on the
// fastest rate of M^-1 R (dem/hydrodynamic_model.hpp), plus the pair count.
struct ExplicitHydroResult : ExplicitResponse {
  std::size_t lubricated_pairs = 0;  // pairs within the outer cutoff
};

class ExplicitHydrodynamics {
 public:
  // species_radius[s]: radius of species s (a_1 units). One PairLubrication per ordered species pair.
  ExplicitHydrodynamics(std::vector<double> species_radius, const hydro::LubricationParams& lubrication,
                        LubricationStress stress = LubricationStress::force_dipole);

  // species[i] indexes species_radius and must match p.radius[i]; pairs from the neighbour search (any gap, those
  // beyond the outer cutoff are skipped); dv: 6 per particle; mass, moment: per particle (for the rate bound).
  // flow.box_height must be the box's L_y. Throws InputError for inconsistent sizes or radii.
  void evaluate(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
                const AmbientFlow& flow, const Eigen::VectorXd& dv, const std::vector<double>& mass,
                const std::vector<double>& moment, ExplicitHydroResult& out);

  // Bytes held by the workspaces (their capacity).
  std::size_t memory_bytes() const;

 private:
  void build_incidence(std::size_t n, const std::vector<int>& species, const std::vector<ActivePair>& pairs);

  SpeciesLubrication law_;
  LubricationStress stress_form_;

  std::vector<std::uint32_t> start_;     // N + 1 offsets into incident_
  std::vector<std::uint32_t> incident_;  // per particle, its lubricated pairs (indices into pairs), in pair order
  struct ChunkSums {
    Mat3 hydrodynamic, lubrication;
    double rate;
  };
  std::vector<ChunkSums> chunks_;
};

}  // namespace suspend

// Sub-grid lubrication for FCM: per close pair, the exact two-sphere resistance minus the part FCM resolves
// (docs/coupling.md; paper 004 section II A 1 eqs. 6-7 and II B; Orsi, Lobry & Peters 2023).
//
// CONTRACT
//  * Scalars: Delta(s') = w(s') [exact(s') - fcm(s')] for every function of pair_tensors::correction_functions,
//    s' = 2r/(a_i + a_j). exact: ExactPairResistance (Stokes drag + lubrication, gap saturated at the pairwise
//    engine's inner cutoff); fcm: FcmPairTable at the actual s' (the FCM solve sees the actual distance).
//    So FCM + Delta reproduces the exact functions wherever w = 1.
//  * Taper (continuity at the cutoff): w = 1 for s' <= s0, w = 1 - t^2 (3 - 2 t), t = (s' - s0)/(s1 - s0), on
//    (s0, s1), w = 0 beyond s1 = `cutoff`. FCM alone is within ~1.5% of the exact X11A at s' = 3 and within 0.75%
//    of every mobility function for s' >= 3 (docs/fcm.md), so the correction is needed only inside s' ~ 3-3.5
//    (docs/references.md). s0 = taper_start for equal spheres (exact functions tabulated);
//    model_taper_start for unequal ones (the singular model alone drifts from the exact functions beyond xi ~ 0.1).
//  * Forces and torques ON the particles (12-vectors (F_i, T_i, F_j, T_j)):
//        F = -Delta_R (V - V_inf) + gammadot Delta_R_FE : E_hat,   E_hat = (e_x e_y + e_y e_x)/2
//    (pair_tensors.hpp for the tensor forms; V - V_inf = the disturbance velocities, equal for a particle and its
//    Lees-Edwards image).
//  * Stress (sum over pairs, not divided by V; Contribution::lubrication): the force dipole of the pair's forces
//    about its contact point, -sym(x_i' F_i + x_j' F_j), x_i' = -l_i n, x_j' = l_j n, l = a r/(a_i + a_j);
//    for equal and opposite forces this is -sym(d F_j), the pairwise engine's default (paper 000 eq. 9b).
// Units: eta = 1, lengths in a_1.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "coupling/exact_pair_resistance.hpp"
#include "coupling/fcm_pair_resistance.hpp"
#include "coupling/pair_tensors.hpp"
#include "linalg/block_matrix.hpp"
#include "dem/integrate/implicit_contacts.hpp"
#include "dem/pair_forces.hpp"

namespace suspend::coupling {

struct SubgridParams {
  double cutoff = 3.5;              // s' beyond which the correction is zero
  double taper_start = 2.5;         // s0 with exact (tabulated) functions
  double model_taper_start = 2.1;   // s0 for unequal spheres (singular model only)
  void validate() const;            // throws InputError naming the key (fcm.subgrid_*)
};

class SubgridLubrication {
 public:
  // species_radius: distinct radii. `table` supplies h, truncation and the table resolution (radii and s_max are
  // set per species pair). Tables are loaded from or written to cache_dir (empty: no cache).
  SubgridLubrication(std::vector<double> species_radius, const SubgridParams& params,
                     const hydro::LubricationParams& lubrication, const FcmPairTableParams& table,
                     const std::string& cache_dir);

  // Largest surface gap (a_1) at which some species pair still has a correction.
  double range() const { return range_; }
  double taper(double s, bool tabulated) const;
  // Delta scalars of the pair (species si of i, sj of j) at surface gap `gap`, seen from i and from j.
  void scalars(int si, int sj, double gap, ResistanceScalars& from_i, ResistanceScalars& from_j) const;

  // Per-configuration assembly: the pair blocks of the pairs with a correction (any others are skipped).
  void assemble(const std::vector<ActivePair>& pairs, const std::vector<int>& species);
  std::size_t corrected_pairs() const { return links_.size(); }
  // f += -Delta_R dv (dv, f: 6 per particle, (U, Omega)).
  void add_velocity_forces(const Eigen::VectorXd& dv, Eigen::VectorXd& f) const;
  // f += gammadot Delta_R_FE : E_hat.
  void add_strain_forces(double shear_rate, Eigen::VectorXd& f) const;
  // Sum of the pair force dipoles for disturbance velocities dv and shear rate (stress contract above); the
  // implicit contact terms below are not part of it.
  Mat3 stress(const Eigen::VectorXd& dv, double shear_rate) const;

  // Linearly implicit contacts (dem/integrate/implicit_contacts.hpp), after assemble(): the step resistance
  // dt C^T S C of every pair with a contact stiffness and its ambient force in the imposed flow at unit rate
  // (unit_flow: simple shear) are added to that pair's terms, so the velocity solve balances the end-of-step
  // contact forces.
  // Contact pairs are always within the correction range (s' < cutoff).
  void add_contact_steps(const std::vector<ActivePair>& pairs, const std::vector<ContactStiffness>& stiffness,
                         double dt, const std::vector<Vec3>& positions, const AmbientFlow& unit_flow);
  // Per pair of the assembled list: the contact force change on j, -dt S u_c, for disturbance velocities dv and
  // the shear rate (zero for pairs without a contact step; empty without any).
  void contact_changes(const Eigen::VectorXd& dv, double shear_rate, std::vector<Vec3>& change_on_j) const;
  // R_Stokes + sum Delta_R over the pairs with s' < s_max as a symmetric block matrix (the Krylov preconditioner),
  // R_Stokes = diag(6 pi a, 8 pi a^3). Restricting it to the close pairs keeps its Cholesky factor sparse.
  // every_contact: pairs with an implicit contact step enter at any s'. fcm_relative: the pairs with s' < s_max
  // also carry P (R_fcm - D) P, the relative-motion part of what FCM resolves of the pair (R_fcm: FcmPairTable, D:
  // the drag, P: the projector of dem/hydro/exact_relative.hpp), so that with Delta_R each pair's relative motion
  // meets its exact two-sphere resistance (the lagged-far-field system, coupled_mobility.hpp).
  void resistance_matrix(const std::vector<double>& radius, double s_max, SymmetricBlockMatrix& m,
                         bool every_contact = false, bool fcm_relative = false);

 private:
  struct SpeciesPair {
    ExactPairResistance exact;
    FcmPairTable fcm;
    bool swapped;  // species order (si, sj) has a_si > a_sj: the tables are stored for the smaller one first
  };
  const SpeciesPair& pair_of(int si, int sj) const { return pairs_[si * species_radius_.size() + sj]; }
  Vector12 pair_forces(std::size_t link, const Eigen::VectorXd& dv, double shear_rate) const;
  Matrix12 fcm_relative_resistance(std::size_t link) const;  // P (R_fcm - D) P of a link
  // -dt S u_c of a link with a contact step.
  Vec3 contact_change(std::size_t link, const Eigen::VectorXd& dv, double shear_rate) const;

  std::vector<double> species_radius_;
  SubgridParams params_;
  std::vector<SpeciesPair> pairs_;  // per ordered species pair
  double range_ = 0.0;

  std::vector<BlockLink> links_;
  std::vector<Vec3> normal_;
  std::vector<double> lever_i_, lever_j_, s_;
  std::vector<BlockLink> near_links_;
  // Delta_R of each pair kept as its block coefficients (pair_resistance_product applies it; the 12 x 12 matrices
  // would be 1152 bytes per pair to stream through every application). The implicit contact step's resistance
  // dt C^T S C of a contact pair is not folded in: pair_forces and resistance_matrix add it from contact_.
  std::vector<PairResistanceCoefficients> delta_r_;
  std::vector<Vector12> delta_strain_;  // for unit shear rate
  std::vector<std::uint32_t> link_pair_;  // index of each link's pair in the assembled list
  std::size_t pair_count_ = 0;
  std::vector<std::int32_t> link_contact_;  // per link: its contact step, or -1
  std::vector<std::pair<int, int>> link_species_;
  std::vector<ContactStep> contact_;        // ambient contact velocity for unit shear rate
};

}  // namespace suspend::coupling

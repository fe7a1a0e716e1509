// Overdamped (zero-inertia) hydrodynamic solve of the pairwise lubrication-DEM engine (docs/overdamped.md;
// paper 000 eqs. 1-3 with the inertia dropped, Appendix A; Mari, Seto, Morris & Denn, J. Rheol. 58, 1693 (2014)).
//
// CONTRACT
//  * Unknowns: the disturbance velocities dV_i = (U_i - U_inf(x_i), Omega_i - Omega_inf(x_i)), 6 per particle.
//    The Lees-Edwards image of a particle has the same disturbance velocity, so pairs across the sheared y faces
//    need no velocity correction (ActivePair::y_images is not used).
//  * Force balance on every particle (hydrodynamic + non-hydrodynamic force and torque = 0):
//        (R_Stokes + sum_pairs R_lub) dV = F_nh + sum_pairs R_FE : E_inf + F_Faxen
//    R_Stokes = diag(6 pi a_i I, 8 pi a_i^3 I) (paper 000 eq. A.1); F_Faxen,i = (6 pi a_i)(a_i^2/6) lap U_inf(x_i)
//    (zero in simple shear); R_lub, R_FE : E_inf from hydro::PairLubrication (dem/hydro/lubrication.hpp) for pairs
//    with gap <= outer cutoff; F_nh = (force, torque) ON each particle from contacts and surface forces (caller).
//  * Output: lab-frame U_i = U_inf(x_i) + dU_i, Omega_i = Omega_inf(x_i) + dOmega_i at the given positions;
//    stress SUMS (not divided by the volume V; the caller adds 2 E_inf and divides):
//      hydrodynamic: sum_i (20/3) pi a_i^3 (E_inf + (a_i^2/10) lap E_inf)(x_i)      (paper 000 eq. 9a)
//      lubrication, LubricationStress::force_dipole (default): sum_pairs -sym(d F_j^lub)  (paper 000 eq. 9b,
//        paper 002), d = x_j - x_i (minimum image), F_j^lub the lubrication force on j; it has a trace, so the
//        lubrication contributes to the particle pressure Pi = -tr(Sigma)/3;
//      lubrication, LubricationStress::stresslet: sum_pairs (S_i + S_j), the traceless resistance-formulation
//        stresslets -G dU - H dOmega + M : E of hydro::PairLubrication::evaluate (no lubrication pressure).
//  * Sign: compressive lubrication (spheres squeezed together) gives a positive lubrication pressure.
// Units: eta_0 = 1, lengths in a_1, velocities in gammadot a_1, forces eta_0 gammadot a_1^2, torques and stresses
// eta_0 gammadot a_1^3.
//
// Solver: preconditioned conjugate gradient (symmetric block Gauss-Seidel by default, or block Jacobi; see
// conjugate_gradient.hpp) warm-started from the previous solution (default), or sparse Cholesky keeping the symbolic analysis while the pair pattern is unchanged. Deterministic: the result
// depends only on the inputs (and, for the warm start, the previous call), not on the thread count.
// Workspaces are kept between calls: no allocation per step once the largest pair count has been seen.
// Memory per link: the coupling block (in the matrix, in the conjugate gradient's scaled form), and the force rows
// of j's self block and j's strain force (21 values, for the stress); the self blocks and strain forces are added to
// their rows a chunk of links at a time. The force-dipole stress is summed from the pair forces without a per-pair
// tensor. With storage pair_form (ResistanceSolverParams::storage) a link keeps n and 6 numbers of its coupling
// block and 3 of j's force rows instead (linalg/pair_form_block.hpp).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/particles.hpp"
#include "core/stress.hpp"
#include "core/ambient_flow.hpp"
#include "dem/hydro/lubrication.hpp"
#include "linalg/block_matrix.hpp"
#include "linalg/conjugate_gradient.hpp"
#include "dem/integrate/implicit_contacts.hpp"
#include "dem/integrate/species_lubrication.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "dem/hydrodynamic_model.hpp"
#include "dem/pair_forces.hpp"

namespace suspend {

enum class LinearSolver { conjugate_gradient, cholesky };
enum class LubricationStress { force_dipole, stresslet };

struct ResistanceSolverParams {
  LinearSolver solver = LinearSolver::conjugate_gradient;
  Preconditioner preconditioner = Preconditioner::symmetric_gauss_seidel;  // of the conjugate gradient
  // Relative residual |b - R dV| / |b| at which CG stops. 1e-6: the velocities' error is then far below the step's
  // own (first order in dt); 1e-8 (before issue 35) moved eta_r by < 0.5% on a transient and took 35% more iterations.
  double tolerance = 1e-6;
  int max_iterations = 5000;  // CG iterations before NumericalError
  bool warm_start = true;     // start CG from the previous solution
  // Coupling blocks of the conjugate gradient: dense 6x6, or pair_form (linalg/pair_form_block.hpp: n and 6
  // numbers a link, the diagonal packed, and the stress's force rows of j as 3 numbers and its strain force), which
  // needs about 1.2 KB less per particle at phi = 0.5 and is the faster one from about 16384 spheres on (it is 1.5-1.7x
  // slower in the caches). The same solution to the solver's tolerance. Unset (`auto`): pair_form from
  // pair_form_from particles on with the conjugate gradient, else dense (docs/performance.md section d).
  std::optional<CouplingStorage> storage;
  static constexpr std::size_t pair_form_from = 16384;
  CouplingStorage storage_for(std::size_t particles) const {
    if (storage) return *storage;
    return solver == LinearSolver::conjugate_gradient && particles >= pair_form_from ? CouplingStorage::pair_form
                                                                                     : CouplingStorage::dense;
  }
  LubricationStress lubrication_stress = LubricationStress::force_dipole;
  hydro::LubricationParams lubrication;
  // Throws InputError naming the key (hydrodynamics.solver.*, lubrication.*).
  void validate() const;
};


// Velocities, stress sums (hydrodynamic and lubrication; with implicit contacts also the virial of
// contact_change_on_j in contact_normal and contact_tangential), CG iterations (0 for Cholesky) and the relative
// residual |b - R dV| / |b| (dem/hydrodynamic_model.hpp), plus the pair forces.
struct SolveResult : HydroResponse {
  // Per pair of the list given (zero beyond the outer cutoff); empty with storage pair_form.
  std::vector<Vec3> lubrication_force_on_j;
  std::size_t lubricated_pairs = 0;          // pairs within the outer cutoff
};

class ResistanceSolver {
 public:
  // species_radius[s]: radius of species s (a_1 units). One PairLubrication per ordered species pair.
  ResistanceSolver(std::vector<double> species_radius, const ResistanceSolverParams& params);

  // One overdamped solve. species[i] indexes species_radius and must match p.radius[i]; pairs come from the
  // neighbour search (ActivePair, any gap: pairs beyond the outer cutoff are skipped by CG and kept as zero blocks
  // by Cholesky so that the pattern, and its analysis, survive between neighbour-list rebuilds); force, torque:
  // non-hydrodynamic force and torque on each particle. flow.box_height must be the box's L_y.
  // Throws NumericalError (message: context, iterations, residual) if CG does not reach the tolerance, or the
  // solution is not finite; InputError for inconsistent sizes or radii.
  // With `implicit` enabled, pairs with a contact stiffness get a block even beyond the outer cutoff, the matrix is
  // R_Stokes + sum R_lub + sum dt C^T S C and the right-hand side gains -C^T dt S u_c,inf.
  void solve(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
             const AmbientFlow& flow, const std::vector<Vec3>& force, const std::vector<Vec3>& torque,
             SolveResult& out, std::string_view context = {}, const ImplicitContacts& implicit = {});
  // Imposed stress: the unit-rate part (flow `unit_flow`, no forces) and the force-driven part (flow `still_flow`,
  // i.e. rate 0, with force and torque) of one matrix, assembled and factorised once; each part warm-starts from its
  // own last solution (disturbance(), forced_disturbance()).
  void solve_parts(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
                   const AmbientFlow& unit_flow, const AmbientFlow& still_flow,
                   const std::vector<Vec3>& force, const std::vector<Vec3>& torque, SolveResult& unit_out,
                   SolveResult& force_out, std::string_view context = {}, const ImplicitContacts& implicit = {});
  // Same, with the species of p.species.
  void solve(const Particles& p, const std::vector<ActivePair>& pairs, const AmbientFlow& flow,
             const std::vector<Vec3>& force, const std::vector<Vec3>& torque, SolveResult& out,
             std::string_view context = {}, const ImplicitContacts& implicit = {});

  // Inertial integrator (paper 000 eq. 15): the hydrodynamic force and torque at given disturbance velocities
  // dv (6 per particle, lab velocity minus U_inf, Omega_inf), explicitly:
  //   F_H = R_FE : E_inf + F_Faxen - (R_Stokes + R_lub) dv,
  // with `out` holding dv as lab velocities and the stress sums as solve() reports them. Replaces the warm start.
  void explicit_forces(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
                       const AmbientFlow& flow, const Eigen::VectorXd& dv, Eigen::VectorXd& force,
                       SolveResult& out);
  // Largest eigenvalue bound of M^-1 R for the matrix of the last call (Gershgorin: max over rows of the absolute
  // row sum divided by that row's mass or moment of inertia): the explicit scheme is stable for dt < 2 / rate.
  double relaxation_rate(const std::vector<double>& mass, const std::vector<double>& moment) const;

  // Drops the warm starts (e.g. after a change of the particle set).
  void forget_warm_start() {
    previous_.resize(0);
    forced_previous_.resize(0);
  }
  // Sets the warm start (a checkpointed disturbance(), so that a restart continues bit for bit), and that of the
  // force-driven part of solve_parts.
  void set_warm_start(const Eigen::VectorXd& dv) { previous_ = dv; }
  void set_forced_warm_start(const Eigen::VectorXd& dv) { forced_previous_ = dv; }

  const ResistanceSolverParams& params() const { return params_; }
  // The matrix and right-hand side of the last solve, their block rows in row_of() order (particle i is block row
  // row_of()[i]; cell_order.hpp), and its solution dV in the particles' order (for tests and diagnostics).
  const SymmetricBlockMatrix& matrix() const { return matrix_; }
  const Eigen::VectorXd& right_hand_side() const { return rhs_; }
  const std::vector<std::uint32_t>& row_of() const { return row_of_; }
  // v (6 per particle, in the particles' order) in block-row order, and back.
  void to_rows(const Eigen::VectorXd& v, Eigen::VectorXd& rows) const;
  void from_rows(const Eigen::VectorXd& rows, Eigen::VectorXd& v) const;
  const Eigen::VectorXd& disturbance() const { return previous_; }
  const Eigen::VectorXd& forced_disturbance() const { return forced_previous_; }
  int pattern_analyses() const { return cholesky_.analyses(); }

 private:
  void assemble(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
                const AmbientFlow& flow, const std::vector<Vec3>& force, const std::vector<Vec3>& torque,
                const ImplicitContacts& implicit = {});
  bool stiff(const ImplicitContacts& implicit, std::size_t k) const {
    return implicit.enabled() && (*implicit.stiffness)[k].any();
  }
  void check(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
             const std::vector<Vec3>& force, const std::vector<Vec3>& torque, const ImplicitContacts& implicit) const;
  // The preconditioner set-up (CG) or the factorisation (Cholesky) of the assembled matrix.
  void factorize();
  // solve_assembled with x (warm start in, solution out) in the particles' order; b in row order.
  void solve_in_particle_order(const Eigen::VectorXd& b, Eigen::VectorXd& x, HydroResponse& out,
                               std::string_view context);
  // x = R^-1 b for the assembled matrix, from the warm start x; throws NumericalError naming the context.
  void solve_assembled(const Eigen::VectorXd& b, Eigen::VectorXd& x, HydroResponse& out, std::string_view context);
  // Lab-frame velocities of the disturbance x, and the stress sums, into out; strain_driven: the assembled strain
  // forces belong to this solution (false for the force-driven part of solve_parts).
  void report_solution(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
                       const AmbientFlow& flow, const Eigen::VectorXd& x, bool strain_driven, SolveResult& out,
                       const ImplicitContacts& implicit = {});
  void accumulate_stress(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
                         const AmbientFlow& flow, const Eigen::VectorXd& x, bool strain_driven, SolveResult& out,
                         const ImplicitContacts& implicit);

  ResistanceSolverParams params_;
  SpeciesLubrication law_;

  // Per link (pair with a block in the matrix): its pair index, and what the stress needs of it beside the coupling
  // block: the force rows of j's self block and j's strain force.
  struct ForceOnJ {
    Eigen::Matrix<double, 3, 6> self_force_rows;
    Vec3 strain_force;
  };
  // The same in pair form (CouplingStorage::pair_form): j's self block's force rows [A, B] as a_n, a_t, b (and, for
  // a sliding contact, s_a and s_b in slip_on_j_, by the matrix's slip_of()).
  struct PairFormForceOnJ {
    double a_n, a_t, b;
    Vec3 strain_force;
  };
  struct SlipOnJ {
    double a, b;
  };
  // -F_j's self part, (A u + B w) of j's block for dV_j = (u, w), of link l.
  Vec3 self_force(std::size_t l, const Vec3& n, const Vector6& dv_j) const;
  // A link's contributions to its two rows, for a chunk of links at a time (assemble()).
  struct ChunkLink {
    PackedSymmetric6 self_i, self_j;
    hydro::Vector12 strain;
  };
  static constexpr std::ptrdiff_t assembly_chunk = 2048;
  std::vector<std::uint32_t> link_pair_;
  std::vector<ForceOnJ> on_j_;
  std::vector<PairFormForceOnJ> compact_on_j_;
  std::vector<SlipOnJ> slip_on_j_;
  std::vector<ChunkLink> chunk_;
  std::vector<std::int32_t> pair_link_;  // per pair: its link, or -1 (beyond the outer cutoff, CG)
  std::size_t lubricated_ = 0;

  std::vector<std::uint32_t> row_of_, order_scratch_;  // block row of each particle (cell_order.hpp)
  std::vector<std::uint32_t> link_count_;              // links per first row, then their offsets
  SymmetricBlockMatrix matrix_;
  Eigen::VectorXd rhs_, previous_, check_, x_;  // x_: a solution in row order
  Eigen::VectorXd forced_rhs_, forced_previous_;  // the force-driven part of solve_parts
  std::vector<Vec3> zero_;
  PreconditionedConjugateGradient cg_;
  PatternCholesky cholesky_;
  std::vector<Mat3> pair_stress_;  // stresslet form only
};

}  // namespace suspend

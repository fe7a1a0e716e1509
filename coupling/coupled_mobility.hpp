// The coupled velocity solve: FCM mobility + sub-grid lubrication resistance + given forces, solved matrix-free
// by right-preconditioned GMRES in one Krylov space for the velocities and the rigidity stresslets together
// (docs/coupling.md).
//
// CONTRACT
//  * Unknowns x = (dV_i, s_i): dV_i = (U_i - U_inf(x_i), Omega_i - Omega_inf) (6 per particle) and the FCM
//    stresslet S_i = sum_k s_ik B_k in an orthonormal basis of traceless symmetric tensors (5 per particle).
//  * Equations (F_i: force and torque the particle exerts on the fluid = external + sub-grid, all ON the particle):
//        F = F_ext + gammadot Delta_R_FE : E_hat - Delta_R dV                        (force balance, zero inertia)
//        dV = U'(F, S),   E_inf + E'(F, S) = 0                                     (FCM mobility, rigidity)
//    with (U', E') one Stokes solve (fcm::Solver::apply). The residual of a guess costs one Stokes solve:
//        r(x) = (U'(F(x), S) - dV, B : (E_inf + E'(F(x), S))),
//    and the operator A x = (dV - U'(-Delta_R dV, S), -B : E'(-Delta_R dV, S)) one more per GMRES iteration.
//    The problem is linear in (gammadot, F_ext): x = gammadot x_shear + x_force (solve_parts).
//  * Preconditioner (right): the isolated-sphere FCM response plus the exact pair correction,
//        P^-1 (r_v, r_s) = ((R_Stokes + sum' Delta_R)^-1 R_Stokes r_v, (20/3) pi a^3 r_s),
//    sum' over the pairs with s' < preconditioner_cutoff (the stiff lubrication pairs; all pairs would make the
//    Cholesky factor dense: 2.2 s per step at phi = 0.45 with the 3.5 cutoff), the first block by block-SGS
//    conjugate gradients to a loose tolerance (default; gmres.hpp is flexible: it keeps the preconditioned vectors)
//    or by sparse Cholesky (dem/integrate/; either falls back to identity if the near-field matrix is not positive
//    definite, counted in preconditioner_failures()).
//  * Stopping: |r| <= tolerance * scale, scale^2 = |r0|^2 + sum_i [ |E_inf|^2 + (|F_i| / 6 pi a_i)^2 / a_i^2 +
//    (|T_i| / 8 pi a_i^3)^2 ] (strain-rate units, like the FCM rigidity solve).
//  * Warm start: the previous solution if the particle count matches (set_warm_start for restarts), or, with
//    `extrapolate` and two previous solutions, 2 x_n - x_{n-1} (the particles move smoothly; steps of similar size).
//  * Lagged far field (multi-rate stepping; CoupledProblem::refresh_far_field = false): no Stokes solve. With the
//    near-field resistance A = R_Stokes + sum'' [Delta_R + P (R_fcm,pair - D) P] + the implicit contact steps
//    (sum'' over the corrected pairs with s' < lagged_cutoff; P (R_fcm,pair - D) P: FCM's own pair resistance for
//    relative motion, SubgridLubrication::resistance_matrix), the far field of the last full solve is kept as
//    its defect g = A_r dV_r - f0_r,
//    the force per particle that FCM and the wider corrections add to the near-field model, and the velocities
//    solve the sparse system of the present configuration
//        A dV = f0 + g
//    by block-SGS conjugate gradients to lagged_tolerance (relative). Sub-grid lubrication of the close pairs,
//    implicit contact steps and all strain forces are those of the present step, so every close pair keeps its
//    exact resistance; g and the FCM stresslets are those of the last full solve. With g of the present
//    configuration this is the full solution, so the error is the drift of g over the lag (docs/coupling.md
//    section 3b). Without a stored g (cold start, another particle count) the solve is full. solve_parts keeps one
//    g per part.
// Units: eta = 1, lengths in a_1.
#pragma once
#include <array>
#include <optional>
#include <span>
#include <vector>

#include "coupling/subgrid_lubrication.hpp"
#include "linalg/conjugate_gradient.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "fcm/solver.hpp"

namespace suspend::coupling {

struct KrylovParams {
  double tolerance = 1e-4;   // relative residual (contract above)
  int max_iterations = 1000;  // GMRES iterations (one Stokes solve each) before NumericalError
  bool warm_start = true;
  bool extrapolate = true;   // warm start from the linear extrapolation of the last two solutions
  double preconditioner_cutoff = 2.2;  // s' below which a pair's correction enters the near-field preconditioner
  // Near-field block of the preconditioner: sparse Cholesky (exact) or a few block-SGS conjugate-gradient
  // iterations to inner_tolerance (inexact and varying, which the flexible GMRES of gmres.hpp allows).
  enum class NearField { cholesky, conjugate_gradient };
  NearField near_field = NearField::conjugate_gradient;
  double inner_tolerance = 1e-2;
  // 5: at min gaps 0.01-0.001 a (phi = 0.45, bench_coupling) the same GMRES iterations (+0.1-0.4 per step) for a
  // fifth to a sixth of the inner iterations of 50 (docs/coupling.md section 6).
  int inner_max_iterations = 5;
  double lagged_tolerance = 1e-6;  // relative residual of the lagged-far-field CG solve
  double lagged_cutoff = 2.25;     // s' below which a pair's correction is solved every step (the pairwise
                                   // engine's lubrication range); beyond it, lagged with the far field
  // > 1: the caller lags the far field (multi-rate stepping, refresh_far_field), so full solves keep their defect g.
  int far_field_every = 1;
  // Full solves start from the lagged-far-field velocities of the present step (the defect g of the last full
  // solve; contract "Lagged far field") instead of the extrapolation: the same solution to the tolerance.
  bool lagged_predictor = false;
  void validate() const;     // throws InputError naming the key (fcm.krylov_*)
};

struct CoupledProblem {
  std::span<const Vec3> positions{};
  std::span<const double> radii{};
  std::span<const Vec3> forces{};   // external, ON the particles; empty: zero
  std::span<const Vec3> torques{};  // empty: zero
  AmbientFlow flow{};  // simple shear (the Lees-Edwards grid); zero: quiescent
  double shear_offset = 0.0;
  // false: the far field of the last full solve is reused (contract, "Lagged far field"), if one is stored.
  bool refresh_far_field = true;
};

struct CoupledResult {
  std::vector<Vec3> velocities, angular_velocities;  // lab frame
  std::vector<Mat3> stresslets;                       // FCM rigidity stresslets
  Mat3 subgrid_stress = Mat3::Zero();                 // sum of the sub-grid pair dipoles (not divided by V)
  std::vector<Vec3> contact_change_on_j;              // implicit contacts: per pair (SubgridLubrication)
  int iterations = 0;                                 // GMRES iterations (lagged far field: CG iterations)
  int stokes_solves = 0;                              // iterations + 1 (the initial residual); lagged: 0
  double residual = 0.0;                              // |r| / scale at exit
};

class CoupledMobility {
 public:
  CoupledMobility(const Vec3& box_length, std::array<int, 3> grid, const fcm::SolverOptions& fcm,
                  const KrylovParams& krylov);

  // subgrid: assembled for this configuration (nullptr: FCM alone). Throws NumericalError if GMRES does not
  // converge or the solution is not finite.
  void solve(const CoupledProblem& problem, SubgridLubrication* subgrid, CoupledResult& out);
  // The two linear parts separately, each with its own warm start (for imposed-stress control, where gammadot is
  // chosen after the solve): shear_part for unit shear rate without forces, force_part for the forces without
  // shear (problem.flow is ignored). The solution for (gammadot, F) is gammadot shear_part + force_part in
  // every output (velocities, spins, stresslets, subgrid_stress; the ambient flow is linear in gammadot).
  void solve_parts(const CoupledProblem& problem, SubgridLubrication* subgrid, CoupledResult& shear_part,
                   CoupledResult& force_part);

  const Eigen::VectorXd& warm_start() const { return x_; }
  // Everything the next warm start depends on, for checkpoints: a restarted run then repeats the uninterrupted one
  // bit for bit. 11 values per particle per stored solution: after `solve`, the last solution and, when
  // extrapolating, the one before it (11 or 22 per particle), then the far-field defect g if kept (6 per
  // particle: 17 or 28); after `solve_parts`, the same for the shear part followed by the force part (22, 44,
  // 34 or 56 per particle).
  std::vector<double> warm_start_state() const;
  // `parts`: the next solves are solve_parts (imposed stress). A state that fits neither layout for n particles
  // (e.g. a restart that switches the flow control) is ignored: the next solve starts cold.
  void set_warm_start_state(const std::vector<double>& state, std::size_t n, bool parts);
  void forget_warm_start() {
    x_.resize(0);
    x_older_.resize(0);
    defect_.resize(0);
    shear_warm_ = {};
    force_warm_ = {};
  }
  fcm::Solver& solver() { return solver_; }
  const fcm::Solver& solver() const { return solver_; }
  const KrylovParams& params() const { return params_; }
  void set_params(const KrylovParams& p) {
    p.validate();
    params_ = p;
  }
  int preconditioner_failures() const { return preconditioner_failures_; }
  int preconditioner_analyses() const { return cholesky_.analyses(); }
  long inner_iterations() const { return inner_iterations_; }
  // Wall-clock seconds since construction: Stokes solves, sub-grid work (assembly excluded), preconditioner.
  struct Timings {
    double stokes = 0.0, subgrid = 0.0, preconditioner = 0.0;
    int solves = 0;
  };
  const Timings& timings() const { return timings_; }
  void reset_timings() { timings_ = {}; }

 private:
  // One Stokes solve with forces f (6 per particle, ON the particles) and stresslet coefficients s; returns
  // dV' (6 per particle) and the particle strain rates' coefficients e (5 per particle).
  void stokes(const CoupledProblem& pb, const Eigen::VectorXd& f, const Eigen::VectorXd& s, Eigen::VectorXd& dv,
              Eigen::VectorXd& e);
  // The lagged-far-field solve (contract) for known forces f0; the near-field matrix is built unless
  // lagged_matrix_ready_ (solve_parts: the second part reuses the first's).
  void solve_lagged(const CoupledProblem& pb, SubgridLubrication* subgrid, const Eigen::VectorXd& f0,
                    const Eigen::VectorXd& r_stokes, CoupledResult& out);
  // The lagged system A dV = f0 + g for the velocities, from the start in `sol` (CG iterations into `out`).
  void lagged_velocities(const CoupledProblem& pb, SubgridLubrication* subgrid, const Eigen::VectorXd& f0,
                         const Eigen::VectorXd& r_stokes, Eigen::VectorXd& sol, CoupledResult& out);
  // lagged_ = A of the present configuration (contract), its CG factors too when `factor`.
  void prepare_lagged_matrix(const CoupledProblem& pb, SubgridLubrication* subgrid, bool factor);
  void write_result(const CoupledProblem& pb, SubgridLubrication* subgrid, CoupledResult& out) const;

  fcm::Solver solver_;
  KrylovParams params_;
  Eigen::VectorXd x_, x_older_, defect_;
  struct WarmStart {
    Eigen::VectorXd last, older, defect;
  };
  WarmStart shear_warm_, force_warm_;
  void exchange(WarmStart& w) {
    std::swap(x_, w.last);
    std::swap(x_older_, w.older);
    std::swap(defect_, w.defect);
  }
  bool lagged_matrix_ready_ = false;
  bool keep_lagged_matrix_ = false;
  bool lagged_matrix_now_ = false;  // lagged_ holds A of the present configuration (this solve assembled it)
  SymmetricBlockMatrix lagged_;
  PreconditionedConjugateGradient lagged_cg_;
  SymmetricBlockMatrix near_;
  PatternCholesky cholesky_;
  PreconditionedConjugateGradient inner_;
  int preconditioner_failures_ = 0;
  long inner_iterations_ = 0;
  Timings timings_;
  std::vector<Vec3> f_, t_, u_, w_;
  std::vector<Mat3> s_;
};

// Orthonormal basis of traceless symmetric 3x3 tensors (B_k : B_l = delta_kl).
const std::array<Mat3, 5>& traceless_basis();

}  // namespace suspend::coupling

// The FCM mobility solver: rigid spheres in a Lees-Edwards periodic box (docs/fcm.md; paper 004 section
// II B; Maxey & Patel 2001, Lomholt & Maxey 2003, Yeo & Maxey 2010).
//
// Units: viscosity eta = 1, lengths in a_1 (smallest radius), so a force F moves an isolated sphere at
// F / (6 pi a); time follows from the caller's forces and shear rate.
// Flow convention: U_inf = (gammadot y, 0, 0), Omega_inf = (0, 0, -gammadot/2), E_inf,xy = E_inf,yx = gammadot/2.
//
// Given forces F and torques T on the particles, solve() returns
//   U = U_inf(Y) + u'(F, T, S),   Omega = Omega_inf + omega'(F, T, S),
// with the stresslets S chosen so every particle is rigid: E_inf + e'(F, T, S) = 0 (preconditioned conjugate
// gradient on the 5 stresslet unknowns per particle, warm-started). u' is the periodic disturbance on the sheared
// lattice with zero mean; the ambient velocity is evaluated at the y the caller passes (its own image).
// The grid is regular in x' = x - gamma_t y (sheared_grid.hpp), gamma_t = D / L_y, D wrapped into [-L_x/2, L_x/2).
#pragma once
#include <array>
#include <memory>
#include <span>
#include <vector>

#include "core/ambient_flow.hpp"
#include "core/vec.hpp"
#include "fcm/disturbance.hpp"
#include "fcm/fft.hpp"
#include "fcm/rigidity_preconditioner.hpp"
#include "fcm/sheared_grid.hpp"
#include "fcm/spreading.hpp"
#include "fcm/stokes_operator.hpp"
#include "fcm/support_plan.hpp"

namespace suspend::fcm {

// Preconditioner of the rigidity CG: the isolated-sphere inverse (Jacobi), or the sparse Cholesky factor of the
// isolated-sphere blocks plus the free-space pair couplings of near neighbours (rigidity_preconditioner.hpp).
enum class RigidityPreconditioner { jacobi, near_field };

struct SolverOptions {
  // Gaussians are cut off at this many monopole widths (of the Gaussian put on the grid: tau_M with spectral
  // splitting, sigma_M without). 4.0 keeps the translational truncation error near 1e-3, below the rotation and
  // stresslet errors of the dipole at h = a/2 (3e-3); 4.5 (1e-4) costs 1.4x the grid work (docs/fcm.md).
  double truncation_widths = 4.0;
  // Spectral splitting (as in spectral Ewald / Gaussian-gridding NUFFT): the envelopes are spread and
  // interpolated with the narrower Gaussians tau^2 = sigma^2 - c^2 and the Green's function is multiplied by
  // exp(-k^2 c^2) (Delta_sigma = Delta_tau * Delta_c), so the operator is FCM with sigma_M, sigma_D up to the
  // aliasing of the narrower Gaussians on the grid, on fewer nodes. c is one value for all particles, chosen so
  // that the smallest particle's dipole is spread with tau_D = split_dipole_width h (h the largest grid spacing);
  // no splitting where sigma_D is already narrower, or with 0.
  double split_dipole_width = 0.0;
  bool rigid = true;                  // solve the stresslets (false: force- and torque-only FCM, S = 0)
  double rigidity_tolerance = 1e-6;   // relative residual of the particle rate of strain
  int max_rigidity_iterations = 200;
  RigidityPreconditioner preconditioner = RigidityPreconditioner::near_field;
  double near_field_cutoff = 1.5;     // near_field: pairs with |Y_m - Y_q| < cutoff (a_m + a_q)
  // near_field: the factor is reused (not rebuilt) while no particle has moved more than this many of its radii,
  // nor the Lees-Edwards offset by more than this many smallest radii, since it was built. Any SPD matrix is a
  // valid preconditioner, so reuse changes the iteration count, never the solution; 0 rebuilds every solve.
  double near_field_reuse_displacement = 0.1;
  FftPlanning planning = FftPlanning::measure;
  void validate() const;
};

struct MobilityProblem {
  std::span<const Vec3> positions{};
  std::span<const double> radii{};
  std::span<const Vec3> forces{};         // on the particles (= on the fluid); empty means zero
  std::span<const Vec3> torques{};        // empty means zero
  AmbientFlow flow{};                     // the imposed flow: simple shear (the Lees-Edwards grid); zero: quiescent
  double shear_offset = 0.0;              // Lees-Edwards offset D (any value; wrapped internally)
  std::span<const Mat3> stresslet_guess{};  // empty: the previous solution if the particle count matches
};

struct MobilityResult {
  std::vector<Vec3> velocities;
  std::vector<Vec3> angular_velocities;
  std::vector<Mat3> stresslets;    // symmetric, traceless (zero when not rigid)
  std::vector<Mat3> strain_rates;  // particle rate of strain incl. the ambient one (~0 when rigid)
  int iterations = 0;              // conjugate-gradient iterations (each costs one Stokes solve)
  double residual = 0.0;           // final relative residual of the rigidity condition
};

// Wall-clock seconds spent in each stage since construction or reset_timings(). `plan` (tabulating the envelope
// footprints, support_plan.hpp) is paid once per configuration (`plans`), the others once per Stokes solve
// (`solves`).
struct SolveTimings {
  double plan = 0.0, spread = 0.0, fft = 0.0, green = 0.0, interpolate = 0.0;
  int solves = 0;
  int plans = 0;
  double precondition = 0.0;  // building the near-field preconditioner (once per configuration) and applying it
};

class Solver {
 public:
  // grid = nodes per direction; FFTW plans are made here (with omp_get_max_threads() threads) and reused.
  Solver(const Vec3& box_length, std::array<int, 3> grid, SolverOptions options = {});

  MobilityResult solve(const MobilityProblem& problem);

  // One Stokes solve without ambient flow or rigidity (any of the spans may be empty).
  // solve() and apply() keep the footprint plan of the last configuration: a call with bitwise the same positions,
  // radii and wrapped Lees-Edwards offset reuses it (e.g. the Stokes solves of one coupled time step).
  Disturbance apply(std::span<const Vec3> positions, std::span<const double> radii, std::span<const Vec3> forces,
                    std::span<const Vec3> torques, std::span<const Mat3> stresslets, double shear_offset);

  // Bulk stress 2 eta E_inf + (1/V) sum_n S_n + (1/V) sum of `moments` (e.g. the interparticle-force
  // stresslets the caller accumulated), eta = 1 (Batchelor 1970; docs/fcm.md). Pressure not included.
  Mat3 bulk_stress(const MobilityResult& result, const AmbientFlow& flow, std::span<const Mat3> moments = {}) const;

  const ShearedGrid& grid() const { return grid_; }
  const SolverOptions& options() const { return options_; }
  // The split width c of the configuration last placed (0: no splitting).
  double split_width() const { return split_; }
  const SolveTimings& timings() const { return timings_; }
  void reset_timings() { timings_ = {}; }

 private:
  // Envelopes and footprint plan of the configuration; a no-op if it equals the one last placed.
  void place(std::span<const Vec3> positions, std::span<const double> radii, double shear_offset);
  // Whether the near-field factor was built for a configuration within near_field_reuse_displacement of pb's.
  bool near_field_is_current(const MobilityProblem& pb) const;
  // u' from the current envelopes and the given multipoles; writes the requested moments (spans may be empty).
  void stokes_solve(std::span<const Vec3> forces, std::span<const Mat3> dipoles, std::span<Vec3> velocities,
                    std::span<Mat3> gradient_moments);

  SolverOptions options_;
  ShearedGrid grid_;
  std::unique_ptr<VectorFft> fft_;
  std::vector<Envelope> envelopes_;
  double split_ = 0.0;        // c of the placed configuration
  SplitWindow window_;        // exp(-c^2 k^2) on the grid's modes
  SupportPlan plan_;  // envelope footprints of the current configuration, in spatially sorted order
  bool plan_current_ = false;         // plan_ holds placed_positions_, placed_radii_ at grid_.shear_fraction
  std::vector<Vec3> placed_positions_;
  std::vector<double> placed_radii_;
  NearFieldPreconditioner near_field_;
  std::vector<Vec3> near_field_positions_;  // configuration the near-field factor was built for
  std::vector<double> near_field_radii_;
  double near_field_offset_ = 0.0;
  std::vector<Mat3> last_stresslets_;
  SolveTimings timings_;
};

}  // namespace suspend::fcm

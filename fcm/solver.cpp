#include "fcm/solver.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/box.hpp"
#include "core/error.hpp"
#include "fcm/envelope.hpp"
#include "fcm/stokes_operator.hpp"

namespace suspend::fcm {
namespace {

Mat3 traceless_symmetric(const Mat3& m) {
  Mat3 s = 0.5 * (m + m.transpose());
  s.diagonal().array() -= s.trace() / 3.0;
  return s;
}

double dot(std::span<const Mat3> a, std::span<const Mat3> b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i].array() * b[i].array()).sum();
  return s;
}

}  // namespace

void SolverOptions::validate() const {
  if (!(truncation_widths >= 2.0 && truncation_widths <= 10.0))
    throw InputError("fcm.truncation_widths must lie in [2, 10]");
  if (!(rigidity_tolerance > 0.0 && rigidity_tolerance < 1.0))
    throw InputError("fcm.rigidity_tolerance must lie in (0, 1)");
  if (max_rigidity_iterations < 1) throw InputError("fcm.max_rigidity_iterations must be at least 1");
  if (!(near_field_reuse_displacement >= 0.0 && near_field_reuse_displacement <= 1.0))
    throw InputError("fcm.near_field_reuse_displacement must lie in [0, 1] (radii)");
  if (!(split_dipole_width == 0.0 || (split_dipole_width >= 0.3 && split_dipole_width <= 5.0)))
    throw InputError("fcm.split_dipole_width must be 0 (no spectral splitting) or lie in [0.3, 5] grid spacings");
  if (!(near_field_cutoff >= 1.0 && near_field_cutoff <= 5.0))
    throw InputError("fcm.near_field_cutoff must lie in [1, 5] (centre distance over the sum of the radii)");
}

Solver::Solver(const Vec3& box_length, std::array<int, 3> grid, SolverOptions options) : options_(options) {
  options_.validate();
  for (int d = 0; d < 3; ++d) {
    if (!(box_length[d] > 0.0)) throw InputError("fcm: box lengths must be positive");
    if (grid[d] < 8) throw InputError("fcm: grid must have at least 8 nodes per direction");
  }
  grid_.n = grid;
  grid_.length = box_length;
  grid_.spacing = box_length.cwiseQuotient(Vec3(grid[0], grid[1], grid[2]));
  fft_ = std::make_unique<VectorFft>(grid, 0, options_.planning);
}

void Solver::place(std::span<const Vec3> positions, std::span<const double> radii, double shear_offset) {
  if (radii.size() != positions.size()) throw InputError("fcm: one radius per particle is required");
  if (!std::isfinite(shear_offset)) throw InputError("fcm: shear offset must be finite");
  // Only the wrapped offset matters: D and D + L_x describe the same lattice.
  const double shear_fraction = wrap_centered(shear_offset, grid_.length.x()) / grid_.length.y();
  // The same configuration as last time (bitwise): the plan is still valid.
  if (plan_current_ && shear_fraction == grid_.shear_fraction && positions.size() == placed_positions_.size() &&
      std::equal(positions.begin(), positions.end(), placed_positions_.begin(),
                 [](const Vec3& a, const Vec3& b) { return a.x() == b.x() && a.y() == b.y() && a.z() == b.z(); }) &&
      std::equal(radii.begin(), radii.end(), placed_radii_.begin()))
    return;
  plan_current_ = false;
  grid_.shear_fraction = shear_fraction;
  // Split width c: the smallest particle's dipole is spread with tau_D = split_dipole_width h.
  double a_min = radii.empty() ? 0.0 : radii[0];
  for (std::size_t i = 0; i < radii.size(); ++i) {
    if (!(radii[i] > 0.0)) throw InputError("fcm: particle radius must be positive (particle " + std::to_string(i) + ")");
    a_min = std::min(a_min, radii[i]);
  }
  const double tau_d = options_.split_dipole_width * grid_.spacing.maxCoeff(), sigma_d = dipole_width(a_min);
  split_ = options_.split_dipole_width > 0.0 && sigma_d > tau_d ? std::sqrt(sigma_d * sigma_d - tau_d * tau_d) : 0.0;
  window_.update(grid_, split_);
  envelopes_.resize(positions.size());
  const double min_length = grid_.length.minCoeff();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite()) throw InputError("fcm: particle position is not finite (particle " + std::to_string(i) + ")");
    envelopes_[i] = make_envelope(positions[i], radii[i], options_.truncation_widths, split_);
    if (2.0 * envelopes_[i].support >= min_length)
      throw InputError("fcm: box too small for the envelope of particle " + std::to_string(i) +
                       " (needs L > 2 * truncation_widths * tau_M)");
  }
  // The footprints are fixed for the whole solve: every Stokes solve of the rigidity CG reuses them.
  const double t0 = omp_get_wtime();
  plan_support(grid_, envelopes_, grid_order(grid_, envelopes_), plan_);
  timings_.plan += omp_get_wtime() - t0;
  ++timings_.plans;
  placed_positions_.assign(positions.begin(), positions.end());
  placed_radii_.assign(radii.begin(), radii.end());
  plan_current_ = true;
}

void Solver::stokes_solve(std::span<const Vec3> forces, std::span<const Mat3> dipoles, std::span<Vec3> velocities,
                          std::span<Mat3> gradient_moments) {
  const std::size_t stride = fft_->real_size();
  double* field = fft_->real_data();
  const double t0 = omp_get_wtime();
  fft_->zero_real();
  spread(plan_, forces, dipoles, field, stride);
  const double t1 = omp_get_wtime();
  timings_.spread += t1 - t0;
  fft_->forward(FftScaling::none);
  const double t2 = omp_get_wtime();
  // The inverse FFT is unnormalised: fold its 1/N into the Green's function (eta = 1).
  apply_stokes_green(grid_, *fft_, 1.0 / static_cast<double>(stride), &window_);
  const double t3 = omp_get_wtime();
  fft_->inverse(FftScaling::none);
  const double t4 = omp_get_wtime();
  interpolate(plan_, field, stride, velocities, gradient_moments);
  const double t5 = omp_get_wtime();
  timings_.fft += (t2 - t1) + (t4 - t3);
  timings_.green += t3 - t2;
  timings_.interpolate += t5 - t4;
  ++timings_.solves;
}

Disturbance Solver::apply(std::span<const Vec3> positions, std::span<const double> radii,
                          std::span<const Vec3> forces, std::span<const Vec3> torques,
                          std::span<const Mat3> stresslets, double shear_offset) {
  place(positions, radii, shear_offset);
  const std::size_t n = positions.size();
  if ((!forces.empty() && forces.size() != n) || (!torques.empty() && torques.size() != n) ||
      (!stresslets.empty() && stresslets.size() != n))
    throw InputError("fcm: forces, torques and stresslets need one entry per particle");
  std::vector<Mat3> dipoles;
  if (!torques.empty() || !stresslets.empty()) {
    dipoles.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      dipoles[i] = dipole_tensor(torques.empty() ? Vec3::Zero() : torques[i],
                                 stresslets.empty() ? Mat3::Zero() : stresslets[i]);
  }
  Disturbance out;
  out.velocities.resize(n);
  std::vector<Mat3> a(n);
  stokes_solve(forces, dipoles, out.velocities, a);
  out.angular_velocities.resize(n);
  out.strain_rates.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.angular_velocities[i] = angular_velocity_of(a[i]);
    out.strain_rates[i] = strain_rate_of(a[i]);
  }
  return out;
}

bool Solver::near_field_is_current(const MobilityProblem& pb) const {
  const std::size_t n = pb.positions.size();
  if (near_field_positions_.size() != n || near_field_radii_ != std::vector<double>(pb.radii.begin(), pb.radii.end()))
    return false;
  const double reuse = options_.near_field_reuse_displacement;
  if (!(reuse > 0.0)) return false;
  double a_min = n > 0 ? pb.radii[0] : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    if ((pb.positions[i] - near_field_positions_[i]).norm() > reuse * pb.radii[i]) return false;
    a_min = std::min(a_min, pb.radii[i]);
  }
  // Pairs across the sheared face move with the offset (D and D + L_x are the same lattice).
  return std::abs(wrap_centered(pb.shear_offset - near_field_offset_, grid_.length.x())) <= reuse * a_min;
}

MobilityResult Solver::solve(const MobilityProblem& pb) {
  place(pb.positions, pb.radii, pb.shear_offset);
  const std::size_t n = pb.positions.size();
  if ((!pb.forces.empty() && pb.forces.size() != n) || (!pb.torques.empty() && pb.torques.size() != n) ||
      (!pb.stresslet_guess.empty() && pb.stresslet_guess.size() != n))
    throw InputError("fcm: forces, torques and stresslet guesses need one entry per particle");
  pb.flow.validate();
  if (!pb.flow.is_simple_shear()) throw InputError("fcm: the Lees-Edwards grid carries simple shear only");
  const Mat3 e_inf = pb.flow.strain_rate();
  const Vec3 omega_inf = pb.flow.angular_velocity();

  MobilityResult res;
  res.stresslets.assign(n, Mat3::Zero());
  if (options_.rigid) {
    if (!pb.stresslet_guess.empty())
      std::copy(pb.stresslet_guess.begin(), pb.stresslet_guess.end(), res.stresslets.begin());
    else if (last_stresslets_.size() == n)
      res.stresslets = last_stresslets_;
    for (auto& s : res.stresslets) s = traceless_symmetric(s);
  }
  // First solve: everything known plus the initial stresslets. Its residual r0 = E_inf + e'(F, T, S0).
  std::vector<Mat3> dipoles(n);
  for (std::size_t i = 0; i < n; ++i)
    dipoles[i] = dipole_tensor(pb.torques.empty() ? Vec3::Zero() : pb.torques[i], res.stresslets[i]);
  std::vector<Vec3> u(n);
  std::vector<Mat3> a(n);
  stokes_solve(pb.forces, dipoles, u, a);
  std::vector<Vec3> omega(n);
  std::vector<Mat3> r(n);
  for (std::size_t i = 0; i < n; ++i) {
    omega[i] = angular_velocity_of(a[i]);
    r[i] = traceless_symmetric(e_inf + strain_rate_of(a[i]));
  }

  if (options_.rigid && n > 0) {
    // Preconditioned CG on K S = E_inf + e'(F, T, 0), K S = -e'(0, 0, S): symmetric positive (the adjoint
    // structure of spreading.hpp). Preconditioner: the isolated-sphere inverse (20/3) pi a^3 (Jacobi) or the
    // near-field factor (rigidity_preconditioner.hpp).
    const bool near_field = options_.preconditioner == RigidityPreconditioner::near_field;
    if (near_field && !near_field_is_current(pb)) {
      const double t0 = omp_get_wtime();
      near_field_.build(grid_, pb.positions, pb.radii, options_.near_field_cutoff);
      near_field_positions_.assign(pb.positions.begin(), pb.positions.end());
      near_field_radii_.assign(pb.radii.begin(), pb.radii.end());
      near_field_offset_ = pb.shear_offset;
      timings_.precondition += omp_get_wtime() - t0;
    }
    const auto precondition = [&](const std::vector<Mat3>& res_in, std::vector<Mat3>& out) {
      if (!near_field) {
        for (std::size_t i = 0; i < n; ++i) out[i] = res_in[i] / stresslet_self_mobility(pb.radii[i]);
        return;
      }
      const double t0 = omp_get_wtime();
      near_field_.apply(res_in, out);
      timings_.precondition += omp_get_wtime() - t0;
    };
    // The residual is measured against a rate-of-strain scale that stays meaningful when the warm start is
    // already converged or the right-hand side vanishes by symmetry: |r0|^2 plus, per particle, |E_inf|^2, the
    // strain the guess induces on an isolated sphere and the rates F/(6 pi a^2), T/(8 pi a^3).
    double scale2 = dot(r, r);
    for (std::size_t i = 0; i < n; ++i) {
      const double ai = pb.radii[i];
      const Mat3 self = res.stresslets[i] * stresslet_self_mobility(ai);
      scale2 += (self.array() * self.array()).sum() + e_inf.squaredNorm();
      if (!pb.forces.empty()) scale2 += (pb.forces[i] * translational_self_mobility(ai) / ai).squaredNorm();
      if (!pb.torques.empty()) scale2 += (pb.torques[i] * rotational_self_mobility(ai)).squaredNorm();
    }
    const double scale = std::sqrt(scale2);
    std::vector<Mat3> z(n), p(n), q(n);
    std::vector<Vec3> up(n);
    precondition(r, z);
    p = z;
    double rz = dot(r, z);
    res.residual = scale > 0.0 ? std::sqrt(dot(r, r)) / scale : 0.0;
    while (res.residual > options_.rigidity_tolerance && res.iterations < options_.max_rigidity_iterations) {
      stokes_solve({}, p, up, a);
      for (std::size_t i = 0; i < n; ++i) q[i] = -traceless_symmetric(strain_rate_of(a[i]));
      const double pq = dot(p, q);
      if (!(pq > 0.0)) throw NumericalError("fcm: rigidity operator is not positive definite (p.Kp <= 0)");
      const double alpha = rz / pq;
      for (std::size_t i = 0; i < n; ++i) {
        res.stresslets[i] += alpha * p[i];
        r[i] -= alpha * q[i];
        u[i] += alpha * up[i];  // velocities are linear in S: accumulate instead of re-solving
        omega[i] += alpha * angular_velocity_of(a[i]);
      }
      ++res.iterations;
      res.residual = std::sqrt(dot(r, r)) / scale;
      precondition(r, z);
      const double rz_new = dot(r, z);
      const double beta = rz_new / rz;
      rz = rz_new;
      for (std::size_t i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
    }
    if (res.residual > options_.rigidity_tolerance)
      throw NumericalError("fcm: rigidity solve did not converge in " + std::to_string(res.iterations) +
                           " iterations (residual " + std::to_string(res.residual) + ")");
    last_stresslets_ = res.stresslets;
  }

  res.velocities.resize(n);
  res.angular_velocities.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    res.velocities[i] = u[i] + pb.flow.velocity(pb.positions[i]);
    res.angular_velocities[i] = omega[i] + omega_inf;
  }
  res.strain_rates = std::move(r);
  return res;
}

Mat3 Solver::bulk_stress(const MobilityResult& result, const AmbientFlow& flow, std::span<const Mat3> moments) const {
  Mat3 sum = Mat3::Zero();
  for (const Mat3& s : result.stresslets) sum += s;
  for (const Mat3& m : moments) sum += m;
  return flow.ambient_stress() + sum / grid_.length.prod();
}

}  // namespace suspend::fcm

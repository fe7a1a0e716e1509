#include "coupling/coupled_mobility.hpp"

#include <omp.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>

#include "core/error.hpp"
#include "linalg/gmres.hpp"

namespace suspend::coupling {
using std::numbers::pi;
namespace {

using Index = Eigen::Index;

}  // namespace

const std::array<Mat3, 5>& traceless_basis() {
  static const std::array<Mat3, 5> basis = [] {
    std::array<Mat3, 5> b;
    for (auto& m : b) m.setZero();
    const double r2 = 1.0 / std::sqrt(2.0), r6 = 1.0 / std::sqrt(6.0);
    b[0](0, 0) = r2;
    b[0](1, 1) = -r2;
    b[1](0, 0) = b[1](1, 1) = -r6;
    b[1](2, 2) = 2.0 * r6;
    b[2](0, 1) = b[2](1, 0) = r2;
    b[3](0, 2) = b[3](2, 0) = r2;
    b[4](1, 2) = b[4](2, 1) = r2;
    return b;
  }();
  return basis;
}

void KrylovParams::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) throw InputError("fcm.krylov_tolerance must lie in (0, 1)");
  if (max_iterations < 1) throw InputError("fcm.krylov_max_iterations must be at least 1");
  if (!(preconditioner_cutoff >= 2.0)) throw InputError("fcm.preconditioner_cutoff must be >= 2");
  if (!(inner_tolerance > 0.0 && inner_tolerance < 1.0)) throw InputError("fcm.inner_tolerance must lie in (0, 1)");
  if (inner_max_iterations < 1) throw InputError("hydrodynamics.fcm.preconditioner_iterations must be at least 1");
  if (!(lagged_tolerance > 0.0 && lagged_tolerance < 1.0))
    throw InputError("fcm.lagged_tolerance must lie in (0, 1)");
  if (far_field_every < 1) throw InputError("fcm.far_field_every must be at least 1");
  if (!(lagged_cutoff >= 2.0)) throw InputError("fcm.lagged_cutoff must be >= 2");
}

CoupledMobility::CoupledMobility(const Vec3& box_length, std::array<int, 3> grid, const fcm::SolverOptions& fcm,
                                 const KrylovParams& krylov)
    : solver_(box_length, grid, fcm), params_(krylov) {
  params_.validate();
}

void CoupledMobility::solve_parts(const CoupledProblem& problem, SubgridLubrication* subgrid,
                                  CoupledResult& shear_part, CoupledResult& force_part) {
  CoupledProblem shear = problem, force = problem;
  shear.flow = AmbientFlow::simple_shear(1.0);
  shear.forces = {};
  shear.torques = {};
  force.flow = AmbientFlow::simple_shear(0.0);
  // A lagged-far-field second part reuses the near-field matrix of the first (same configuration).
  lagged_matrix_ready_ = false;
  keep_lagged_matrix_ = true;
  for (auto [pb, ws, out] : {std::tuple{&shear, &shear_warm_, &shear_part}, std::tuple{&force, &force_warm_, &force_part}}) {
    exchange(*ws);
    try {
      solve(*pb, subgrid, *out);
    } catch (...) {
      exchange(*ws);
      keep_lagged_matrix_ = lagged_matrix_ready_ = false;
      throw;
    }
    exchange(*ws);
    keep_lagged_matrix_ = false;
  }
  lagged_matrix_ready_ = false;
}

namespace {

void append(std::vector<double>& s, const Eigen::VectorXd& last, const Eigen::VectorXd& older,
            const Eigen::VectorXd& defect) {
  s.insert(s.end(), last.data(), last.data() + last.size());
  if (older.size() == last.size()) s.insert(s.end(), older.data(), older.data() + older.size());
  if (defect.size() * 11 == last.size() * 6) s.insert(s.end(), defect.data(), defect.data() + defect.size());
}

}  // namespace

std::vector<double> CoupledMobility::warm_start_state() const {
  std::vector<double> s;
  if (shear_warm_.last.size() == 0) {
    append(s, x_, x_older_, defect_);
  } else {
    append(s, shear_warm_.last, shear_warm_.older, shear_warm_.defect);
    append(s, force_warm_.last, force_warm_.older, force_warm_.defect);
  }
  return s;
}

void CoupledMobility::set_warm_start_state(const std::vector<double>& state, std::size_t n, bool parts) {
  forget_warm_start();
  if (state.empty()) return;
  const std::size_t per = n == 0 ? 0 : state.size() / n;
  // Per part: last (11), older (11, when extrapolating), defect (6, lagged far field).
  const std::size_t part = parts ? per / 2 : per;
  const bool fits = n > 0 && state.size() == per * n && (!parts || per % 2 == 0) &&
                    (part == 11 || part == 22 || part == 17 || part == 28);
  if (!fits) return;  // another layout (a restart that changes the flow control, or the pairwise engine's): start cold
  const bool older = part == 22 || part == 28, defect = part == 17 || part == 28;
  const double* at = state.data();
  const auto read = [&](std::size_t values, Eigen::VectorXd& v) {
    v = Eigen::Map<const Eigen::VectorXd>(at, static_cast<Eigen::Index>(values * n));
    at += values * n;
  };
  const auto read_part = [&](Eigen::VectorXd& last, Eigen::VectorXd& old, Eigen::VectorXd& g) {
    read(11, last);
    if (older) read(11, old);
    if (defect) read(6, g);
  };
  if (!parts) {
    read_part(x_, x_older_, defect_);
    return;
  }
  read_part(shear_warm_.last, shear_warm_.older, shear_warm_.defect);
  read_part(force_warm_.last, force_warm_.older, force_warm_.defect);
}

void CoupledMobility::stokes(const CoupledProblem& pb, const Eigen::VectorXd& f, const Eigen::VectorXd& s,
                             Eigen::VectorXd& dv, Eigen::VectorXd& e) {
  const std::size_t n = pb.positions.size();
  const auto& b = traceless_basis();
  f_.resize(n);
  t_.resize(n);
  s_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Index o = 6 * static_cast<Index>(i);
    f_[i] = f.segment<3>(o);
    t_[i] = f.segment<3>(o + 3);
    Mat3 m = Mat3::Zero();
    for (int k = 0; k < 5; ++k) m += s(5 * static_cast<Index>(i) + k) * b[k];
    s_[i] = m;
  }
  const double t0 = omp_get_wtime();
  const fcm::Disturbance d = solver_.apply(pb.positions, pb.radii, f_, t_, s_, pb.shear_offset);
  timings_.stokes += omp_get_wtime() - t0;
  ++timings_.solves;
  dv.resize(6 * static_cast<Index>(n));
  e.resize(5 * static_cast<Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    dv.segment<3>(6 * static_cast<Index>(i)) = d.velocities[i];
    dv.segment<3>(6 * static_cast<Index>(i) + 3) = d.angular_velocities[i];
    for (int k = 0; k < 5; ++k) e(5 * static_cast<Index>(i) + k) = (b[k].array() * d.strain_rates[i].array()).sum();
  }
}

void CoupledMobility::solve(const CoupledProblem& pb, SubgridLubrication* subgrid, CoupledResult& out) {
  const std::size_t n = pb.positions.size();
  if (pb.radii.size() != n || (!pb.forces.empty() && pb.forces.size() != n) ||
      (!pb.torques.empty() && pb.torques.size() != n))
    throw InputError("coupling: positions, radii, forces and torques need one entry per particle");
  const Index nv = 6 * static_cast<Index>(n), ns = 5 * static_cast<Index>(n);
  const auto& basis = traceless_basis();
  if (!pb.flow.is_simple_shear()) throw InputError("coupling: the Lees-Edwards grid carries simple shear only");
  const Mat3 e_inf = pb.flow.strain_rate();
  Eigen::VectorXd e_inf_coeff(5);
  for (int k = 0; k < 5; ++k) e_inf_coeff(k) = (basis[k].array() * e_inf.array()).sum();

  // Known forces: external plus the sub-grid strain forces.
  Eigen::VectorXd f0 = Eigen::VectorXd::Zero(nv);
  for (std::size_t i = 0; i < n; ++i) {
    if (!pb.forces.empty()) f0.segment<3>(6 * static_cast<Index>(i)) = pb.forces[i];
    if (!pb.torques.empty()) f0.segment<3>(6 * static_cast<Index>(i) + 3) = pb.torques[i];
  }
  double t0 = omp_get_wtime();
  if (subgrid) subgrid->add_strain_forces(pb.flow.shear_rate(), f0);
  timings_.subgrid += omp_get_wtime() - t0;

  if (!params_.warm_start || x_.size() != nv + ns) {
    x_ = Eigen::VectorXd::Zero(nv + ns);
    x_older_.resize(0);
    defect_.resize(0);
  }
  // Isolated-sphere drag diag(6 pi a, 8 pi a^3): the preconditioner's scale and the lagged system without pairs.
  Eigen::VectorXd r_stokes(nv);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = pb.radii[i];
    r_stokes.segment<3>(6 * static_cast<Index>(i)).setConstant(6.0 * pi * a);
    r_stokes.segment<3>(6 * static_cast<Index>(i) + 3).setConstant(8.0 * pi * a * a * a);
  }
  if (!pb.refresh_far_field && defect_.size() == nv) {
    solve_lagged(pb, subgrid, f0, r_stokes, out);
    return;
  }
  const Eigen::VectorXd last = x_;
  // Linear, not quadratic (3 x_n - 3 x_{n-1} + x_{n-2}): the stored solutions carry errors up to the tolerance,
  // which the larger weights amplify; at phi = 0.45 that took 7.3 GMRES iterations per step instead of 1.4, and
  // least-squares lines through 3 or 4 solutions lost at a min gap of 0.001 a (docs/coupling.md section 6).
  if (params_.extrapolate && x_older_.size() == x_.size()) x_ = 2.0 * x_ - x_older_;
  lagged_matrix_now_ = false;
  if (params_.lagged_predictor && defect_.size() == nv) {
    // The velocities of the lagged-far-field step as the start: contacts and close pairs of this step, the far
    // field of the last solve (docs/coupling.md section 3c). A predictor that fails leaves the extrapolation.
    const double tp = omp_get_wtime();
    Eigen::VectorXd predicted = x_.head(nv);
    CoupledResult ignored;
    try {
      lagged_velocities(pb, subgrid, f0, r_stokes, predicted, ignored);
      x_.head(nv) = predicted;
    } catch (const NumericalError&) {
      // The start stays the extrapolation; lagged_ (if assembled) is still this configuration's matrix.
    }
    timings_.subgrid += omp_get_wtime() - tp;
  }
  // Preconditioner: (R_Stokes + sum Delta_R)^-1 R_Stokes on the velocities, the isolated stresslet on the strains.
  std::vector<double> radius(pb.radii.begin(), pb.radii.end());
  Eigen::VectorXd s_scale(ns);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = radius[i];
    s_scale.segment<5>(5 * static_cast<Index>(i)).setConstant(20.0 / 3.0 * pi * a * a * a);
  }
  bool near_ok = false;
  t0 = omp_get_wtime();
  if (subgrid && subgrid->corrected_pairs() > 0) {
    subgrid->resistance_matrix(radius, params_.preconditioner_cutoff, near_);
    try {
      if (params_.near_field == KrylovParams::NearField::cholesky)
        cholesky_.factorize(near_);
      else
        inner_.prepare(near_);
      near_ok = true;
    } catch (const NumericalError&) {
      ++preconditioner_failures_;
    }
  }
  timings_.preconditioner += omp_get_wtime() - t0;

  Eigen::VectorXd f(nv), dv(nv), e(ns), rhs(nv), sol(nv);
  auto forces_of = [&](const Eigen::VectorXd& v, const Eigen::VectorXd& base) {
    f = base;
    if (subgrid) {
      const double ts = omp_get_wtime();
      subgrid->add_velocity_forces(v, f);
      timings_.subgrid += omp_get_wtime() - ts;
    }
  };
  // Initial residual r(x) (one Stokes solve).
  Eigen::VectorXd r0(nv + ns);
  forces_of(x_.head(nv), f0);
  stokes(pb, f, x_.tail(ns), dv, e);
  r0.head(nv) = dv - x_.head(nv);
  for (std::size_t i = 0; i < n; ++i)
    r0.segment<5>(nv + 5 * static_cast<Index>(i)) = e_inf_coeff + e.segment<5>(5 * static_cast<Index>(i));
  double scale2 = r0.squaredNorm();
  for (std::size_t i = 0; i < n; ++i) {
    const double a = radius[i];
    scale2 += e_inf.squaredNorm();
    scale2 += (f0.segment<3>(6 * static_cast<Index>(i)) / (6.0 * pi * a * a)).squaredNorm();
    scale2 += (f0.segment<3>(6 * static_cast<Index>(i) + 3) / (8.0 * pi * a * a * a)).squaredNorm();
  }
  const double scale = std::sqrt(scale2);
  const Eigen::VectorXd zero_f = Eigen::VectorXd::Zero(nv);

  auto apply = [&](const Eigen::VectorXd& v, Eigen::VectorXd& result) {
    forces_of(v.head(nv), zero_f);
    stokes(pb, f, v.tail(ns), dv, e);
    result.resize(nv + ns);
    result.head(nv) = v.head(nv) - dv;
    result.tail(ns) = -e;
  };
  auto precondition = [&](const Eigen::VectorXd& v, Eigen::VectorXd& result) {
    result.resize(nv + ns);
    if (near_ok) {
      const double tp = omp_get_wtime();
      rhs = r_stokes.cwiseProduct(v.head(nv));
      if (params_.near_field == KrylovParams::NearField::cholesky) {
        cholesky_.solve(rhs, sol);
      } else {
        sol = v.head(nv);  // the isolated-sphere answer as the inner start
        const ConjugateGradientReport cg = inner_.solve(near_, rhs, sol, params_.inner_tolerance,
                                                        params_.inner_max_iterations,
                                                        Preconditioner::symmetric_gauss_seidel);
        inner_iterations_ += cg.iterations;
      }
      result.head(nv) = sol;
      timings_.preconditioner += omp_get_wtime() - tp;
    } else {
      result.head(nv) = v.head(nv);
    }
    result.tail(ns) = s_scale.cwiseProduct(v.tail(ns));
  };
  Eigen::VectorXd dx;
  const GmresReport rep = gmres(apply, precondition, r0, dx, params_.tolerance * scale, params_.max_iterations);
  out.iterations = rep.iterations;
  out.stokes_solves = rep.iterations + 1;
  out.residual = scale > 0.0 ? rep.residual / scale : 0.0;
  if (!(out.residual <= params_.tolerance)) {
    x_ = last;
    throw NumericalError("coupled FCM solve did not converge in " + std::to_string(rep.iterations) +
                         " GMRES iterations (relative residual " + std::to_string(out.residual) + ")");
  }
  x_ += dx;
  if (!x_.allFinite()) {
    x_.resize(0);
    x_older_.resize(0);
    throw NumericalError("coupled FCM solve: non-finite solution");
  }

  x_older_ = last;
  if (params_.far_field_every > 1 || params_.lagged_predictor) {  // the defect g = A dV - f0 (contract)
    if (!lagged_matrix_now_) prepare_lagged_matrix(pb, subgrid, false);
    const Eigen::VectorXd dv_r = x_.head(nv);
    if (subgrid && subgrid->corrected_pairs() > 0) {
      lagged_.multiply(dv_r, defect_);
    } else {
      defect_ = r_stokes.cwiseProduct(dv_r);
    }
    defect_ -= f0;
  } else {
    defect_.resize(0);
  }
  write_result(pb, subgrid, out);
}

void CoupledMobility::lagged_velocities(const CoupledProblem& pb, SubgridLubrication* subgrid,
                                        const Eigen::VectorXd& f0, const Eigen::VectorXd& r_stokes,
                                        Eigen::VectorXd& sol, CoupledResult& out) {
  const bool near = subgrid && subgrid->corrected_pairs() > 0;
  if (near && !lagged_matrix_ready_) prepare_lagged_matrix(pb, subgrid, true);
  lagged_matrix_ready_ = keep_lagged_matrix_;
  lagged_matrix_now_ = near;
  const Eigen::VectorXd rhs = f0 + defect_;
  out.iterations = 0;
  out.residual = 0.0;
  if (near) {
    const ConjugateGradientReport cg =
        lagged_cg_.solve(lagged_, rhs, sol, params_.lagged_tolerance, params_.max_iterations * 25,
                         Preconditioner::symmetric_gauss_seidel);
    if (!cg.converged)
      throw NumericalError("lagged-far-field solve (near-field conjugate gradients) did not converge in " +
                           std::to_string(cg.iterations) + " iterations (relative residual " +
                           std::to_string(cg.residual) + ")");
    out.iterations = cg.iterations;
    out.residual = cg.residual;
  } else {
    sol = rhs.cwiseQuotient(r_stokes);
  }
  if (!sol.allFinite()) throw NumericalError("lagged-far-field solve: non-finite solution");
}

void CoupledMobility::solve_lagged(const CoupledProblem& pb, SubgridLubrication* subgrid, const Eigen::VectorXd& f0,
                                   const Eigen::VectorXd& r_stokes, CoupledResult& out) {
  const Index nv = 6 * static_cast<Index>(pb.positions.size());
  const double t0 = omp_get_wtime();
  Eigen::VectorXd sol = x_.head(nv);
  if (params_.extrapolate && x_older_.size() == x_.size()) sol = 2.0 * x_.head(nv) - x_older_.head(nv);
  lagged_velocities(pb, subgrid, f0, r_stokes, sol, out);
  timings_.subgrid += omp_get_wtime() - t0;
  x_older_ = x_;
  x_.head(nv) = sol;  // the stresslets stay those of the last full solve
  out.stokes_solves = 0;
  write_result(pb, subgrid, out);
}

void CoupledMobility::prepare_lagged_matrix(const CoupledProblem& pb, SubgridLubrication* subgrid, bool factor) {
  if (!subgrid || subgrid->corrected_pairs() == 0) return;
  const std::vector<double> radius(pb.radii.begin(), pb.radii.end());
  subgrid->resistance_matrix(radius, params_.lagged_cutoff, lagged_, true, true);
  if (factor) lagged_cg_.prepare(lagged_);  // throws NumericalError if a diagonal block is not positive definite
}

void CoupledMobility::write_result(const CoupledProblem& pb, SubgridLubrication* subgrid, CoupledResult& out) const {
  const std::size_t n = pb.positions.size();
  const Index nv = 6 * static_cast<Index>(n);
  const auto& basis = traceless_basis();
  out.velocities.resize(n);
  out.angular_velocities.resize(n);
  out.stresslets.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Index o = 6 * static_cast<Index>(i);
    out.velocities[i] = x_.segment<3>(o) + pb.flow.velocity(pb.positions[i]);
    out.angular_velocities[i] = x_.segment<3>(o + 3) + pb.flow.angular_velocity();
    Mat3 m = Mat3::Zero();
    for (int k = 0; k < 5; ++k) m += x_(nv + 5 * static_cast<Index>(i) + k) * basis[k];
    out.stresslets[i] = m;
  }
  out.subgrid_stress = subgrid ? subgrid->stress(x_.head(nv), pb.flow.shear_rate()) : Mat3::Zero();
  if (subgrid)
    subgrid->contact_changes(x_.head(nv), pb.flow.shear_rate(), out.contact_change_on_j);
  else
    out.contact_change_on_j.clear();
}

}  // namespace suspend::coupling

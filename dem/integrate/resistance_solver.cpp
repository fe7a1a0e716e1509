// Assembly, solve and stress of the overdamped resistance problem; equations and conventions in the header.
#include "dem/integrate/resistance_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/capacity.hpp"
#include "core/error.hpp"
#include "dem/hydro/stokes_drag.hpp"
#include "dem/integrate/cell_order.hpp"

namespace suspend {

namespace {
const ResistanceSolverParams& validated(const ResistanceSolverParams& p) {
  p.validate();
  return p;
}
}  // namespace

void ResistanceSolverParams::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0))
    throw InputError("hydrodynamics.solver.tolerance = " + std::to_string(tolerance) + " must be in (0, 1)");
  if (max_iterations < 1)
    throw InputError("hydrodynamics.solver.max_iterations = " + std::to_string(max_iterations) + " must be >= 1");
  if (storage == CouplingStorage::pair_form && solver != LinearSolver::conjugate_gradient)
    throw InputError("hydrodynamics.solver.storage = pair_form needs hydrodynamics.solver.method = cg");
  lubrication.validate();
}

ResistanceSolver::ResistanceSolver(std::vector<double> species_radius, const ResistanceSolverParams& params)
    : params_(validated(params)), law_(std::move(species_radius), params_.lubrication, "resistance solver") {}

void ResistanceSolver::solve(const Particles& p, const std::vector<ActivePair>& pairs, const AmbientFlow& flow,
                             const std::vector<Vec3>& force, const std::vector<Vec3>& torque, SolveResult& out,
                             std::string_view context, const ImplicitContacts& implicit) {
  solve(p, p.species, pairs, flow, force, torque, out, context, implicit);
}

void ResistanceSolver::assemble(const Particles& p, const std::vector<int>& species,
                                const std::vector<ActivePair>& pairs, const AmbientFlow& flow,
                                const std::vector<Vec3>& force, const std::vector<Vec3>& torque,
                                const ImplicitContacts& implicit) {
  const std::size_t n = p.size();
  const bool keep_inactive = params_.solver == LinearSolver::cholesky;  // stable pattern for the analysis

  // Rows in cell order (cell_order.hpp) for the conjugate gradient; Cholesky keeps the particles' order, so that its
  // pattern (and analysis) survives while the pairs do.
  if (keep_inactive) {
    row_of_.resize(n);
    for (std::size_t i = 0; i < n; ++i) row_of_[i] = static_cast<std::uint32_t>(i);
  } else {
    cell_order(p.position, 2.0, row_of_, order_scratch_);
  }

  // Links: pairs that get a block, by their first row (ties in list order), so that a sweep over the rows reads
  // the blocks nearly in storage order.
  lubricated_ = 0;
  resize_with_headroom(pair_link_, pairs.size());
  link_count_.assign(n + 1, 0);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ActivePair& pr = pairs[k];
    const bool active = law_.active(pr, species);
    lubricated_ += active ? 1 : 0;
    if (active || keep_inactive || stiff(implicit, k)) {
      pair_link_[k] = 0;  // has a link; which one is set below
      ++link_count_[std::min(row_of_[pr.i], row_of_[pr.j]) + 1];
    } else {
      pair_link_[k] = -1;
    }
  }
  for (std::size_t r = 0; r < n; ++r) link_count_[r + 1] += link_count_[r];
  std::vector<BlockLink>& links = matrix_.links_to_set();
  resize_with_headroom(links, link_count_[n]);
  resize_with_headroom(link_pair_, link_count_[n]);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (pair_link_[k] < 0) continue;
    const ActivePair& pr = pairs[k];
    const std::uint32_t l = link_count_[std::min(row_of_[pr.i], row_of_[pr.j])]++;
    pair_link_[k] = static_cast<std::int32_t>(l);
    links[l] = {row_of_[pr.i], row_of_[pr.j]};
    link_pair_[l] = static_cast<std::uint32_t>(k);
  }
  matrix_.set_structure(n, params_.storage_for(n));
  const bool compact = matrix_.storage() == CouplingStorage::pair_form;
  const std::ptrdiff_t nl = static_cast<std::ptrdiff_t>(links.size());
  if (compact) {
    // Sliding contacts' links get a slip entry (the only blocks with terms along the slip direction).
    resize_with_headroom(compact_on_j_, nl);
    std::int32_t slips = 0;
    for (std::ptrdiff_t l = 0; l < nl; ++l) {
      const std::size_t k = link_pair_[l];
      const bool slides = stiff(implicit, k) && (*implicit.stiffness)[k].slip_direction.squaredNorm() > 0.0;
      matrix_.slip_of()[l] = slides ? slips++ : -1;
    }
    matrix_.slips().resize(static_cast<std::size_t>(slips));
    slip_on_j_.resize(static_cast<std::size_t>(slips));
  } else {
    resize_with_headroom(on_j_, nl);
  }

  // Block rows: Stokes drag; right-hand side F_nh + Faxen.
  rhs_.resize(6 * static_cast<Eigen::Index>(n));
  const std::ptrdiff_t nn = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (nn > 512)
  for (std::ptrdiff_t i = 0; i < nn; ++i) {
    const double a = p.radius[i];
    const hydro::StokesResistance s = hydro::stokes_resistance(a);
    const std::ptrdiff_t r = row_of_[i];
    Vector6 drag;
    drag << s.translation, s.translation, s.translation, s.rotation, s.rotation, s.rotation;
    matrix_.set_diagonal(static_cast<std::size_t>(r), drag);
    rhs_.segment<3>(6 * r) = force[i] + s.translation * (a * a / 6.0) * flow.velocity_laplacian(p.position[i]);
    rhs_.segment<3>(6 * r + 3) = torque[i];
  }

  // Pair blocks (R_lub is zero beyond the outer cutoff), a chunk of links at a time: each link writes its coupling
  // block and its self blocks and strain forces into the chunk (in parallel), then the chunk is added to its rows
  // in link order (sequentially: the sums do not depend on the thread count). Only the force rows of j's self
  // block and strain force are kept, for the stress.
  for (std::ptrdiff_t start = 0; start < nl; start += assembly_chunk) {
    const std::ptrdiff_t count = std::min<std::ptrdiff_t>(assembly_chunk, nl - start);
    chunk_.resize(static_cast<std::size_t>(count));
#pragma omp parallel for schedule(static) if (count > 256)
    for (std::ptrdiff_t c = 0; c < count; ++c) {
      const std::ptrdiff_t l = start + c;
      const std::size_t k = link_pair_[l];
      const ActivePair& pr = pairs[k];
      const hydro::PairLubrication& lub = law_(species[pr.i], species[pr.j]);
      const double gap = pr.gap();
      hydro::Matrix12 r = lub.resistance(pr.geometry().n, gap);
      hydro::Vector12 strain = lub.strain_forces(pr.geometry().n, gap, flow.strain_rate(p.position[pr.i]),
                                                 flow.strain_rate(p.position[pr.j]));
      if (stiff(implicit, k)) {  // backward-Euler contact terms (implicit_contacts.hpp)
        const ContactStep cs =
            contact_step(pr.geometry(), p.position[pr.i], (*implicit.stiffness)[k], implicit.dt, flow);
        r += cs.resistance();
        strain += cs.ambient_force();
      }
      ChunkLink& out = chunk_[c];
      out.self_i.pack(r.block<6, 6>(0, 0));
      out.self_j.pack(r.block<6, 6>(6, 6));
      out.strain = strain;
      if (compact) {
        const std::int32_t s = matrix_.slip_of()[l];
        const Vec3 t = s < 0 ? Vec3::Zero() : Vec3((*implicit.stiffness)[k].slip_direction);
        SlipForm slip, self_slip;
        PairFormBlock self;
        if (!compress(r.block<6, 6>(0, 6), pr.geometry().n, t, matrix_.pair_form()[l], slip) ||
            !compress(r.block<6, 6>(6, 6), pr.geometry().n, t, self, self_slip))
          throw NumericalError("resistance solver: the block of pair (" + std::to_string(pr.i) + ", " +
                               std::to_string(pr.j) + ") is not of the pair form (hydrodynamics.solver.storage = "
                               "pair_form); use storage: dense");
        if (s >= 0) {
          matrix_.slips()[s] = slip;
          slip_on_j_[s] = {self_slip.a, self_slip.b};
        }
        compact_on_j_[l] = {self.a_n, self.a_t, self.b, strain.segment<3>(6)};
      } else {
        matrix_.coupling()[l] = r.block<6, 6>(0, 6);
        on_j_[l] = {r.block<3, 6>(6, 6), strain.segment<3>(6)};
      }
    }
    for (std::ptrdiff_t c = 0; c < count; ++c) {
      const BlockLink& link = links[start + c];
      matrix_.add_to_diagonal(link.i, chunk_[c].self_i);
      matrix_.add_to_diagonal(link.j, chunk_[c].self_j);
      rhs_.segment<6>(6 * static_cast<Eigen::Index>(link.i)) += chunk_[c].strain.segment<6>(0);
      rhs_.segment<6>(6 * static_cast<Eigen::Index>(link.j)) += chunk_[c].strain.segment<6>(6);
    }
  }
}

void ResistanceSolver::check(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
                             const std::vector<Vec3>& force, const std::vector<Vec3>& torque,
                             const ImplicitContacts& implicit) const {
  const std::size_t n = p.size();
  if (species.size() != n || force.size() != n || torque.size() != n || p.position.size() != n)
    throw InputError("resistance solver: species, force and torque need one entry per particle");
  law_.check(p, species, pairs);
  if (implicit.enabled() && (implicit.stiffness->size() != pairs.size() || !(implicit.dt >= 0.0)))
    throw InputError("resistance solver: implicit contacts need one stiffness per pair and dt >= 0");
}

void ResistanceSolver::factorize() {
  if (params_.solver == LinearSolver::conjugate_gradient)
    cg_.prepare(matrix_);
  else
    cholesky_.factorize(matrix_);
}

void ResistanceSolver::solve_assembled(const Eigen::VectorXd& b, Eigen::VectorXd& x, HydroResponse& out,
                                       std::string_view context) {
  const Eigen::Index size = b.size();
  if (!params_.warm_start || x.size() != size) x = Eigen::VectorXd::Zero(size);
  out.iterations = 0;
  bool converged = true;
  if (params_.solver == LinearSolver::conjugate_gradient) {
    const ConjugateGradientReport report =
        cg_.solve(matrix_, b, x, params_.tolerance, params_.max_iterations, params_.preconditioner);
    out.iterations = report.iterations;
    out.residual = report.residual;
    converged = report.converged;
  } else {
    cholesky_.solve(b, x);
    matrix_.multiply(x, check_);
    const double b_norm = b.norm();
    out.residual = b_norm > 0.0 ? (b - check_).norm() / b_norm : 0.0;
    converged = std::isfinite(out.residual);
  }
  if (!converged || !x.allFinite()) {
    std::ostringstream s;
    s << "resistance solve failed";
    if (!context.empty()) s << " (" << context << ")";
    if (params_.solver == LinearSolver::conjugate_gradient)
      s << ": " << out.iterations << " conjugate-gradient iterations, relative residual " << out.residual
        << " (tolerance " << params_.tolerance << ", max_iterations " << params_.max_iterations << ")";
    else
      s << ": sparse Cholesky solution not finite (relative residual " << out.residual << ")";
    x.resize(0);  // do not warm-start from a failed solve
    throw NumericalError(s.str());
  }
}

void ResistanceSolver::to_rows(const Eigen::VectorXd& v, Eigen::VectorXd& rows) const {
  rows.resize(v.size());
  for (std::size_t i = 0; i < row_of_.size(); ++i)
    rows.segment<6>(6 * Eigen::Index(row_of_[i])) = v.segment<6>(6 * Eigen::Index(i));
}

void ResistanceSolver::from_rows(const Eigen::VectorXd& rows, Eigen::VectorXd& v) const {
  v.resize(rows.size());
  for (std::size_t i = 0; i < row_of_.size(); ++i)
    v.segment<6>(6 * Eigen::Index(i)) = rows.segment<6>(6 * Eigen::Index(row_of_[i]));
}

void ResistanceSolver::solve_in_particle_order(const Eigen::VectorXd& b, Eigen::VectorXd& x, HydroResponse& out,
                                               std::string_view context) {
  if (x.size() == b.size())
    to_rows(x, x_);
  else
    x_.resize(0);
  try {
    solve_assembled(b, x_, out, context);
  } catch (...) {
    x.resize(0);  // do not warm-start from a failed solve
    throw;
  }
  from_rows(x_, x);
}

void ResistanceSolver::solve(const Particles& p, const std::vector<int>& species, const std::vector<ActivePair>& pairs,
                             const AmbientFlow& flow, const std::vector<Vec3>& force,
                             const std::vector<Vec3>& torque, SolveResult& out, std::string_view context,
                             const ImplicitContacts& implicit) {
  check(p, species, pairs, force, torque, implicit);
  assemble(p, species, pairs, flow, force, torque, implicit);
  factorize();
  solve_in_particle_order(rhs_, previous_, out, context);
  report_solution(p, species, pairs, flow, previous_, true, out, implicit);
}

void ResistanceSolver::solve_parts(const Particles& p, const std::vector<int>& species,
                                   const std::vector<ActivePair>& pairs, const AmbientFlow& unit_flow,
                                   const AmbientFlow& still_flow, const std::vector<Vec3>& force,
                                   const std::vector<Vec3>& torque, SolveResult& unit_out, SolveResult& force_out,
                                   std::string_view context, const ImplicitContacts& implicit) {
  check(p, species, pairs, force, torque, implicit);
  const std::size_t n = p.size();
  zero_.assign(n, Vec3::Zero());
  assemble(p, species, pairs, unit_flow, zero_, zero_, implicit);
  factorize();
  solve_in_particle_order(rhs_, previous_, unit_out, context);
  report_solution(p, species, pairs, unit_flow, previous_, true, unit_out, implicit);
  // The same matrix; the load of the contact forces alone (Faxen of the still flow, no strain forces).
  forced_rhs_.resize(6 * static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double a = p.radius[i];
    const Eigen::Index r = row_of_[i];
    forced_rhs_.segment<3>(6 * r) =
        force[i] + hydro::stokes_resistance(a).translation * (a * a / 6.0) * still_flow.velocity_laplacian(p.position[i]);
    forced_rhs_.segment<3>(6 * r + 3) = torque[i];
  }
  solve_in_particle_order(forced_rhs_, forced_previous_, force_out, context);
  report_solution(p, species, pairs, still_flow, forced_previous_, false, force_out, implicit);
}

void ResistanceSolver::report_solution(const Particles& p, const std::vector<int>& species,
                                       const std::vector<ActivePair>& pairs, const AmbientFlow& flow,
                                       const Eigen::VectorXd& x, bool strain_driven, SolveResult& out,
                                       const ImplicitContacts& implicit) {
  const std::size_t n = p.size();
  out.velocity.resize(n);
  out.angular_velocity.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto dv = x.segment<6>(6 * static_cast<Eigen::Index>(i));
    out.velocity[i] = flow.velocity(p.position[i]) + dv.head<3>();
    out.angular_velocity[i] = flow.angular_velocity(p.position[i]) + dv.tail<3>();
  }
  out.lubricated_pairs = lubricated_;
  accumulate_stress(p, species, pairs, flow, x, strain_driven, out, implicit);
}

void ResistanceSolver::explicit_forces(const Particles& p, const std::vector<int>& species,
                                       const std::vector<ActivePair>& pairs, const AmbientFlow& flow,
                                       const Eigen::VectorXd& dv, Eigen::VectorXd& force, SolveResult& out) {
  const std::size_t n = p.size();
  if (species.size() != n || dv.size() != 6 * static_cast<Eigen::Index>(n))
    throw InputError("resistance solver: species and dv need one entry (dv: six) per particle");
  zero_.assign(n, Vec3::Zero());
  assemble(p, species, pairs, flow, zero_, zero_);
  to_rows(dv, x_);
  matrix_.multiply(x_, check_);
  x_ = rhs_ - check_;
  from_rows(x_, force);
  previous_ = dv;
  out.iterations = 0;
  out.residual = 0.0;
  report_solution(p, species, pairs, flow, previous_, true, out);
}

double ResistanceSolver::relaxation_rate(const std::vector<double>& mass, const std::vector<double>& moment) const {
  double rate = 0.0;
  for (std::size_t i = 0; i < matrix_.block_rows(); ++i) {  // particle i, row r
    const std::size_t r = row_of_[i];
    Vector6 row = matrix_.plain_diagonal(r).cwiseAbs().rowwise().sum();
    for (const auto* e = matrix_.row_begin(r); e != matrix_.row_end(r); ++e) {
      const Matrix6 c = matrix_.plain_coupling(e->link);
      row += e->transposed ? Vector6(c.transpose().cwiseAbs().rowwise().sum()) : Vector6(c.cwiseAbs().rowwise().sum());
    }
    rate = std::max({rate, row.head<3>().maxCoeff() / mass[i], row.tail<3>().maxCoeff() / moment[i]});
  }
  return rate;
}

Vec3 ResistanceSolver::self_force(std::size_t l, const Vec3& n, const Vector6& dv_j) const {
  const PairFormForceOnJ& f = compact_on_j_[l];
  const Vec3 u = dv_j.head<3>(), w = dv_j.tail<3>();
  Vec3 out = f.a_t * u + ((f.a_n - f.a_t) * n.dot(u)) * n + f.b * n.cross(w);
  if (const SlipForm* s = matrix_.slip(l)) {
    const SlipOnJ& sj = slip_on_j_[matrix_.slip_of()[l]];
    out += (sj.a * s->t.dot(u) + sj.b * n.cross(s->t).dot(w)) * s->t;
  }
  return out;
}

void ResistanceSolver::accumulate_stress(const Particles& p, const std::vector<int>& species,
                                         const std::vector<ActivePair>& pairs, const AmbientFlow& flow,
                                         const Eigen::VectorXd& x, bool strain_driven, SolveResult& out,
                                         const ImplicitContacts& implicit) {
  const std::ptrdiff_t np = static_cast<std::ptrdiff_t>(pairs.size());
  // Pair form: the lubrication forces on j are not kept (24 B a pair) but formed again as the stress is summed.
  const bool compact = matrix_.storage() == CouplingStorage::pair_form;
  if (compact)
    out.lubrication_force_on_j.clear();
  else
    resize_with_headroom(out.lubrication_force_on_j, np);
  if (implicit.enabled())
    out.contact_change_on_j.assign(np, Vec3::Zero());
  else
    out.contact_change_on_j.clear();
  const bool dipole = params_.lubrication_stress == LubricationStress::force_dipole;
  if (!dipole) pair_stress_.resize(np);
  // F_j^lub = -(R_ji dV_i + R_jj dV_j) + (R_FE : E)_j from the stored blocks, less the implicit contact change (the
  // blocks hold lubrication + implicit contact terms).
  auto force_on_j = [&](std::ptrdiff_t k) {
    const ActivePair& pr = pairs[k];
    const std::int32_t l = pair_link_[k];
    const Vector6 dv_i = x.segment<6>(6 * static_cast<Eigen::Index>(pr.i));
    const Vector6 dv_j = x.segment<6>(6 * static_cast<Eigen::Index>(pr.j));
    Vec3 f_j = -(matrix_.coupling_transpose_times(l, dv_i).head<3>() +
                 (compact ? self_force(l, pr.geometry().n, dv_j) : Vec3(on_j_[l].self_force_rows * dv_j)));
    if (strain_driven) f_j += compact ? compact_on_j_[l].strain_force : on_j_[l].strain_force;
    if (stiff(implicit, k)) f_j -= out.contact_change_on_j[k];
    return f_j;
  };
  // Each pair writes its own slots.
#pragma omp parallel for schedule(static) if (np > 256)
  for (std::ptrdiff_t k = 0; k < np; ++k) {
    const ActivePair& pr = pairs[k];
    if (pair_link_[k] < 0) {
      if (!compact) out.lubrication_force_on_j[k].setZero();
      if (!dipole) pair_stress_[k].setZero();
      continue;
    }
    const Vector6 dv_i = x.segment<6>(6 * static_cast<Eigen::Index>(pr.i));
    const Vector6 dv_j = x.segment<6>(6 * static_cast<Eigen::Index>(pr.j));
    if (stiff(implicit, k)) {
      hydro::Vector12 dv;
      dv << dv_i, dv_j;
      out.contact_change_on_j[k] =
          contact_step(pr.geometry(), p.position[pr.i], (*implicit.stiffness)[k], implicit.dt, flow).force_change_on_j(dv);
    }
    if (!compact) out.lubrication_force_on_j[k] = force_on_j(k);
    if (!dipole) {
      hydro::PairMotion m;
      m.du_i = dv_i.head<3>();
      m.dw_i = dv_i.tail<3>();
      m.du_j = dv_j.head<3>();
      m.dw_j = dv_j.tail<3>();
      m.e_i = flow.strain_rate(p.position[pr.i]);
      m.e_j = flow.strain_rate(p.position[pr.j]);
      const hydro::PairHydroForce h = law_(species[pr.i], species[pr.j]).evaluate(pr.geometry().n, pr.gap(), m);
      pair_stress_[k] = h.stresslet_i + h.stresslet_j;
    }
  }
  out.stress.clear();
  Mat3& lub = out.stress[Contribution::lubrication];
  // In list order; pairs beyond the outer cutoff add exact zeros and are skipped.
  if (dipole) {
    for (std::ptrdiff_t k = 0; k < np; ++k)
      if (pair_link_[k] >= 0)
        lub += -sym_outer(pairs[k].d, compact ? force_on_j(k) : out.lubrication_force_on_j[k]);
  } else {
    for (const Mat3& s : pair_stress_) lub += s;
  }
  if (implicit.enabled())
    for (std::ptrdiff_t k = 0; k < np; ++k)
      if (stiff(implicit, k)) add_contact_change_virial(pairs[k].geometry(), out.contact_change_on_j[k], out.stress);
  Mat3& hyd = out.stress[Contribution::hydrodynamic];
  for (std::size_t i = 0; i < p.size(); ++i) hyd += hydro::stokes_stresslet(p.radius[i], p.position[i], flow);
}

}  // namespace suspend

#include "dem/integrate/pairwise_models.hpp"

#include <numbers>

#include "core/error.hpp"
#include "dem/hydro/stokes_drag.hpp"
#include "dem/simulation.hpp"

namespace suspend {

using std::numbers::pi;

namespace {
// Stokes stresslet sums of the particles in the flow f (paper 000 eq. 9a).
template <class Flow>
void add_stokes_stresslets(const Particles& p, const Flow& f, StressTensors& sums) {
  Mat3& h = sums[Contribution::hydrodynamic];
  for (std::size_t i = 0; i < p.size(); ++i) h += hydro::stokes_stresslet(p.radius[i], p.position[i], f);
}
}  // namespace

void StokesDragModel::respond(const HydroLoad& load, double rate, bool loaded, HydroResponse& out) const {
  const Particles& p = load.particles;
  const std::size_t n = p.size();
  const AmbientFlow f = flow_.ambient(rate, load.box.length().y());
  out.velocity.resize(n);
  out.angular_velocity.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = p.radius[i];
    out.velocity[i] = hydro::faxen_velocity(a, p.position[i], f);
    out.angular_velocity[i] = f.angular_velocity(p.position[i]);
    if (loaded) {
      out.velocity[i] += load.force[i] / (6.0 * pi * a);
      out.angular_velocity[i] += load.torque[i] / (8.0 * pi * a * a * a);
    }
  }
  out.stress = {};
  add_stokes_stresslets(p, f, out.stress);
}

HydroResponse& StokesDragModel::solve(const HydroLoad& load, double rate) {
  respond(load, rate, true, out_);
  return out_;
}

std::pair<HydroResponse&, HydroResponse&> StokesDragModel::solve_parts(const HydroLoad& load) {
  respond(load, 1.0, false, out_);
  respond(load, 0.0, true, force_out_);
  return {out_, force_out_};
}

PairwiseResistanceModel::PairwiseResistanceModel(const Particles& p, const Flow& flow,
                                                 const ResistanceSolverParams& params)
    : flow_(flow), params_(params), classes_(p.radius), solver_(classes_.radius, params) {}

HydroResponse& PairwiseResistanceModel::solve(const HydroLoad& load, double rate) {
  const Particles& p = load.particles;
  solver_.solve(p, classes_.of_particle, load.pairs, flow_.ambient(rate, load.box.length().y()),
                load.force, load.torque, out_, load.where, load.implicit);
  return out_;
}

std::pair<HydroResponse&, HydroResponse&> PairwiseResistanceModel::solve_parts(const HydroLoad& load) {
  const double ly = load.box.length().y();
  // Velocities, stress and the implicit contact changes are linear in (gammadot, F): one matrix, two loads.
  solver_.solve_parts(load.particles, classes_.of_particle, load.pairs, flow_.ambient(1.0, ly),
                      flow_.ambient(0.0, ly), load.force, load.torque, out_, force_out_, load.where,
                      load.implicit);
  return {out_, force_out_};
}

std::vector<double> PairwiseResistanceModel::warm_start_state() const {
  const Eigen::VectorXd& dv = solver_.disturbance();
  std::vector<double> s(dv.data(), dv.data() + dv.size());
  const Eigen::VectorXd& dc = solver_.forced_disturbance();
  if (dc.size() == dv.size()) s.insert(s.end(), dc.data(), dc.data() + dc.size());
  return s;
}

void PairwiseResistanceModel::set_warm_start_state(const std::vector<double>& state, std::size_t n, bool parts) {
  const auto size = static_cast<Eigen::Index>(6 * n);
  if (state.size() >= 6 * n) solver_.set_warm_start(Eigen::Map<const Eigen::VectorXd>(state.data(), size));
  if (parts && state.size() == 12 * n)
    solver_.set_forced_warm_start(Eigen::Map<const Eigen::VectorXd>(state.data() + 6 * n, size));
}

ExplicitPairwiseModel::ExplicitPairwiseModel(const Particles& p, const Flow& flow, bool lubrication,
                                             const ResistanceSolverParams& params)
    : flow_(flow), lubrication_range_(params.lubrication.outer_cutoff), classes_(p.radius) {
  if (lubrication) explicit_.emplace(classes_.radius, params.lubrication, params.lubrication_stress);
}

const ExplicitResponse& ExplicitPairwiseModel::explicit_forces(const HydroLoad& load, double rate,
                                                               const Eigen::VectorXd& dv,
                                                               const std::vector<double>& mass,
                                                               const std::vector<double>& moment) {
  const Particles& p = load.particles;
  const AmbientFlow f = flow_.ambient(rate, load.box.length().y());
  if (explicit_) {
    explicit_->evaluate(p, classes_.of_particle, load.pairs, f, dv, mass, moment, out_);
    return out_;
  }
  // Stokes drag at the given velocities: F = -6 pi a (dU - (a^2/6) lap U_inf), T = -8 pi a^3 dOmega.
  const std::size_t n = p.size();
  out_.force.resize(6 * static_cast<Eigen::Index>(n));
  out_.relaxation_rate = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = p.radius[i];
    const hydro::StokesResistance r = hydro::stokes_resistance(a);
    const Vec3 du = dv.segment<3>(6 * i) - (a * a / 6.0) * f.velocity_laplacian(p.position[i]);
    out_.force.segment<3>(6 * i) = -r.translation * du;
    out_.force.segment<3>(6 * i + 3) = -r.rotation * dv.segment<3>(6 * i + 3);
    out_.relaxation_rate = std::max({out_.relaxation_rate, r.translation / mass[i], r.rotation / moment[i]});
  }
  out_.stress = {};
  add_stokes_stresslets(p, f, out_.stress);
  return out_;
}

void check_pairwise_model(const SimulationParams& params) {
  params.validate();
  if (params.time_step.implicit_contacts && !params.lubrication)
    throw InputError("run.time_step.contacts = implicit needs hydrodynamics.lubrication.enabled = true (the "
                     "resistance solve) or hydrodynamics.model = fcm");
}

std::unique_ptr<HydrodynamicModel> make_pairwise_model(const Particles& p, const SimulationParams& params) {
  check_pairwise_model(params);
  if (params.integrator == Integrator::inertial)
    return std::make_unique<ExplicitPairwiseModel>(p, params.flow, params.lubrication, params.resistance);
  if (params.lubrication) return std::make_unique<PairwiseResistanceModel>(p, params.flow, params.resistance);
  return std::make_unique<StokesDragModel>(params.flow);
}

}  // namespace suspend

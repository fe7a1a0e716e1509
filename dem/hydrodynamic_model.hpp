// The hydrodynamic part of a time step, as the one step of dem/simulation.hpp sees it: given the particles, the
// contact (and surface) forces on them and the imposed flow at a shear rate, a model returns the velocities and
// the hydrodynamic stress sums. Models (docs/architecture.md section 2):
//   StokesDragModel          drag + Faxen alone              (dem/integrate/stokes_drag_model.hpp)
//   PairwiseResistanceModel  + pairwise lubrication, solved  (dem/integrate/pairwise_resistance_model.hpp)
//   ExplicitPairwiseModel    inertial: forces at given velocities, drag alone or with lubrication
//                                                            (dem/integrate/explicit_pairwise_model.hpp)
//   FcmModel       FCM + sub-grid lubrication      (coupling/fcm_model.hpp)
// Flow control is not the model's: under imposed stress the step asks for the unit-rate and the force-driven parts
// (every model is linear in (gammadot, F)) and picks the rate itself. One virtual call per step, none per pair.
// An overdamped step asks a model for a solve (OverdampedModel), an explicit (inertial) step for forces at given
// velocities (InertialModel); each model implements the one interface it has.
// Units: eta_0 = 1, lengths in a_1, time in 1/gammadot_ref.
#pragma once
#include <Eigen/Dense>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/box.hpp"
#include "core/particles.hpp"
#include "core/stress.hpp"
#include "dem/integrate/implicit_contacts.hpp"
#include "dem/pair_forces.hpp"

namespace suspend {

// Velocities and hydrodynamic stress of one overdamped solve.
struct HydroResponse {
  std::vector<Vec3> velocity, angular_velocity;  // lab frame, per particle
  std::vector<Vec3> contact_change_on_j;         // implicit contacts: -dt S u_c per pair of the list (else empty)
  // Sums over particles and pairs, not divided by V and without the fluid's 2 E_inf: hydrodynamic (the particles'
  // stresslets), lubrication (pair terms), and with implicit contacts the virial of contact_change_on_j in the
  // contact parts; other parts zero.
  StressTensors stress;
  int iterations = 0;     // linear-solver iterations
  double residual = 0.0;  // relative residual of the returned solution

  // The solution for (gammadot, F) from this unit-rate part and the force-driven part: this = rate this + force.
  void combine(double rate, const HydroResponse& force_part) {
    for (std::size_t i = 0; i < velocity.size(); ++i) {
      velocity[i] = rate * velocity[i] + force_part.velocity[i];
      angular_velocity[i] = rate * angular_velocity[i] + force_part.angular_velocity[i];
    }
    for (std::size_t c = 0; c < contribution_count; ++c)
      stress.part[c] = rate * stress.part[c] + force_part.stress.part[c];
    for (std::size_t k = 0; k < contact_change_on_j.size(); ++k)
      contact_change_on_j[k] = rate * contact_change_on_j[k] + force_part.contact_change_on_j[k];
    iterations += force_part.iterations;
    residual = std::max(residual, force_part.residual);
  }
};

// Hydrodynamic forces at given velocities (inertial integrator, paper 000 eq. 15c).
struct ExplicitResponse {
  Eigen::VectorXd force;          // 6 per particle: force, then torque, ON the particle
  StressTensors stress;           // sums as in HydroResponse
  double relaxation_rate = 0.0;   // bound on the fastest rate of M^-1 R (the explicit step needs dt < 2 / rate)
};

// What the model balances in this step.
struct HydroLoad {
  const Particles& particles;
  const std::vector<ActivePair>& pairs;  // the contact stage's list (any gap)
  const std::vector<Vec3>& force;        // contact and surface forces ON each particle
  const std::vector<Vec3>& torque;
  const Box& box;
  ImplicitContacts implicit;       // run.time_step.contacts = implicit: the stiffnesses and this step's dt
  std::int64_t step = 0;
  bool rate_changed = false;       // the imposed rate differs from the last step's (oscillation, reversal)
  std::string where;               // "step N, strain S", for error messages
};

class HydrodynamicModel {
 public:
  virtual ~HydrodynamicModel() = default;
  // Neighbour-list range the model's pair terms need (0: none).
  virtual double pair_range() const { return 0.0; }
  // Everything the next solve's warm start depends on (checkpointed, so a restart continues bit for bit), and
  // its restoration: `parts` when the next solves are solve_parts. A state that does not fit is ignored.
  virtual std::vector<double> warm_start_state() const { return {}; }
  virtual void set_warm_start_state(const std::vector<double>& /*state*/, std::size_t /*n*/, bool /*parts*/) {}
};

// What an overdamped step asks (run.integrator = overdamped): the velocities that balance the forces.
class OverdampedModel : public HydrodynamicModel {
 public:
  // Imposed rate: the velocities in the flow at `rate` with the load's forces. The response is the model's own and
  // stays valid until its next call. Throws NumericalError (message starts with load.where).
  virtual HydroResponse& solve(const HydroLoad& load, double rate) = 0;
  // Imposed stress: the unit-rate part (no forces) and the force-driven part (rate 0).
  virtual std::pair<HydroResponse&, HydroResponse&> solve_parts(const HydroLoad& load) = 0;
};

// What an explicit step asks (run.integrator = inertial): the hydrodynamic forces at disturbance velocities dv (6
// per particle, lab velocity minus U_inf, Omega_inf) in the flow at `rate`; mass and moment per particle for the
// rate bound.
class InertialModel : public HydrodynamicModel {
 public:
  virtual const ExplicitResponse& explicit_forces(const HydroLoad& load, double rate, const Eigen::VectorXd& dv,
                                                  const std::vector<double>& mass,
                                                  const std::vector<double>& moment) = 0;
};

// Radii classes: the distinct radii in increasing order and each particle's class (pair tables are per class).
struct RadiusClasses {
  std::vector<double> radius;
  std::vector<int> of_particle;
  explicit RadiusClasses(const std::vector<double>& particle_radius);
};

}  // namespace suspend

// Linearly implicit (backward Euler) contact springs for the overdamped step (docs/overdamped.md, "Implicit
// contacts"). Both engines use it: the pairwise resistance solve and the FCM coupled solve.
//
// Over a step dt a contact's elastic force changes by dF_j = -dt S u_c (to first order), with u_c the velocity of
// the contact point of j relative to i and S = k_n n n + k_t (I - n n) its tangent stiffness (PairForce::
// normal_stiffness, tangential_stiffness: k_t only while the spring sticks). Putting the end-of-step force
// F_c - dt S u_c into the force balance instead of F_c makes the stiff contact modes unconditionally stable, so the
// step is bounded by accuracy (displacement per step) instead of by 6 pi eta a / k.
//
// Kinematics (dem/contact/pair_geometry.hpp, RelativeMotion::contact_velocity): with the generalised pair velocity
// V = (U_i, Omega_i, U_j, Omega_j),
//   u_c = C V = (U_j - U_i) + l_i n x Omega_i + l_j n x Omega_j,    C = [-I, l_i [n]x, I, l_j [n]x],
// and a force F on j at the contact point (-F on i, torques from the lever arms as PairForce::add_tangential) is the
// generalised force C^T F. So the implicit terms are the 12x12 resistance dt C^T S C (symmetric positive
// semi-definite) and the generalised force -C^T (dt S) u_c,inf of the ambient flow's contact velocity.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "core/stress.hpp"
#include "core/vec.hpp"
#include "dem/contact/pair_geometry.hpp"
#include "core/ambient_flow.hpp"
#include "dem/hydro/lubrication.hpp"
#include "dem/pair_forces.hpp"

namespace suspend {

// Linearly implicit contacts (dem/integrate/implicit_contacts.hpp): the contact forces the caller passes are those
// at the start of the step; the solve adds their change over dt, -dt S u_c, to the force balance.
struct ImplicitContacts {
  const std::vector<ContactStiffness>* stiffness = nullptr;  // per pair of the list; null: explicit contacts
  double dt = 0.0;
  bool enabled() const { return stiffness != nullptr; }
};

using ContactOperator = Eigen::Matrix<double, 3, 12>;

// C of the header: contact velocity of j relative to i from (U_i, Omega_i, U_j, Omega_j).
inline ContactOperator contact_velocity_operator(const PairGeometry& g) {
  Mat3 nx;
  nx << 0.0, -g.n.z(), g.n.y(), g.n.z(), 0.0, -g.n.x(), -g.n.y(), g.n.x(), 0.0;  // nx w = n x w
  ContactOperator c;
  c << -Mat3::Identity(), g.lever_i() * nx, Mat3::Identity(), g.lever_j() * nx;
  return c;
}

// dt S = dt (k_n n n + k_t (I - n n - t t)), t the slip direction of a sliding contact (zero while it sticks).
inline Mat3 step_stiffness(const Vec3& n, const ContactStiffness& k, double dt) {
  const Mat3 nn = n * n.transpose();
  const Mat3 tt = k.slip_direction * k.slip_direction.transpose();
  return dt * (k.normal * nn + k.tangential * (Mat3::Identity() - nn - tt));
}

// Contact velocity of the ambient flow, C V_inf, with j's image at x_i + d (Lees-Edwards: the image velocity
// follows from the unwrapped position).
inline Vec3 ambient_contact_velocity(const PairGeometry& g, const Vec3& x_i, const AmbientFlow& flow) {
  const Vec3 x_j = x_i + g.d;
  return (flow.velocity(x_j) - flow.velocity(x_i)) +
         g.n.cross(g.lever_i() * flow.angular_velocity(x_i) + g.lever_j() * flow.angular_velocity(x_j));
}

// Linearised contact of one pair over the step: its resistance and the ambient flow's generalised force.
struct ContactStep {
  ContactOperator c;
  Mat3 s;       // dt S
  Vec3 u_inf;   // C V_inf
  hydro::Matrix12 resistance() const { return c.transpose() * s * c; }
  hydro::Vector12 ambient_force() const { return -(c.transpose() * (s * u_inf)); }
  // Change of the contact force on j over the step for lab-frame pair velocities V = V_inf + dV.
  Vec3 force_change_on_j(const hydro::Vector12& dv) const { return -(s * (u_inf + c * dv)); }
};

// Adds the virial -sym(d dF) of a contact force change on j to the sums, its normal part to contact_normal and
// its tangential part to contact_tangential.
inline void add_contact_change_virial(const PairGeometry& g, const Vec3& change, StressTensors& sums) {
  const Vec3 normal = change.dot(g.n) * g.n;
  sums[Contribution::contact_normal] += -sym_outer(g.d, normal);
  sums[Contribution::contact_tangential] += -sym_outer(g.d, Vec3(change - normal));
}

inline ContactStep contact_step(const PairGeometry& g, const Vec3& x_i, const ContactStiffness& k, double dt,
                                const AmbientFlow& flow) {
  return {contact_velocity_operator(g), step_stiffness(g.n, k, dt), ambient_contact_velocity(g, x_i, flow)};
}

}  // namespace suspend

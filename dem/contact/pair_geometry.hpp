// What every pair law sees and returns (the contract of the shared contact module, docs/contact.md).
//
// Conventions, used by every law:
//  * d = r_j - r_i (Lees-Edwards minimum image), n = d / |d| points from i to j.
//  * gap h = |d| - (a_i + a_j): negative when the spheres overlap; overlap delta = -h.
//  * Forces are returned as the force ON j; the driver applies -F to i (Newton's third law is structural).
//  * Torques are returned for both particles (they differ for unequal radii).
//  * The stresslet of a pair is S = -sym(d F_j^T) per contribution (virial); divided by the volume it gives Sigma,
//    so a repulsive force yields a positive particle pressure Pi = -tr(Sigma)/3 (docs/units.md, Conventions).
// Units: lengths in a_1, forces in eta_0 gammadot a_1^2, velocities in gammadot a_1 (docs/units.md).
#pragma once
#include <array>

#include "core/stress.hpp"
#include "core/vec.hpp"

namespace suspend {

struct PairGeometry {
  Vec3 d;          // r_j - r_i
  Vec3 n;          // d / |d|
  double r;        // |d|
  double a_i, a_j;
  double gap() const { return r - a_i - a_j; }
  // Harmonic radius a-bar = 2 a_i a_j / (a_i + a_j) (paper 000, eqs. 6-7 and Appendix B).
  double harmonic_radius() const { return 2.0 * a_i * a_j / (a_i + a_j); }
  // Lever arms from each centre to the contact point, l_i = a_i r / (a_i + a_j) and l_j = a_j r / (a_i + a_j)
  // (paper 004, eq. 11). They add up to r, so a tangential force conserves angular momentum exactly, and a rigid
  // rotation of the pair has zero slip at the contact point, whether the spheres overlap or not.
  double lever_i() const { return a_i * r / (a_i + a_j); }
  double lever_j() const { return a_j * r / (a_i + a_j); }
  static PairGeometry from(const Vec3& d, double a_i, double a_j) {
    const double r = d.norm();
    return {d, d / r, r, a_i, a_j};
  }
};

// Rigid-body motion of the pair; u_j is the velocity of the image of j actually used (Lees-Edwards corrected).
struct RelativeMotion {
  Vec3 u_i, u_j;
  Vec3 omega_i, omega_j;
  // Velocity of the surface of j relative to that of i at the contact point (paper 000, eq. 5 context).
  Vec3 surface_velocity(const PairGeometry& g) const {
    return (u_j - u_i) - (g.a_i * omega_i + g.a_j * omega_j).cross(g.n);
  }
  // The same, evaluated at the contact point (lever arms of paper 004, eq. 11). Differs from surface_velocity by
  // O(gap) and is exactly zero for a rigid rotation of the pair (objective); the frictional laws use it.
  Vec3 contact_velocity(const PairGeometry& g) const {
    return (u_j - u_i) - (g.lever_i() * omega_i + g.lever_j() * omega_j).cross(g.n);
  }
};

// Forces on j split by origin, and the torques on i and j. The stresslet follows from d and each force part.
// The contact law also reports its tangent stiffnesses at this state, for the linearly implicit (backward Euler)
// contact step (docs/overdamped.md): normal_stiffness = dF_n/d(delta) of the elastic normal force, and
// tangential_stiffness = k_t while the tangential spring sticks. While it slides at the Coulomb limit F_max, the force
// -F_max t (t = slip_direction, along the trial stretch) responds only to a turn of the slip: tangential_stiffness is
// then k_t F_max / |k_t xi_trial| and acts across t only (the consistent tangent of the cap, i.e. the derivative of
// -F_max xi/|xi| with respect to xi); 0 when frictionless or absent. Both are zero out of contact; surface forces
// stay explicit and add none.
struct PairForce {
  std::array<Vec3, contribution_count> on_j;
  Vec3 torque_i = Vec3::Zero();
  Vec3 torque_j = Vec3::Zero();
  double normal_stiffness = 0.0;
  double tangential_stiffness = 0.0;
  Vec3 slip_direction = Vec3::Zero();  // sliding: unit vector along the tangential force on j; else zero
  bool sliding = false;  // the tangential force sits at its Coulomb limit (a frictional contact slides)
  PairForce() {
    for (auto& f : on_j) f.setZero();
  }
  Vec3& operator[](Contribution c) { return on_j[static_cast<std::size_t>(c)]; }
  const Vec3& operator[](Contribution c) const { return on_j[static_cast<std::size_t>(c)]; }
  Vec3 total_on_j() const {
    Vec3 t = Vec3::Zero();
    for (const auto& f : on_j) t += f;
    return t;
  }
  PairForce& operator+=(const PairForce& o) {
    for (std::size_t c = 0; c < contribution_count; ++c) on_j[c] += o.on_j[c];
    torque_i += o.torque_i;
    torque_j += o.torque_j;
    return *this;
  }
  // A tangential force on j acting at the contact point: torques (l_i n) x (-F) on i and (-l_j n) x F on j
  // (paper 000 eqs. 4d-4e with the lever arms of paper 004 eq. 11), so tau_i + tau_j + d x F = 0.
  void add_tangential(const PairGeometry& g, const Vec3& f_on_j, Contribution c) {
    (*this)[c] += f_on_j;
    const Vec3 nxf = g.n.cross(f_on_j);
    torque_i -= g.lever_i() * nxf;
    torque_j -= g.lever_j() * nxf;
  }
};

// What a normal sub-model tells the sub-models composed with it (contact_model.hpp): whether the pair is in contact,
// its normal force on j along n (positive = repulsive; the contact_normal contribution, to which the damping sub-model
// adds its force before it is written), and the load that friction, rolling and twisting resistance are
// proportional to (the spring force of the linear laws, plus the damping; the Hertz elastic force, F_n + F_adh, of
// paper 004 eq. 16). A normal law with its own adhesion (JKR) writes that part to the adhesion contribution itself.
struct NormalContact {
  bool active = false;
  double load = 0.0;
  double force = 0.0;
};

// Pair stresslet of one force contribution, S = -sym(d F_j^T) (paper 000 eqs. 9c-9d with F_ij = -F_j). Summed over
// pairs and divided by the volume it gives that contribution's Sigma. Split between the two particles in the
// ratio a_i : a_j when a per-particle stresslet is needed (paper 004, eq. 12; see stresslet_share_i).
inline Mat3 pair_stresslet(const PairGeometry& g, const Vec3& f_on_j) { return -sym_outer(g.d, f_on_j); }
inline Mat3 pair_stresslet(const PairGeometry& g, const PairForce& f, Contribution c) {
  return pair_stresslet(g, f[c]);
}
inline double stresslet_share_i(const PairGeometry& g) { return g.a_i / (g.a_i + g.a_j); }

}  // namespace suspend

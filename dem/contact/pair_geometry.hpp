// What every pair law sees and returns (the contract of the shared contact module, DESIGN.md section 5).
//
// Conventions, used by every law:
//  * d = r_j - r_i (Lees-Edwards minimum image), n = d / |d| points from i to j.
//  * gap h = |d| - (a_i + a_j): negative when the spheres overlap; overlap delta = -h.
//  * Forces are returned as the force ON j; the driver applies -F to i (Newton's third law is structural).
//  * Torques are returned for both particles (they differ for unequal radii).
//  * The stresslet of a pair is S = -sym(d F_j^T) per contribution (virial); divided by the volume it gives Sigma,
//    so a repulsive force yields a positive particle pressure Pi = -tr(Sigma)/3 (DESIGN.md section 3).
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
};

// Forces on j split by origin, and the torques on i and j. The stresslet follows from d and each force part.
struct PairForce {
  std::array<Vec3, contribution_count> on_j;
  Vec3 torque_i = Vec3::Zero();
  Vec3 torque_j = Vec3::Zero();
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
};

}  // namespace suspend

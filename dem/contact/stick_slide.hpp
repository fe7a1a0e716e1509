// Stick/slide update of a linear tangential spring with a Coulomb-type cap (paper 000 eq. 5, Luding 2008 sec. 2.2).
//
// Each step, for a spring of stiffness k and an allowed force magnitude F_max >= 0:
//  1. rotate the stored stretch onto the current tangent plane (normal n) keeping its length, so a pair that turns
//     as a rigid body carries its spring with it (frame invariance; Luding 2008 eq. 7),
//  2. integrate the tangential velocity: xi += u dt (u is already tangential),
//  3. trial force on j F = -k xi; if |F| > F_max the contact slides: F = F_max F/|F| and xi = -F/k, the stretch
//     the spring would have at the Coulomb limit (eq. 5, second line). F_max = 0 gives a frictionless contact and
//     resets the stretch.
// Reversal: when the step's slip u dt carries the stretch through zero and out beyond the limit on the other side
// (the trial stretch points against the stored one), the step did not resolve the spring: its velocities were found
// with the old force (explicit, or a sliding contact's zero tangent stiffness in the implicit step,
// docs/overdamped.md 4b), which pushed the contact back across the whole elastic range. A backward-Euler spring
// would have unloaded and stuck. The contact sticks at the smallest stretch along the step's path instead (the part
// of the stored stretch across the slip), so the next step holds it with its stiffness; left alone, such a contact
// slides back and forth across the range every step (a period-2 chatter at slip speeds far above the flow's; docs/
// overdamped.md 4c). A step that resolves the spring (|u dt| < 2 F_max / k) never reverses this way, so the rule
// leaves every converged trajectory unchanged.
// Used for the tangential (sliding) spring and, with the rolling velocity, for the rolling spring.
#pragma once
#include <cmath>

#include "core/vec.hpp"

namespace suspend {

struct StickSlideResult {
  Vec3 force_on_j;     // -k xi after the cap
  bool sliding;        // the Coulomb cap was active this step
  double trial = 0.0;  // |k xi| before the cap (sliding: > F_max)
};

inline void rotate_onto_tangent_plane(Vec3& xi, const Vec3& n) {
  const double len2 = xi.squaredNorm();
  if (len2 == 0.0) return;
  xi -= xi.dot(n) * n;
  const double proj2 = xi.squaredNorm();
  // A stretch exactly along the new normal (the pair turned by 90 degrees in one step) has no tangential image.
  xi = proj2 > 0.0 ? Vec3(xi * std::sqrt(len2 / proj2)) : Vec3(Vec3::Zero());
}

inline StickSlideResult stick_slide(Vec3& xi, const Vec3& n, const Vec3& u_tangential, double dt, double k,
                                    double f_max) {
  rotate_onto_tangent_plane(xi, n);
  const Vec3 start = xi, slip = u_tangential * dt;
  xi += slip;
  if (xi.dot(start) < 0.0 && k * xi.norm() > f_max) xi = start - (start.dot(slip) / slip.squaredNorm()) * slip;
  const Vec3 trial = -k * xi;
  const double f = trial.norm();
  if (f <= f_max) return {trial, false, f};
  if (f_max <= 0.0) {
    xi.setZero();
    return {Vec3::Zero(), true, f};
  }
  const Vec3 capped = (f_max / f) * trial;
  xi = -capped / k;
  return {capped, true, f};
}

}  // namespace suspend

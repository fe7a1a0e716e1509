// Isolated-sphere Stokes resistance with the Faxen corrections (paper 000 eq. A.1 and eq. 9a; Kim & Karrila ch. 3):
//   F = -6 pi eta a (U - U_inf(x) - (a^2/6) lap U_inf(x))
//   T = -8 pi eta a^3 (Omega - Omega_inf(x))
//   S = (20/3) pi eta a^3 (E_inf(x) + (a^2/10) lap E_inf(x))
// F and T act ON the sphere from the fluid; S is the stresslet the sphere exerts on the fluid (its particle-stress
// contribution, S / V). The Laplacian terms vanish for linear flows and matter for the wavy shear (paper 000 eq. 17).
// Units: eta_0 = 1, lengths in a_1, so F in eta_0 gammadot a_1^2, T and S in eta_0 gammadot a_1^3.
// Flow is any type with velocity, angular_velocity, strain_rate, velocity_laplacian, strain_rate_laplacian (x)
// (ambient_flow.hpp).
#pragma once
#include <numbers>

#include "core/vec.hpp"

namespace suspend::hydro {

struct StokesResistance {
  double translation;  // 6 pi a: diagonal of R_Stokes for the velocity
  double rotation;     // 8 pi a^3: diagonal of R_Stokes for the angular velocity
};
inline StokesResistance stokes_resistance(double a) {
  return {6.0 * std::numbers::pi * a, 8.0 * std::numbers::pi * a * a * a};
}

// The velocity a force-free sphere would take: U_inf + (a^2/6) lap U_inf (Faxen's first law).
template <class Flow>
Vec3 faxen_velocity(double a, const Vec3& x, const Flow& flow) {
  return flow.velocity(x) + (a * a / 6.0) * flow.velocity_laplacian(x);
}

// Stokes stresslet of a rigid sphere in the ambient flow (Faxen's third law).
template <class Flow>
Mat3 stokes_stresslet(double a, const Vec3& x, const Flow& flow) {
  return (20.0 / 3.0) * std::numbers::pi * a * a * a *
         (flow.strain_rate(x) + (a * a / 10.0) * flow.strain_rate_laplacian(x));
}

struct StokesDragResult {
  Vec3 force;
  Vec3 torque;
  Mat3 stresslet;
};

template <class Flow>
StokesDragResult stokes_drag(double a, const Vec3& x, const Vec3& u, const Vec3& omega, const Flow& flow) {
  const StokesResistance r = stokes_resistance(a);
  return {-r.translation * (u - faxen_velocity(a, x, flow)), -r.rotation * (omega - flow.angular_velocity(x)),
          stokes_stresslet(a, x, flow)};
}

}  // namespace suspend::hydro

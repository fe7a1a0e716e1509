// The imposed (ambient) flow the particles are suspended in, as one value both hydrodynamic models take: a linear
// flow with velocity-gradient tensor L (L_ij = dU_i / dx_j), plus the wave of paper 000 eq. 17:
//   U_inf = L x + (U sin(k y), 0, 0),  k = 2 pi n / L_y
//   the local gradient G(x) = L + U k cos(k y) e_x e_y,  E_inf = sym G,  Omega_inf = (1/2) curl U_inf
//   lap U_inf = (-U k^2 sin(k y), 0, 0),  lap E_inf,xy = -U k^3 cos(k y)/2   (the Faxen terms, paper 000 eq. A.1, 9a)
// and the ambient part of the bulk stress, 2 E_inf (of the linear flow; the wave averages to zero over the box).
// Simple shear (x flow, y gradient, z vorticity) is L = gammadot e_x e_y: Omega_inf = (0, 0, -gammadot/2). It is
// the gradient a Lees-Edwards cell carries; other gradients (planar extension) are values too, for boundaries that
// follow them (io/protocols/ and Flow::ambient build it; docs/units.md, Conventions).
// Units: velocities in gammadot_ref a_1, lengths in a_1. A few flops per particle.
#pragma once
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "core/vec.hpp"

namespace suspend {

struct AmbientFlow {
  Mat3 gradient = Mat3::Zero();  // L
  double amplitude = 0.0;        // U (paper 000 Table 3: 20 gammadot a_0); 0: a linear flow
  int periods = 1;               // n, periods across the box height
  double box_height = 1.0;       // L_y

  static AmbientFlow simple_shear(double rate) {
    AmbientFlow f;
    f.gradient(0, 1) = rate;
    return f;
  }
  static AmbientFlow wavy_shear(double rate, double amplitude, int periods, double box_height) {
    AmbientFlow f = simple_shear(rate);
    f.amplitude = amplitude;
    f.periods = periods;
    f.box_height = box_height;
    return f;
  }

  void validate() const {
    if (!gradient.allFinite()) throw InputError("flow: the velocity gradient must be finite");
    if (!std::isfinite(amplitude)) throw InputError("flow.amplitude must be finite");
    if (periods < 0) throw InputError("flow.periods = " + std::to_string(periods) + " must be >= 0");
    if (!(box_height > 0.0)) throw InputError("flow.box_height = " + std::to_string(box_height) + " must be > 0");
  }
  // Simple shear (only L_xy set) without a wave: what the Lees-Edwards FCM grid can carry.
  bool is_simple_shear() const {
    Mat3 rest = gradient;
    rest(0, 1) = 0.0;
    return amplitude == 0.0 && rest.isZero(0.0);
  }
  // L_xy: the shear rate of simple shear, the rate the Lees-Edwards images move at.
  double shear_rate() const { return gradient(0, 1); }
  double wavenumber() const { return 2.0 * std::numbers::pi * periods / box_height; }

  // G(x) = dU_inf / dx at x.
  Mat3 local_gradient(const Vec3& x) const {
    Mat3 g = gradient;
    if (amplitude != 0.0) g(0, 1) += amplitude * wavenumber() * std::cos(wavenumber() * x.y());
    return g;
  }
  Vec3 velocity(const Vec3& x) const {
    Vec3 u = gradient * x;
    if (amplitude != 0.0) u.x() += amplitude * std::sin(wavenumber() * x.y());
    return u;
  }
  // Omega_inf = half the vorticity.
  Vec3 angular_velocity(const Vec3& x) const { return angular_velocity_of(local_gradient(x)); }
  Mat3 strain_rate(const Vec3& x) const {
    const Mat3 g = local_gradient(x);
    return 0.5 * (g + g.transpose());
  }
  // Of the linear flow (uniform): E_inf, Omega_inf and the ambient bulk stress 2 E_inf.
  Mat3 strain_rate() const { return 0.5 * (gradient + gradient.transpose()); }
  Vec3 angular_velocity() const { return angular_velocity_of(gradient); }
  Mat3 ambient_stress() const { return 2.0 * strain_rate(); }

  Vec3 velocity_laplacian(const Vec3& x) const {
    const double k = wavenumber();
    return {-amplitude * k * k * std::sin(k * x.y()), 0.0, 0.0};
  }
  Mat3 strain_rate_laplacian(const Vec3& x) const {
    const double k = wavenumber();
    Mat3 e = Mat3::Zero();
    e(0, 1) = e(1, 0) = -0.5 * amplitude * k * k * k * std::cos(k * x.y());
    return e;
  }

 private:
  // (1/2) curl U for U = G x: Omega_i = (1/2) eps_ijk G_kj.
  static Vec3 angular_velocity_of(const Mat3& g) {
    return 0.5 * Vec3(g(2, 1) - g(1, 2), g(0, 2) - g(2, 0), g(1, 0) - g(0, 1));
  }
};

}  // namespace suspend

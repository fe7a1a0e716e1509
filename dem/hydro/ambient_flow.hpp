// The imposed (ambient) flow the particles are suspended in: simple shear and the wavy shear of paper 000 eq. 17.
//   U_inf = (gammadot y + U sin(k y), 0, 0),  k = 2 pi n / L_y   (U = 0: simple shear, docs/units.md, Conventions)
//   Omega_inf = (1/2) curl U_inf = (0, 0, -(gammadot + U k cos(k y))/2)
//   E_inf,xy = E_inf,yx = (gammadot + U k cos(k y))/2, other components 0 (traceless)
//   lap U_inf = (-U k^2 sin(k y), 0, 0),  lap E_inf,xy = -U k^3 cos(k y)/2   (the Faxen terms, paper 000 eq. A.1, 9a)
// x flow, y gradient, z vorticity. Units: velocities in gammadot_ref a_1, lengths in a_1.
// A small value type: the driver picks one per run (std::variant), evaluation is a few flops per particle.
#pragma once
#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include "core/error.hpp"
#include "core/flow.hpp"
#include "core/vec.hpp"

namespace suspend::hydro {

struct WavyShear {
  double shear_rate = 1.0;  // gammadot
  double amplitude = 0.0;   // U (paper 000 Table 3: 20 gammadot a_0)
  int periods = 1;          // n, periods across the box height
  double box_height = 1.0;  // L_y

  void validate() const {
    if (!std::isfinite(shear_rate)) throw InputError("flow.shear_rate must be finite");
    if (!std::isfinite(amplitude)) throw InputError("flow.amplitude must be finite");
    if (periods < 0) throw InputError("flow.periods = " + std::to_string(periods) + " must be >= 0");
    if (!(box_height > 0.0)) throw InputError("flow.box_height = " + std::to_string(box_height) + " must be > 0");
  }
  double wavenumber() const { return 2.0 * std::numbers::pi * periods / box_height; }
  // d U_x / d y at height y: the local shear rate.
  double local_shear_rate(double y) const { return shear_rate + amplitude * wavenumber() * std::cos(wavenumber() * y); }

  Vec3 velocity(const Vec3& x) const {
    return {shear_rate * x.y() + amplitude * std::sin(wavenumber() * x.y()), 0.0, 0.0};
  }
  // Omega_inf = half the vorticity.
  Vec3 angular_velocity(const Vec3& x) const { return {0.0, 0.0, -0.5 * local_shear_rate(x.y())}; }
  Mat3 strain_rate(const Vec3& x) const { return off_diagonal_xy(0.5 * local_shear_rate(x.y())); }
  Vec3 velocity_laplacian(const Vec3& x) const {
    const double k = wavenumber();
    return {-amplitude * k * k * std::sin(k * x.y()), 0.0, 0.0};
  }
  Mat3 strain_rate_laplacian(const Vec3& x) const {
    const double k = wavenumber();
    return off_diagonal_xy(-0.5 * amplitude * k * k * k * std::cos(k * x.y()));
  }

 private:
  static Mat3 off_diagonal_xy(double v) {
    Mat3 e = Mat3::Zero();
    e(0, 1) = e(1, 0) = v;
    return e;
  }
};

// Simple shear is the wavy shear without a wave; kept as its own name for readability at call sites.
struct SimpleShear : WavyShear {
  explicit SimpleShear(double gammadot = 1.0) : WavyShear{gammadot, 0.0, 0, 1.0} {}
};

// The imposed flow of a run (core/flow.hpp: its shape) at shear rate `rate` in a box of height L_y.
inline WavyShear ambient_flow(const Flow& flow, double rate, double box_height) {
  return {rate, flow.wave_amplitude, flow.wave_periods, box_height};
}

}  // namespace suspend::hydro

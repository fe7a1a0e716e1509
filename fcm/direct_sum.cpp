#include "fcm/direct_sum.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "core/error.hpp"
#include "fcm/envelope.hpp"
#include "fcm/spreading.hpp"

namespace suspend::fcm {
using std::numbers::pi;
namespace {

// 4th-order central difference of f along axis k with step d.
template <class F>
auto derivative(const F& f, const Vec3& r, int k, double d) {
  using Value = std::decay_t<decltype(f(r))>;  // a concrete Eigen type, never a dangling expression
  Vec3 e = Vec3::Zero();
  e[k] = d;
  const Value result = ((f(r - 2.0 * e) - f(r + 2.0 * e)) + 8.0 * (f(r + e) - f(r - e))) / (12.0 * d);
  return result;
}
}  // namespace

Mat3 regularised_stokeslet(const Vec3& rv, double variance) {
  const double c = 1.0 / std::sqrt(2.0 * variance);
  const double r = rv.norm(), x = c * r;
  const double k = c / (4.0 * pi * std::sqrt(pi));
  if (x < 1e-3) {  // series: 4 pi A = (c/sqrt(pi)) (4/3 - 8 x^2/15), B rr = (c/sqrt(pi)) (4/15) c^2 r r^T
    return k * ((4.0 / 3.0 - 8.0 / 15.0 * x * x) * Mat3::Identity() + (4.0 / 15.0) * c * c * rv * rv.transpose());
  }
  const double erf_x = std::erf(x), ex = std::exp(-x * x);
  const double t1 = erf_x / (2.0 * r), t2 = ex / (2.0 * c * std::sqrt(pi) * r * r),
               t3 = erf_x / (4.0 * c * c * r * r * r);
  const double a = (t1 - t2 + t3) / (4.0 * pi), b = (t1 + 3.0 * t2 - 3.0 * t3) / (4.0 * pi);
  return a * Mat3::Identity() + b * rv * rv.transpose() / (r * r);
}

Disturbance direct_sum(std::span<const Vec3> pos, std::span<const double> rad, std::span<const Vec3> forces,
                       std::span<const Vec3> torques, std::span<const Mat3> stresslets) {
  const std::size_t n = pos.size();
  if (rad.size() != n || (!forces.empty() && forces.size() != n) || (!torques.empty() && torques.size() != n) ||
      (!stresslets.empty() && stresslets.size() != n))
    throw InputError("fcm direct sum: one radius, force, torque and stresslet per particle");
  Disturbance out;
  out.velocities.assign(n, Vec3::Zero());
  out.angular_velocities.assign(n, Vec3::Zero());
  out.strain_rates.assign(n, Mat3::Zero());
  for (std::size_t m = 0; m < n; ++m) {
    const double am = rad[m], sm = monopole_width(am), dm = dipole_width(am);
    Vec3 u = Vec3::Zero();
    Mat3 grad = Mat3::Zero();  // the gradient moment A of the pair terms
    for (std::size_t q = 0; q < n; ++q) {
      if (q == m) continue;
      const double sq = monopole_width(rad[q]), dq = dipole_width(rad[q]);
      const Vec3 f = forces.empty() ? Vec3::Zero() : forces[q];
      const Mat3 g = dipole_tensor(torques.empty() ? Vec3::Zero() : torques[q],
                                   stresslets.empty() ? Mat3::Zero() : stresslets[q]);
      const Vec3 r = pos[m] - pos[q];
      const double step = 1e-3 * std::sqrt(sm * sm + dq * dq);
      u += regularised_stokeslet(r, sm * sm + sq * sq) * f;
      // U_i += d_l M_ij G_jl  (monopole envelope of m, dipole envelope of q).
      const auto m_md = [&](const Vec3& x) { return regularised_stokeslet(x, sm * sm + dq * dq); };
      for (int l = 0; l < 3; ++l) u += derivative(m_md, r, l, step) * g.col(l);
      // A_ik -= d_k (M f)_i  (dipole of m, monopole of q).
      const auto mf = [&](const Vec3& x) -> Vec3 { return regularised_stokeslet(x, dm * dm + sq * sq) * f; };
      for (int k = 0; k < 3; ++k) grad.col(k) -= derivative(mf, r, k, step);
      // A_ik -= d_k d_l M_ij G_jl  (dipole of m, dipole of q).
      const auto mg = [&](const Vec3& x) -> Vec3 {
        Vec3 v = Vec3::Zero();
        const auto mdd = [&](const Vec3& y) { return regularised_stokeslet(y, dm * dm + dq * dq); };
        for (int l = 0; l < 3; ++l) v += derivative(mdd, x, l, step) * g.col(l);
        return v;
      };
      for (int k = 0; k < 3; ++k) grad.col(k) -= derivative(mg, r, k, step);
    }
    const Vec3 t = torques.empty() ? Vec3::Zero() : torques[m];
    Mat3 s = stresslets.empty() ? Mat3::Zero() : Mat3(0.5 * (stresslets[m] + stresslets[m].transpose()));
    s.diagonal().array() -= s.trace() / 3.0;  // an isotropic dipole drives no flow
    const Vec3 f = forces.empty() ? Vec3::Zero() : forces[m];
    out.velocities[m] = u + translational_self_mobility(am) * f;
    out.angular_velocities[m] = angular_velocity_of(grad) + rotational_self_mobility(am) * t;
    out.strain_rates[m] = strain_rate_of(grad) - stresslet_self_mobility(am) * s;
  }
  return out;
}

}  // namespace suspend::fcm

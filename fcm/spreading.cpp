#include "fcm/spreading.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fcm/envelope.hpp"

namespace suspend::fcm {
namespace {

double gaussian_norm(double sigma) { return std::pow(2.0 * std::numbers::pi * sigma * sigma, -1.5); }

// Calls point(node, w_m, w_d, d) for every node within the truncation sphere of the envelope whose z plane
// lies in [z_begin, z_end). w_m, w_d are the two Gaussians at the node, d the physical node - centre vector.
// Along x the Gaussians are advanced by the exact recurrence exp(-(d+h)^2/2s^2) = exp(-d^2/2s^2) r,
// r <- r exp(-h^2/s^2), so each node costs a few multiplications instead of two exponentials.
template <class Point>
void visit_support(const ShearedGrid& g, const Envelope& e, int z_begin, int z_end, Point&& point) {
  const double hx = g.spacing.x(), hy = g.spacing.y(), hz = g.spacing.z();
  const double r2 = e.support * e.support;
  const double am = 0.5 / (e.sigma_m * e.sigma_m), ad = 0.5 / (e.sigma_d * e.sigma_d);
  const double cm = gaussian_norm(e.sigma_m), cd = gaussian_norm(e.sigma_d);
  const double qm = std::exp(-2.0 * am * hx * hx), qd = std::exp(-2.0 * ad * hx * hx);
  const int kz0 = static_cast<int>(std::ceil((e.centre.z() - e.support) / hz));
  const int kz1 = static_cast<int>(std::floor((e.centre.z() + e.support) / hz));
  for (int kz = kz0; kz <= kz1; ++kz) {
    const int iz = periodic_index(kz, g.n[2]);
    if (iz < z_begin || iz >= z_end) continue;
    const double dz = kz * hz - e.centre.z();
    const double ry2 = r2 - dz * dz;
    if (ry2 < 0.0) continue;
    const double ry = std::sqrt(ry2);
    const int ky0 = static_cast<int>(std::ceil((e.centre.y() - ry) / hy));
    const int ky1 = static_cast<int>(std::floor((e.centre.y() + ry) / hy));
    for (int ky = ky0; ky <= ky1; ++ky) {
      const double y = ky * hy;
      const double dy = y - e.centre.y();
      const double rx2 = ry2 - dy * dy;
      if (rx2 < 0.0) continue;
      const double rx = std::sqrt(rx2);
      // Row centre in sheared coordinates: node x' = kx h_x is at physical x' + gamma_t y.
      const double xc = e.centre.x() - g.shear_fraction * y;
      const int kx0 = static_cast<int>(std::ceil((xc - rx) / hx));
      const int kx1 = static_cast<int>(std::floor((xc + rx) / hx));
      if (kx1 < kx0) continue;
      const double dyz2 = dy * dy + dz * dz;
      double dx = kx0 * hx - xc;
      double wm = cm * std::exp(-am * (dx * dx + dyz2)), wd = cd * std::exp(-ad * (dx * dx + dyz2));
      double rm = std::exp(-am * (2.0 * dx * hx + hx * hx)), rd = std::exp(-ad * (2.0 * dx * hx + hx * hx));
      const std::size_t row = g.index(0, periodic_index(ky, g.n[1]), iz);
      int ix = periodic_index(kx0, g.n[0]);
      for (int kx = kx0; kx <= kx1; ++kx) {
        point(row + static_cast<std::size_t>(ix), wm, wd, Vec3(dx, dy, dz));
        wm *= rm;
        wd *= rd;
        rm *= qm;
        rd *= qd;
        dx += hx;
        if (++ix == g.n[0]) ix = 0;
      }
    }
  }
}

}  // namespace

Envelope make_envelope(const Vec3& centre, double radius, double truncation_widths) {
  const double sm = monopole_width(radius);
  return {centre, sm, dipole_width(radius), truncation_widths * sm};
}

Mat3 dipole_tensor(const Vec3& torque, const Mat3& stresslet) {
  Mat3 rot;
  rot << 0.0, torque.z(), -torque.y(),  //
      -torque.z(), 0.0, torque.x(),     //
      torque.y(), -torque.x(), 0.0;
  return stresslet + 0.5 * rot;
}

Vec3 angular_velocity_of(const Mat3& a) {
  return 0.5 * Vec3(a(1, 2) - a(2, 1), a(2, 0) - a(0, 2), a(0, 1) - a(1, 0));
}

Mat3 strain_rate_of(const Mat3& a) { return -0.5 * (a + a.transpose()); }

void spread(const ShearedGrid& grid, std::span<const Envelope> envelopes, std::span<const Vec3> forces,
            std::span<const Mat3> dipoles, double* field, std::size_t stride) {
  const bool has_f = !forces.empty(), has_g = !dipoles.empty();
  if (!has_f && !has_g) return;
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(envelopes.size());
  double* fx = field;
  double* fy = field + stride;
  double* fz = field + 2 * stride;
#pragma omp parallel
  {
    // Thread t owns z planes [z_begin, z_end): writes never collide.
    const int threads = omp_get_num_threads(), t = omp_get_thread_num();
    const int nz = grid.n[2];
    const int z_begin = static_cast<int>(static_cast<long>(nz) * t / threads);
    const int z_end = static_cast<int>(static_cast<long>(nz) * (t + 1) / threads);
    for (std::ptrdiff_t p = 0; p < count; ++p) {
      const Envelope& e = envelopes[static_cast<std::size_t>(p)];
      const Vec3 f = has_f ? forces[static_cast<std::size_t>(p)] : Vec3::Zero();
      // d/dx_j Delta_D = -d_j / sigma_D^2 Delta_D, so G_ij d_j Delta_D = -(G d)_i w_d / sigma_D^2.
      const Mat3 gs = has_g ? Mat3(-dipoles[static_cast<std::size_t>(p)] / (e.sigma_d * e.sigma_d)) : Mat3::Zero();
      visit_support(grid, e, z_begin, z_end, [&](std::size_t i, double wm, double wd, const Vec3& d) {
        const Vec3 v = f * wm + (gs * d) * wd;
        fx[i] += v.x();
        fy[i] += v.y();
        fz[i] += v.z();
      });
    }
  }
}

void interpolate(const ShearedGrid& grid, std::span<const Envelope> envelopes, const double* field,
                 std::size_t stride, std::span<Vec3> velocities, std::span<Mat3> gradient_moments) {
  const bool want_u = !velocities.empty(), want_a = !gradient_moments.empty();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(envelopes.size());
  const double dv = grid.cell_volume();
  const double* ux = field;
  const double* uy = field + stride;
  const double* uz = field + 2 * stride;
#pragma omp parallel for schedule(dynamic, 4)
  for (std::ptrdiff_t p = 0; p < count; ++p) {
    const Envelope& e = envelopes[static_cast<std::size_t>(p)];
    Vec3 u = Vec3::Zero();
    Mat3 a = Mat3::Zero();
    visit_support(grid, e, 0, grid.n[2], [&](std::size_t i, double wm, double wd, const Vec3& d) {
      const Vec3 v(ux[i], uy[i], uz[i]);
      u += v * wm;
      a.noalias() += (v * wd) * d.transpose();
    });
    // A_ij = sum u_i d_j Delta_D dV with d_j Delta_D = -d_j / sigma_D^2 Delta_D.
    if (want_u) velocities[static_cast<std::size_t>(p)] = u * dv;
    if (want_a) gradient_moments[static_cast<std::size_t>(p)] = a * (-dv / (e.sigma_d * e.sigma_d));
  }
}

}  // namespace suspend::fcm

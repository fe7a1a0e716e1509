#include "fcm/spreading.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "fcm/envelope.hpp"

namespace suspend::fcm {
namespace {

double gaussian_norm(double sigma) { return std::pow(2.0 * std::numbers::pi * sigma * sigma, -1.5); }

// Gaussian factors tabulated once per particle: along z and y (1-D), and along x' once per y row (the row centre
// moves with y on the sheared lattice). The truncation sphere then only selects which entries are used.
// Tables are filled with the exact recurrence exp(-(d+h)^2/2s^2) = exp(-d^2/2s^2) r, r <- r exp(-h^2/s^2).
struct SupportTables {
  std::vector<double> zm, zd, ym, yd, xm, xd;  // xm/xd: row-major [ky - ky0][kx - kx0[ky]]
  std::vector<int> kx0;
  std::vector<double> dx0;
};

void gaussian_row(double d0, double h, double a, int count, double* out) {
  // out[i] = exp(-a (d0 + i h)^2)
  double w = std::exp(-a * d0 * d0), r = std::exp(-a * (2.0 * d0 * h + h * h));
  const double q = std::exp(-2.0 * a * h * h);
  for (int i = 0; i < count; ++i) {
    out[i] = w;
    w *= r;
    r *= q;
  }
}

// One contiguous run of nodes inside the truncation sphere: nodes first .. first + count - 1 of the field, with
// Gaussians w_m = yz_m xm[i], w_d = yz_d xd[i] and physical offset d = (dx + i h_x, dy, dz) from the centre.
struct RowSegment {
  std::size_t first;
  int count;
  const double* xm;
  const double* xd;
  double dx, dy, dz, yz_m, yz_d;
};

// Calls row(segment) for the runs of nodes within the truncation sphere of the envelope whose z plane lies in
// [z_begin, z_end); a row that wraps around the periodic x' boundary is split in two runs.
template <class Row>
void visit_support(const ShearedGrid& g, const Envelope& e, int z_begin, int z_end, SupportTables& t, Row&& row) {
  const double hx = g.spacing.x(), hy = g.spacing.y(), hz = g.spacing.z();
  const double inv_hx = 1.0 / hx;
  const double r2 = e.support * e.support;
  const double am = 0.5 / (e.sigma_m * e.sigma_m), ad = 0.5 / (e.sigma_d * e.sigma_d);
  const double cm = gaussian_norm(e.sigma_m), cd = gaussian_norm(e.sigma_d);
  const int kz0 = static_cast<int>(std::ceil((e.centre.z() - e.support) / hz));
  const int kz1 = static_cast<int>(std::floor((e.centre.z() + e.support) / hz));
  // Skip particles with no plane in this thread's slab before tabulating anything.
  bool any = false;
  for (int kz = kz0; kz <= kz1 && !any; ++kz) {
    const int iz = periodic_index(kz, g.n[2]);
    any = iz >= z_begin && iz < z_end;
  }
  if (!any) return;
  const int ky0 = static_cast<int>(std::ceil((e.centre.y() - e.support) / hy));
  const int ky1 = static_cast<int>(std::floor((e.centre.y() + e.support) / hy));
  const int nzs = kz1 - kz0 + 1, nys = ky1 - ky0 + 1;
  const int width = static_cast<int>(std::ceil(2.0 * e.support / hx)) + 2;
  t.zm.resize(nzs);
  t.zd.resize(nzs);
  t.ym.resize(nys);
  t.yd.resize(nys);
  t.kx0.resize(nys);
  t.dx0.resize(nys);
  t.xm.resize(static_cast<std::size_t>(nys) * width);
  t.xd.resize(static_cast<std::size_t>(nys) * width);
  gaussian_row(kz0 * hz - e.centre.z(), hz, am, nzs, t.zm.data());
  gaussian_row(kz0 * hz - e.centre.z(), hz, ad, nzs, t.zd.data());
  gaussian_row(ky0 * hy - e.centre.y(), hy, am, nys, t.ym.data());
  gaussian_row(ky0 * hy - e.centre.y(), hy, ad, nys, t.yd.data());
  for (int j = 0; j < nys; ++j) {
    // Row centre in sheared coordinates: node x' = kx h_x is at physical x' + gamma_t y.
    const double xc = e.centre.x() - g.shear_fraction * (ky0 + j) * hy;
    t.kx0[j] = static_cast<int>(std::ceil((xc - e.support) / hx));
    t.dx0[j] = t.kx0[j] * hx - xc;
    gaussian_row(t.dx0[j], hx, am, width, &t.xm[static_cast<std::size_t>(j) * width]);
    gaussian_row(t.dx0[j], hx, ad, width, &t.xd[static_cast<std::size_t>(j) * width]);
  }
  for (int kz = kz0; kz <= kz1; ++kz) {
    const int iz = periodic_index(kz, g.n[2]);
    if (iz < z_begin || iz >= z_end) continue;
    const double dz = kz * hz - e.centre.z();
    const double ry2 = r2 - dz * dz;
    if (ry2 < 0.0) continue;
    const double zm = cm * t.zm[kz - kz0], zd = cd * t.zd[kz - kz0];
    for (int j = 0; j < nys; ++j) {
      const int ky = ky0 + j;
      const double dy = ky * hy - e.centre.y();
      const double rx2 = ry2 - dy * dy;
      if (rx2 < 0.0) continue;
      const double rx = std::sqrt(rx2);
      // Node range [ka, kb] of the sphere's chord, relative to the tabulated row start kx0 (xc - kx0 h = -dx0).
      const int ka = t.kx0[j] + std::max(static_cast<int>(std::ceil((-t.dx0[j] - rx) * inv_hx)), 0);
      const int kb = t.kx0[j] + std::min(static_cast<int>(std::floor((-t.dx0[j] + rx) * inv_hx)), width - 1);
      if (kb < ka) continue;
      const double yzm = zm * t.ym[j], yzd = zd * t.yd[j];
      const double* xm = &t.xm[static_cast<std::size_t>(j) * width];
      const double* xd = &t.xd[static_cast<std::size_t>(j) * width];
      const std::size_t base = g.index(0, periodic_index(ky, g.n[1]), iz);
      const int i0 = ka - t.kx0[j];
      const int ix = periodic_index(ka, g.n[0]);
      const int total = kb - ka + 1, first_run = std::min(total, g.n[0] - ix);
      row(RowSegment{base + ix, first_run, xm + i0, xd + i0, t.dx0[j] + i0 * hx, dy, dz, yzm, yzd});
      if (first_run < total)
        row(RowSegment{base, total - first_run, xm + i0 + first_run, xd + i0 + first_run,
                       t.dx0[j] + (i0 + first_run) * hx, dy, dz, yzm, yzd});
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

std::vector<std::uint32_t> grid_order(const ShearedGrid& g, std::span<const Envelope> envelopes) {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> key(envelopes.size());
  for (std::size_t p = 0; p < envelopes.size(); ++p) {
    const Vec3& c = envelopes[p].centre;
    const int iy = periodic_index(static_cast<int>(std::floor(c.y() / g.spacing.y())), g.n[1]);
    const double xs = c.x() - g.shear_fraction * std::floor(c.y() / g.spacing.y()) * g.spacing.y();
    const int ix = periodic_index(static_cast<int>(std::floor(xs / g.spacing.x())), g.n[0]);
    const int iz = periodic_index(static_cast<int>(std::floor(c.z() / g.spacing.z())), g.n[2]);
    // Blocks of 8 nodes (~4 h = 2 a at h = a/2) ordered lexicographically: consecutive particles are neighbours
    // in all three directions and share most of the grid rows they touch.
    constexpr int b = 8;
    const std::uint64_t bx = ix / b, by = iy / b, bz = iz / b;
    const std::uint64_t nbx = (g.n[0] + b - 1) / b, nby = (g.n[1] + b - 1) / b;
    key[p] = {((bz * nby + by) * nbx + bx) << 32 | g.index(ix, iy, iz), static_cast<std::uint32_t>(p)};
  }
  std::sort(key.begin(), key.end());
  std::vector<std::uint32_t> order(envelopes.size());
  for (std::size_t k = 0; k < key.size(); ++k) order[k] = key[k].second;
  return order;
}

void spread(const ShearedGrid& grid, std::span<const Envelope> envelopes, std::span<const Vec3> forces,
            std::span<const Mat3> dipoles, double* field, std::size_t stride, std::span<const std::uint32_t> order) {
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
    SupportTables tables;
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const std::size_t p = order.empty() ? static_cast<std::size_t>(k) : order[static_cast<std::size_t>(k)];
      const Envelope& e = envelopes[p];
      const Vec3 f = has_f ? forces[p] : Vec3::Zero();
      // d/dx_j Delta_D = -d_j / sigma_D^2 Delta_D, so G_ij d_j Delta_D = -(G d)_i w_d / sigma_D^2.
      const Mat3 gs = has_g ? Mat3(-dipoles[p] / (e.sigma_d * e.sigma_d)) : Mat3::Zero();
      const double hx = grid.spacing.x();
      visit_support(grid, e, z_begin, z_end, tables, [&](const RowSegment& r) {
        // gs d = gs.col(0) dx + (gs.col(1) dy + gs.col(2) dz): only the first term varies along the row.
        const Vec3 b = gs.col(1) * r.dy + gs.col(2) * r.dz;
        const double g0 = gs(0, 0), g1 = gs(1, 0), g2 = gs(2, 0);
        double* px = fx + r.first;
        double* py = fy + r.first;
        double* pz = fz + r.first;
        for (int i = 0; i < r.count; ++i) {
          const double wm = r.yz_m * r.xm[i], wd = r.yz_d * r.xd[i], dx = r.dx + i * hx;
          px[i] += f.x() * wm + (b.x() + g0 * dx) * wd;
          py[i] += f.y() * wm + (b.y() + g1 * dx) * wd;
          pz[i] += f.z() * wm + (b.z() + g2 * dx) * wd;
        }
      });
    }
  }
}

void interpolate(const ShearedGrid& grid, std::span<const Envelope> envelopes, const double* field,
                 std::size_t stride, std::span<Vec3> velocities, std::span<Mat3> gradient_moments,
                 std::span<const std::uint32_t> order) {
  const bool want_u = !velocities.empty(), want_a = !gradient_moments.empty();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(envelopes.size());
  const double dv = grid.cell_volume();
  const double* ux = field;
  const double* uy = field + stride;
  const double* uz = field + 2 * stride;
#pragma omp parallel
  {
  SupportTables tables;
#pragma omp for schedule(dynamic, 16)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::size_t p = order.empty() ? static_cast<std::size_t>(k) : order[static_cast<std::size_t>(k)];
    const Envelope& e = envelopes[p];
    Vec3 u = Vec3::Zero();
    Mat3 a = Mat3::Zero();
    const double hx = grid.spacing.x();
    visit_support(grid, e, 0, grid.n[2], tables, [&](const RowSegment& r) {
      // Row sums of u w_m, u w_d and u w_d dx; dy and dz are constant along the row.
      double um0 = 0, um1 = 0, um2 = 0, s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0, t2 = 0;
      const double* px = ux + r.first;
      const double* py = uy + r.first;
      const double* pz = uz + r.first;
      for (int i = 0; i < r.count; ++i) {
        const double wm = r.yz_m * r.xm[i], wd = r.yz_d * r.xd[i], wdx = wd * (r.dx + i * hx);
        um0 += px[i] * wm;
        um1 += py[i] * wm;
        um2 += pz[i] * wm;
        s0 += px[i] * wd;
        s1 += py[i] * wd;
        s2 += pz[i] * wd;
        t0 += px[i] * wdx;
        t1 += py[i] * wdx;
        t2 += pz[i] * wdx;
      }
      u += Vec3(um0, um1, um2);
      const Vec3 s(s0, s1, s2);
      a.col(0) += Vec3(t0, t1, t2);
      a.col(1) += s * r.dy;
      a.col(2) += s * r.dz;
    });
    // A_ij = sum u_i d_j Delta_D dV with d_j Delta_D = -d_j / sigma_D^2 Delta_D.
    if (want_u) velocities[p] = u * dv;
    if (want_a) gradient_moments[p] = a * (-dv / (e.sigma_d * e.sigma_d));
  }
  }
}

}  // namespace suspend::fcm

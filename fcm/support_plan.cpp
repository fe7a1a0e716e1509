#include "fcm/support_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "fcm/spreading.hpp"

namespace suspend::fcm {
namespace {

// floor and ceil for values well inside the int range, without a libm call (the row loop runs ~100 times per
// particle).
int floor_int(double v) {
  const int i = static_cast<int>(v);
  return i - (v < i ? 1 : 0);
}
int ceil_int(double v) {
  const int i = static_cast<int>(v);
  return i + (v > i ? 1 : 0);
}

double gaussian_norm(double sigma) { return std::pow(2.0 * std::numbers::pi * sigma * sigma, -1.5); }

void gaussian_row(double d0, double h, double a, int count, double* out) {
  // out[i] = exp(-a (d0 + i h)^2) by the exact recurrence.
  double w = std::exp(-a * d0 * d0), r = std::exp(-a * (2.0 * d0 * h + h * h));
  const double q = std::exp(-2.0 * a * h * h);
  for (int i = 0; i < count; ++i) {
    out[i] = w;
    w *= r;
    r *= q;
  }
}

// Node ranges of one envelope's truncation sphere: z planes kz0..kz1, y rows ky0..ky1 (unwrapped indices), and
// `width` tabulated x nodes per y row starting at kx0(ky).
struct Extent {
  int kz0, kz1, ky0, ky1, width;
  int rows() const { return ky1 - ky0 + 1; }
};

Extent extent_of(const ShearedGrid& g, const Envelope& e) {
  Extent x{};
  x.kz0 = static_cast<int>(std::ceil((e.centre.z() - e.support) / g.spacing.z()));
  x.kz1 = static_cast<int>(std::floor((e.centre.z() + e.support) / g.spacing.z()));
  x.ky0 = static_cast<int>(std::ceil((e.centre.y() - e.support) / g.spacing.y()));
  x.ky1 = static_cast<int>(std::floor((e.centre.y() + e.support) / g.spacing.y()));
  x.width = static_cast<int>(std::ceil(2.0 * e.support / g.spacing.x())) + 2;
  return x;
}

// Row centre in sheared coordinates (node x' = kx h_x sits at physical x' + gamma_t y) and its first tabulated node.
double row_centre(const ShearedGrid& g, const Envelope& e, int ky) {
  return e.centre.x() - g.shear_fraction * ky * g.spacing.y();
}
int row_start(const ShearedGrid& g, const Envelope& e, int ky) {
  return static_cast<int>(std::ceil((row_centre(g, e, ky) - e.support) / g.spacing.x()));
}

// Per-envelope factors along z and y, and the x' start of each y row (reused per thread).
struct AxisTables {
  std::vector<double> zm, zd, ym, yd, dx0;
  std::vector<int> kx0, iy;
};

// Calls emit(row) for every run of the envelope's support, z plane by z plane; `table` is the offset of the
// particle's x tables (row j of the extent at table + 3 j width).
template <class Emit>
void for_each_row(const ShearedGrid& g, const Envelope& e, const Extent& x, std::size_t table, AxisTables& t,
                  Emit&& emit) {
  const double hx = g.spacing.x(), hy = g.spacing.y(), hz = g.spacing.z();
  const double inv_hx = 1.0 / hx, r2 = e.support * e.support;
  const double am = 0.5 / (e.sigma_m * e.sigma_m), ad = 0.5 / (e.sigma_d * e.sigma_d);
  const double cm = gaussian_norm(e.sigma_m), cd = gaussian_norm(e.sigma_d);
  const int nzs = x.kz1 - x.kz0 + 1, nys = x.rows(), nx = g.n[0];
  t.zm.resize(static_cast<std::size_t>(std::max(nzs, 0)));
  t.zd.resize(t.zm.size());
  t.ym.resize(static_cast<std::size_t>(std::max(nys, 0)));
  t.yd.resize(t.ym.size());
  t.dx0.resize(t.ym.size());
  t.kx0.resize(t.ym.size());
  t.iy.resize(t.ym.size());
  gaussian_row(x.kz0 * hz - e.centre.z(), hz, am, nzs, t.zm.data());
  gaussian_row(x.kz0 * hz - e.centre.z(), hz, ad, nzs, t.zd.data());
  gaussian_row(x.ky0 * hy - e.centre.y(), hy, am, nys, t.ym.data());
  gaussian_row(x.ky0 * hy - e.centre.y(), hy, ad, nys, t.yd.data());
  for (int j = 0; j < nys; ++j) {
    t.kx0[j] = row_start(g, e, x.ky0 + j);
    t.dx0[j] = t.kx0[j] * hx - row_centre(g, e, x.ky0 + j);
    t.iy[j] = periodic_index(x.ky0 + j, g.n[1]);
  }
  for (int kz = x.kz0; kz <= x.kz1; ++kz) {
    const double dz = kz * hz - e.centre.z();
    const double ry2 = r2 - dz * dz;
    if (ry2 < 0.0) continue;
    const int iz = periodic_index(kz, g.n[2]);
    const double zm = cm * t.zm[kz - x.kz0], zd = cd * t.zd[kz - x.kz0];
    for (int j = 0; j < nys; ++j) {
      const double dy = (x.ky0 + j) * hy - e.centre.y();
      const double rx2 = ry2 - dy * dy;
      if (rx2 < 0.0) continue;
      const double rx = std::sqrt(rx2);
      // Node range [ka, kb] of the sphere's chord within the tabulated nodes kx0 .. kx0 + width - 1.
      const int kx0 = t.kx0[j];
      const int ia = std::max(ceil_int((-t.dx0[j] - rx) * inv_hx), 0);
      const int ib = std::min(floor_int((-t.dx0[j] + rx) * inv_hx), x.width - 1);
      if (ib < ia) continue;
      SupportRow r;
      r.width = static_cast<std::uint16_t>(x.width);
      r.iz = static_cast<std::uint32_t>(iz);
      r.yz_m = zm * t.ym[j];
      r.yz_d = zd * t.yd[j];
      r.ydy = r.yz_d * dy;
      r.ydz = r.yz_d * dz;
      const std::size_t base = g.index(0, t.iy[j], iz);
      const std::size_t row_table = table + 3 * static_cast<std::size_t>(j) * x.width;
      const int ix = periodic_index(kx0 + ia, nx);
      const int total = ib - ia + 1, first_run = std::min(total, nx - ix);
      r.first = static_cast<std::uint32_t>(base + ix);
      r.table = static_cast<std::uint32_t>(row_table + ia);
      r.count = static_cast<std::uint16_t>(first_run);
      emit(r);
      if (first_run < total) {
        r.first = static_cast<std::uint32_t>(base);
        r.table = static_cast<std::uint32_t>(row_table + ia + first_run);
        r.count = static_cast<std::uint16_t>(total - first_run);
        emit(r);
      }
    }
  }
}

// The m, d, dd tables of every y row of the extent (layout of for_each_row).
void fill_tables(const ShearedGrid& g, const Envelope& e, const Extent& x, double* t) {
  const double hx = g.spacing.x();
  const double am = 0.5 / (e.sigma_m * e.sigma_m), ad = 0.5 / (e.sigma_d * e.sigma_d);
  for (int ky = x.ky0; ky <= x.ky1; ++ky) {
    const int kx0 = row_start(g, e, ky);
    const double dx0 = kx0 * hx - row_centre(g, e, ky);
    double* m = t + 3 * static_cast<std::size_t>(ky - x.ky0) * x.width;
    double* d = m + x.width;
    double* dd = d + x.width;
    gaussian_row(dx0, hx, am, x.width, m);
    gaussian_row(dx0, hx, ad, x.width, d);
    for (int i = 0; i < x.width; ++i) dd[i] = (dx0 + i * hx) * d[i];
  }
}

}  // namespace

SupportPlan plan_support(const ShearedGrid& g, std::span<const Envelope> envelopes,
                         std::span<const std::uint32_t> order) {
  SupportPlan plan;
  plan_support(g, envelopes, order, plan);
  return plan;
}

void plan_support(const ShearedGrid& g, std::span<const Envelope> envelopes, std::span<const std::uint32_t> order,
                  SupportPlan& plan) {
  if (static_cast<double>(g.n[0]) * g.n[1] * g.n[2] > std::numeric_limits<std::uint32_t>::max())
    throw NumericalError("fcm: grid too large for 32-bit node offsets");
  for (const Envelope& e : envelopes)  // checked here: nothing may throw inside the parallel passes
    if (!(extent_of(g, e).width <= std::numeric_limits<std::uint16_t>::max()))
      throw NumericalError("fcm: envelope support spans more than 65535 grid nodes");
  const std::size_t n = envelopes.size();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(n);
  plan.cell_volume = g.cell_volume();
  plan.particle.resize(n);
  plan.dipole_scale.resize(n);
  std::vector<std::size_t> table_begin(n + 1, 0);
  plan.row_begin.assign(n + 1, 0);  // (sizes only grow or shrink: a reused plan is not zero-filled again)
  plan.row_end.resize(n);
  plan.z_first.resize(n);
  plan.z_planes.resize(n);
  // Pass 1: row slots and table entries per visit.
#pragma omp parallel for schedule(dynamic, 32)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    const std::uint32_t p = order.empty() ? static_cast<std::uint32_t>(k) : order[ku];
    const Envelope& e = envelopes[p];
    const Extent x = extent_of(g, e);
    // Room for every (z, y) pair of the extent, twice where the tabulated x range crosses the periodic boundary:
    // an upper bound, so the rows are written in one pass (the unused tail of a slot is skipped via row_end).
    std::size_t slots = 0;
    for (int ky = x.ky0; ky <= x.ky1; ++ky) {
      const int ix = periodic_index(row_start(g, e, ky), g.n[0]);
      slots += ix + x.width > g.n[0] ? 2 : 1;
    }
    const std::size_t rows = slots * static_cast<std::size_t>(std::max(x.kz1 - x.kz0 + 1, 0));
    plan.particle[ku] = p;
    plan.z_first[ku] = static_cast<std::uint32_t>(periodic_index(x.kz0, g.n[2]));
    plan.z_planes[ku] = static_cast<std::uint32_t>(std::clamp(x.kz1 - x.kz0 + 1, 0, g.n[2]));
    plan.dipole_scale[ku] = -1.0 / (e.sigma_d * e.sigma_d);
    plan.row_begin[ku + 1] = rows;
    table_begin[ku + 1] = 3 * static_cast<std::size_t>(x.rows()) * x.width;
  }
  for (std::size_t k = 0; k < n; ++k) {
    plan.row_begin[k + 1] += plan.row_begin[k];
    table_begin[k + 1] += table_begin[k];
  }
  if (table_begin[n] > std::numeric_limits<std::uint32_t>::max())
    throw NumericalError("fcm: envelope tables too large for 32-bit offsets");
  plan.rows.resize(plan.row_begin[n]);
  plan.tables.resize(table_begin[n]);
  // Pass 2: tables and rows.
#pragma omp parallel
  {
  AxisTables axis;
#pragma omp for schedule(dynamic, 32)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    const Envelope& e = envelopes[plan.particle[ku]];
    const Extent x = extent_of(g, e);
    fill_tables(g, e, x, plan.tables.data() + table_begin[ku]);
    std::size_t r = plan.row_begin[ku];
    for_each_row(g, e, x, table_begin[ku], axis, [&](const SupportRow& row) { plan.rows[r++] = row; });
    plan.row_end[ku] = r;
  }
  }
  plan.plane_nodes.assign(static_cast<std::size_t>(g.n[2]), 0);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t j = plan.row_begin[k]; j < plan.row_end[k]; ++j) plan.plane_nodes[plan.rows[j].iz] += plan.rows[j].count;
}

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

}  // namespace suspend::fcm

#include "fcm/support_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include <Eigen/Core>

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

double gaussian_norm(double sigma) {  // (2 pi sigma^2)^(-3/2)
  const double v = 2.0 * std::numbers::pi * sigma * sigma;
  return 1.0 / (v * std::sqrt(v));
}

// The two x tables of a y row at once (two independent product chains in one loop: the multiplications of one
// overlap the latency of the other): m[i] = wm exp(-am (d0 + i h)^2) / exp(-am d0^2) by the exact recurrence
// w <- w r, r <- r q from r = exp(-am (2 d0 h + h^2)), q = exp(-2 am h^2) (one per width and spacing); d likewise.
void gaussian_recurrences(double wm, double rm, double qm, double wd, double rd, double qd, int count, double* m,
                          double* d) {
  for (int i = 0; i < count; ++i) {
    m[i] = wm;
    d[i] = wd;
    wm *= rm;
    rm *= qm;
    wd *= rd;
    rd *= qd;
  }
}

// out[i] = exp(-a (d0 + i h)^2), q = exp(-2 a h^2).
void gaussian_row(double d0, double h, double a, double q, int count, double* out) {
  double w = std::exp(-a * d0 * d0), r = std::exp(-a * (2.0 * d0 * h + h * h));
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
  int planes() const { return kz1 - kz0 + 1; }
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
  // The four exponentials that start each y row's x tables (exp(-a dx0^2), exp(-a (2 dx0 h + h^2)) for both
  // widths), evaluated as one array: Eigen's vectorised exp, 4 x 11 per particle at h = a/2, where one libm call
  // each was a sixth of the planning time.
  Eigen::ArrayXd exponent, factor;
  Eigen::ArrayXd dy2, centre, rx2, half_chord;  // per y row (the plane loop, below)
};

// Fills the envelope's x tables (y row j at tables + 2 j width: m, d with the row's y factor, support_plan.hpp)
// and writes its planes and rows from `plane` and `row` on; returns the ends and adds the support nodes of each z
// plane to plane_nodes. `table` is the offset of the particle's tables in the plan.
void plan_envelope(const ShearedGrid& g, const Envelope& e, const Extent& x, std::size_t table, double* tables,
                   double* row_dy, double* row_dx0, AxisTables& t, SupportPlane* plane, SupportRow* row,
                   SupportPlane*& plane_end, SupportRow*& row_end, std::size_t row_offset, std::size_t* plane_nodes) {
  const double hx = g.spacing.x(), hy = g.spacing.y(), hz = g.spacing.z();
  const double inv_hx = 1.0 / hx, r2 = e.support * e.support;
  const double am = 0.5 / (e.sigma_m * e.sigma_m), ad = 0.5 / (e.sigma_d * e.sigma_d);
  const double cm = gaussian_norm(e.sigma_m), cd = gaussian_norm(e.sigma_d);
  const int nzs = x.planes(), nys = x.rows(), nx = g.n[0];
  t.zm.resize(static_cast<std::size_t>(std::max(nzs, 0)));
  t.zd.resize(t.zm.size());
  t.ym.resize(static_cast<std::size_t>(std::max(nys, 0)));
  t.yd.resize(t.ym.size());
  t.dx0.resize(t.ym.size());
  t.kx0.resize(t.ym.size());
  t.iy.resize(t.ym.size());
  gaussian_row(x.kz0 * hz - e.centre.z(), hz, am, std::exp(-2.0 * am * hz * hz), nzs, t.zm.data());
  gaussian_row(x.kz0 * hz - e.centre.z(), hz, ad, std::exp(-2.0 * ad * hz * hz), nzs, t.zd.data());
  gaussian_row(x.ky0 * hy - e.centre.y(), hy, am, std::exp(-2.0 * am * hy * hy), nys, t.ym.data());
  gaussian_row(x.ky0 * hy - e.centre.y(), hy, ad, std::exp(-2.0 * ad * hy * hy), nys, t.yd.data());
  const double qm = std::exp(-2.0 * am * hx * hx), qd = std::exp(-2.0 * ad * hx * hx);
  t.exponent.resize(4 * std::max(nys, 0));
  for (int j = 0; j < nys; ++j) {
    t.kx0[j] = row_start(g, e, x.ky0 + j);
    t.dx0[j] = t.kx0[j] * hx - row_centre(g, e, x.ky0 + j);
    t.iy[j] = periodic_index(x.ky0 + j, g.n[1]);
    row_dy[j] = (x.ky0 + j) * hy - e.centre.y();
    row_dx0[j] = t.dx0[j];
    const double d0 = t.dx0[j];
    t.exponent[4 * j] = -am * d0 * d0;
    t.exponent[4 * j + 1] = -am * (2.0 * d0 * hx + hx * hx);
    t.exponent[4 * j + 2] = -ad * d0 * d0;
    t.exponent[4 * j + 3] = -ad * (2.0 * d0 * hx + hx * hx);
  }
  t.factor = t.exponent.exp();
  for (int j = 0; j < nys; ++j) {
    double* m = tables + 2 * static_cast<std::size_t>(j) * x.width;
    gaussian_recurrences(t.ym[j] * t.factor[4 * j], t.factor[4 * j + 1], qm, t.yd[j] * t.factor[4 * j + 2],
                         t.factor[4 * j + 3], qd, x.width, m, m + x.width);
  }
  // Per y row: dy^2 and the chord's centre -dx0 in units of h_x, for the plane loop's array expressions.
  t.dy2.resize(std::max(nys, 0));
  t.centre.resize(t.dy2.size());
  for (int j = 0; j < nys; ++j) {
    t.dy2[j] = row_dy[j] * row_dy[j];
    t.centre[j] = -t.dx0[j] * inv_hx;
  }
  for (int kz = x.kz0; kz <= x.kz1; ++kz) {
    const double dz = kz * hz - e.centre.z();
    const double ry2 = r2 - dz * dz;
    if (ry2 < 0.0) continue;
    SupportPlane p;
    p.zm = cm * t.zm[kz - x.kz0];
    p.zd = cd * t.zd[kz - x.kz0];
    p.dz = dz;
    p.iz = static_cast<std::uint32_t>(periodic_index(kz, g.n[2]));
    SupportRow* first_row = row;
    // Half chords of the sphere in every y row of the plane, in units of h_x (vectorised square roots; rows
    // outside the sphere get a negative value and are skipped).
    t.rx2 = ry2 - t.dy2;
    t.half_chord = t.rx2.max(0.0).sqrt() * inv_hx;
    for (int j = 0; j < nys; ++j) {
      if (t.rx2[j] < 0.0) continue;
      // Node range [ia, ib] of the sphere's chord within the tabulated nodes kx0 .. kx0 + width - 1.
      const int ia = std::max(ceil_int(t.centre[j] - t.half_chord[j]), 0);
      const int ib = std::min(floor_int(t.centre[j] + t.half_chord[j]), x.width - 1);
      if (ib < ia) continue;
      const std::size_t base = g.index(0, t.iy[j], static_cast<int>(p.iz));
      const std::size_t row_table = table + 2 * static_cast<std::size_t>(j) * x.width;
      int ix = t.kx0[j] + ia;
      if (ix < 0 || ix >= nx) ix = periodic_index(ix, nx);
      const int total = ib - ia + 1, first_run = std::min(total, nx - ix);
      plane_nodes[p.iz] += static_cast<std::size_t>(total);
      *row++ = {static_cast<std::uint32_t>(base + ix), static_cast<std::uint32_t>(row_table + ia),
                static_cast<std::uint16_t>(first_run), static_cast<std::uint16_t>(j)};
      if (first_run < total)
        *row++ = {static_cast<std::uint32_t>(base), static_cast<std::uint32_t>(row_table + ia + first_run),
                  static_cast<std::uint16_t>(total - first_run), static_cast<std::uint16_t>(j)};
    }
    if (row == first_row) continue;
    p.row_begin = static_cast<std::uint32_t>(row_offset);
    row_offset += static_cast<std::size_t>(row - first_row);
    p.row_end = static_cast<std::uint32_t>(row_offset);
    *plane++ = p;
  }
  plane_end = plane;
  row_end = row;
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
  for (const Envelope& e : envelopes) {  // checked here: nothing may throw inside the parallel passes
    const Extent x = extent_of(g, e);
    if (!(x.width <= std::numeric_limits<std::uint16_t>::max() && x.rows() <= std::numeric_limits<std::uint16_t>::max()))
      throw NumericalError("fcm: envelope support spans more than 65535 grid nodes");
  }
  const std::size_t n = envelopes.size();
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(n);
  plan.cell_volume = g.cell_volume();
  plan.spacing_x = g.spacing.x();
  plan.particle.resize(n);
  plan.dipole_scale.resize(n);
  plan.dy_begin.assign(n + 1, 0);
  plan.width.resize(n);
  std::vector<std::size_t>& table_begin = plan.table_begin;
  table_begin.assign(n + 1, 0);
  std::vector<std::size_t> row_begin(n + 1, 0);
  plan.plane_begin.assign(n + 1, 0);  // (sizes only grow or shrink: a reused plan is not zero-filled again)
  plan.plane_end.resize(n);
  plan.z_first.resize(n);
  plan.z_planes.resize(n);
  // Pass 1: plane and row slots and table entries per visit.
#pragma omp parallel for schedule(dynamic, 32)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    const std::uint32_t p = order.empty() ? static_cast<std::uint32_t>(k) : order[ku];
    const Envelope& e = envelopes[p];
    const Extent x = extent_of(g, e);
    // Room for every (z, y) pair of the extent, twice where the tabulated x range crosses the periodic boundary:
    // an upper bound, so the rows are written in one pass.
    std::size_t slots = 0;
    for (int ky = x.ky0; ky <= x.ky1; ++ky) {
      const int ix = periodic_index(row_start(g, e, ky), g.n[0]);
      slots += ix + x.width > g.n[0] ? 2 : 1;
    }
    const std::size_t planes = static_cast<std::size_t>(std::max(x.planes(), 0));
    plan.particle[ku] = p;
    plan.z_first[ku] = static_cast<std::uint32_t>(periodic_index(x.kz0, g.n[2]));
    plan.z_planes[ku] = static_cast<std::uint32_t>(std::clamp(x.planes(), 0, g.n[2]));
    plan.dipole_scale[ku] = -1.0 / (e.sigma_d * e.sigma_d);
    plan.dy_begin[ku + 1] = static_cast<std::size_t>(std::max(x.rows(), 0));
    plan.width[ku] = static_cast<std::uint16_t>(x.width);
    plan.plane_begin[ku + 1] = planes;
    row_begin[ku + 1] = slots * planes;
    table_begin[ku + 1] = 2 * static_cast<std::size_t>(x.rows()) * x.width;
  }
  for (std::size_t k = 0; k < n; ++k) {
    plan.plane_begin[k + 1] += plan.plane_begin[k];
    plan.dy_begin[k + 1] += plan.dy_begin[k];
    row_begin[k + 1] += row_begin[k];
    table_begin[k + 1] += table_begin[k];
  }
  if (table_begin[n] > std::numeric_limits<std::uint32_t>::max() ||
      row_begin[n] > std::numeric_limits<std::uint32_t>::max())
    throw NumericalError("fcm: envelope tables too large for 32-bit offsets");
  plan.planes.resize(plan.plane_begin[n]);
  plan.rows.resize(row_begin[n]);
  plan.tables.resize(table_begin[n]);
  plan.dy.resize(plan.dy_begin[n]);
  plan.dx0.resize(plan.dy_begin[n]);
  // Pass 2: tables, planes and rows; support nodes per z plane summed per thread, then over the threads.
  plan.plane_nodes.assign(static_cast<std::size_t>(g.n[2]), 0);
#pragma omp parallel
  {
  AxisTables axis;
  std::vector<std::size_t> plane_nodes(static_cast<std::size_t>(g.n[2]), 0);
#pragma omp for schedule(dynamic, 32)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const std::size_t ku = static_cast<std::size_t>(k);
    const Envelope& e = envelopes[plan.particle[ku]];
    const Extent x = extent_of(g, e);
    SupportPlane* plane_end = nullptr;
    SupportRow* row_end = nullptr;
    plan_envelope(g, e, x, table_begin[ku], plan.tables.data() + table_begin[ku], plan.dy.data() + plan.dy_begin[ku],
                  plan.dx0.data() + plan.dy_begin[ku], axis,
                  plan.planes.data() + plan.plane_begin[ku], plan.rows.data() + row_begin[ku], plane_end, row_end,
                  row_begin[ku], plane_nodes.data());
    plan.plane_end[ku] = static_cast<std::size_t>(plane_end - plan.planes.data());
  }
#pragma omp critical(suspend_fcm_plane_nodes)
  for (std::size_t z = 0; z < plane_nodes.size(); ++z) plan.plane_nodes[z] += plane_nodes[z];
  }
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

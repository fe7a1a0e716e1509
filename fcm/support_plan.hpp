// The grid footprint of every particle's envelopes, tabulated once per particle configuration (positions and the
// Lees-Edwards offset) and reused by every spread and interpolation until the particles move: the rigidity CG
// of one mobility solve runs many Stokes solves on the same footprints (spreading.hpp for the moments).
//
// Support: the nodes within the truncation sphere |x - Y| <= support (physical distance on the sheared lattice,
// sheared_grid.hpp). The Gaussians are separable, exp(-|d|^2/2s^2) = exp(-dz^2/2s^2) exp(-dy^2/2s^2)
// exp(-dx^2/2s^2), so a support is stored as z planes, each a list of rows of consecutive x' nodes. The x tables
// depend on the y row, because the row centre x' = x - gamma_t y moves with y; they carry the row's y factor. For
// y row j of the extent we tabulate, over its nodes i = 0 .. w - 1:
//   m[i] = ym_j exp(-dx_i^2 / 2 sM^2),  d[i] = yd_j exp(-dx_i^2 / 2 sD^2),  dx_i = dx0_j + i h_x
// with ym_j = exp(-dy_j^2 / 2 sM^2), yd_j = exp(-dy_j^2 / 2 sD^2). The first moment the dipole needs
// (d/dx_j Delta_D = -d_j / sD^2 Delta_D) is dx_i d[i], formed by the kernels from dx0_j: a third table of it
// would be a third of the bytes every spread and interpolation streams. A z plane holds its factors
// zm = cM exp(-dz^2/2 sM^2), zd = cD exp(-dz^2/2 sD^2) (cM = (2 pi sM^2)^(-3/2)), so node weights are
// w_M = zm m[i], w_D = zd d[i], and the x, y and z offsets of the dipole moment are zd dx_i d[i], zd dy_j d[i] and
// zd dz d[i].
// Tables are filled with the exact recurrence exp(-a(d+h)^2) = exp(-a d^2) r, r <- r exp(-2 a h^2).
// A row descriptor is 12 bytes and a plane 32 (the rows of a 64^3 solve at phi = 0.4 are streamed through every
// spread and interpolation: 271,000 of them). Units: lengths in a_1.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fcm/sheared_grid.hpp"

namespace suspend::fcm {

struct Envelope;

// One run of `count` consecutive nodes first .. first + count - 1 (index within one field component) of y row j of
// its particle's extent, in the z plane that lists it. Its x tables start at tables[table] (m) and tables[table + w]
// (d), w = SupportPlan::width[visit]; its first node is node table - table_begin[visit] - 2 w j of the row's tables
// (so dx = dx0_j + that index h_x). A row crossing the periodic x' boundary is stored as two runs.
struct SupportRow {
  std::uint32_t first = 0;
  std::uint32_t table = 0;
  std::uint16_t count = 0;
  std::uint16_t j = 0;
};

// One z plane of a particle's support: rows [row_begin, row_end) of SupportPlan::rows, the plane's Gaussian
// factors (normalisation included) and dz = z_plane - Z.
struct SupportPlane {
  double zm = 0.0, zd = 0.0, dz = 0.0;
  std::uint32_t iz = 0;
  std::uint32_t row_begin = 0, row_end = 0;
};

struct SupportPlan {
  std::vector<std::uint32_t> particle;   // particle visited at position k (spatially sorted)
  std::vector<std::size_t> plane_begin;  // planes of visit k: [plane_begin[k], plane_end[k]) (slots up to
  std::vector<std::size_t> plane_end;    //   plane_begin[k + 1] are reserved, an upper bound)
  std::vector<double> dipole_scale;      // -1 / sD^2 of visit k
  std::vector<std::size_t> dy_begin;     // dy of visit k's y row j: dy[dy_begin[k] + j], and dx0_j: dx0[...]
  std::vector<double> dy;
  std::vector<double> dx0;               // x offset (sheared coordinates) of table node 0 of y row j
  std::vector<std::size_t> table_begin;  // tables of visit k: [table_begin[k], table_begin[k + 1])
  std::vector<std::uint16_t> width;      // x-table width of visit k
  std::vector<std::uint32_t> z_first;    // first z plane (wrapped) of visit k's extent ...
  std::vector<std::uint32_t> z_planes;   // ... and its number of planes (may wrap past n_z)
  std::vector<SupportPlane> planes;
  std::vector<SupportRow> rows;
  std::vector<double> tables;
  std::vector<std::size_t> plane_nodes;  // support nodes per z plane: the work a spreading thread owns
  double cell_volume = 0.0;
  double spacing_x = 0.0;                // h_x

  std::size_t visits() const { return particle.size(); }
  // Whether visit k has nodes in the z planes [z_begin, z_end) of a grid with nz planes.
  bool touches_planes(std::size_t k, std::uint32_t z_begin, std::uint32_t z_end, std::uint32_t nz) const {
    const std::uint32_t a = z_first[k], b = z_first[k] + z_planes[k];  // [a, b), b may exceed nz
    return (a < z_end && b > z_begin) || (b > nz && b - nz > z_begin);
  }
  // Whether all of visit k's planes lie in [z_begin, z_end).
  bool inside_planes(std::size_t k, std::uint32_t z_begin, std::uint32_t z_end) const {
    return z_first[k] >= z_begin && z_first[k] + z_planes[k] <= z_end;
  }
};

// Builds the plan; `order` is the visiting order (e.g. grid_order; empty = index order). OpenMP-parallel.
// Throws NumericalError if the tables outgrow 32-bit offsets or a support row is wider than 65535 nodes.
SupportPlan plan_support(const ShearedGrid& grid, std::span<const Envelope> envelopes,
                         std::span<const std::uint32_t> order = {});
// The same into an existing plan, reusing its memory (the solver re-plans every configuration).
void plan_support(const ShearedGrid& grid, std::span<const Envelope> envelopes, std::span<const std::uint32_t> order,
                  SupportPlan& plan);

// Particle indices sorted by the grid block (8^3 nodes), then the grid node, of their centres.
std::vector<std::uint32_t> grid_order(const ShearedGrid& grid, std::span<const Envelope> envelopes);

}  // namespace suspend::fcm

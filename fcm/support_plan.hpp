// The grid footprint of every particle's envelopes, tabulated once per particle configuration (positions and the
// Lees-Edwards offset) and reused by every spread and interpolation until the particles move: the rigidity CG
// of one mobility solve runs many Stokes solves on the same footprints (spreading.hpp for the moments).
//
// Support: the nodes within the truncation sphere |x - Y| <= support (physical distance on the sheared lattice,
// sheared_grid.hpp). The Gaussians are separable, exp(-|d|^2/2s^2) = exp(-dz^2/2s^2) exp(-dy^2/2s^2)
// exp(-dx^2/2s^2), so a support is stored as rows of consecutive x' nodes, each with its (y, z) factor and a
// pointer into per-particle x tables. The x tables depend on the y row, because the row centre x' = x - gamma_t y
// moves with y. For each y row we tabulate, over the nodes of the row:
//   m[i] = exp(-dx_i^2 / 2 sM^2),  d[i] = exp(-dx_i^2 / 2 sD^2),  dd[i] = dx_i d[i]
// (dd carries the first moment the dipole needs: d/dx_j Delta_D = -d_j / sD^2 Delta_D). Node weights are then
//   w_M = yz_m m[i],  w_D = yz_d d[i],  with yz_m = cM exp(-(dy^2 + dz^2)/2 sM^2), cM = (2 pi sM^2)^(-3/2).
// Tables are filled with the exact recurrence exp(-a(d+h)^2) = exp(-a d^2) r, r <- r exp(-2 a h^2).
// Units: lengths in a_1.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "fcm/sheared_grid.hpp"

namespace suspend::fcm {

struct Envelope;

// One run of `count` consecutive nodes first .. first + count - 1 (index within one field component) in z plane
// iz, at offsets dy, dz from the centre, stored pre-multiplied: ydy = yz_d dy, ydz = yz_d dz. Its x tables start at tables[table] (m), tables[table + width] (d) and
// tables[table + 2 width] (dd); a row crossing the periodic x' boundary is stored as two runs.
struct SupportRow {
  std::uint32_t first = 0;
  std::uint32_t table = 0;
  std::uint16_t count = 0;
  std::uint16_t width = 0;
  std::uint32_t iz = 0;
  double yz_m = 0.0, yz_d = 0.0, ydy = 0.0, ydz = 0.0;
};

struct SupportPlan {
  std::vector<std::uint32_t> particle;   // particle visited at position k (spatially sorted)
  std::vector<std::size_t> row_begin;    // rows of visit k: [row_begin[k], row_end[k]) (slots up to
  std::vector<std::size_t> row_end;      //   row_begin[k + 1] are reserved, an upper bound)
  std::vector<double> dipole_scale;      // -1 / sD^2 of visit k
  std::vector<std::uint32_t> z_first;    // first z plane (wrapped) of visit k's extent ...
  std::vector<std::uint32_t> z_planes;   // ... and its number of planes (may wrap past n_z)
  std::vector<SupportRow> rows;
  std::vector<double> tables;
  std::vector<std::size_t> plane_nodes;  // support nodes per z plane: the work a spreading thread owns
  double cell_volume = 0.0;

  std::size_t visits() const { return particle.size(); }
  // Whether visit k has nodes in the z planes [z_begin, z_end) of a grid with nz planes.
  bool touches_planes(std::size_t k, std::uint32_t z_begin, std::uint32_t z_end, std::uint32_t nz) const {
    const std::uint32_t a = z_first[k], b = z_first[k] + z_planes[k];  // [a, b), b may exceed nz
    return (a < z_end && b > z_begin) || (b > nz && b - nz > z_begin);
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
